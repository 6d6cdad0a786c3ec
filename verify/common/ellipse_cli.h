#pragma once
// The spherical-ellipse options shared by `disklab map` and `disklab points` (--map, --center,
// --normal, --radius, --point, --two-sided): binding, validation and the output line of one
// sample.
#include <string>

#include "common/options.h"

#include "disklab/ellipse/any_map.h"

namespace disklab::cli {

struct EllipseOptions {
  std::string map;  // empty: not an ellipse run
  std::string center, normal, radius, point;
  std::string receiver_normal;  // projected only
  bool two_sided = false;

  // Whether any disk/point option was given (they are an error without --map).
  bool any_scene_option() const {
    return !center.empty() || !normal.empty() || !radius.empty() || !point.empty() ||
           !receiver_normal.empty() || two_sided;
  }
};

// "area, gamito, ..." (for --help and messages).
std::string ellipse_map_list();

// Adds --map, --center, --normal, --radius, --point, --two-sided, --receiver-normal bound to `o`.
void add_ellipse_options(Options& sub, EllipseOptions& o);

// Checks that --map and --strategy are not both given, and that scene options come with --map.
void check_ellipse_exclusive(const EllipseOptions& o, const std::string& strategy);

// A disk light and a shading point from the text of --center, --normal, --radius, --point and
// --two-sided: every value present and finite, the normal non-zero, the radius > 0 (or >= 0
// with allow_zero_radius). Throws UsageError with one line. Shared by the commands that take a
// scene (map, points, solid-angle).
struct SceneInput {
  ellipse::Disk disk;
  Vec3 point = Vec3::Zero();
};
SceneInput parse_scene(const std::string& center, const std::string& normal,
                       const std::string& radius, const std::string& point, bool two_sided,
                       bool allow_zero_radius = false);

// Validates the options (known name; the scene as parse_scene; the point sees the disk;
// --receiver-normal non-zero, given for projected and only for it) and builds the map. Throws
// UsageError with one line.
ellipse::AnyMap make_ellipse_map(const EllipseOptions& o);

// One-line description of the scene for titles: "c=(...) n=(...) r=... o=(...)".
std::string describe_scene(const EllipseOptions& o);

// "x y z pdf" (%.17g) for a valid sample.
std::string format_sample(const ellipse::EllipseSample& s);

}  // namespace disklab::cli
