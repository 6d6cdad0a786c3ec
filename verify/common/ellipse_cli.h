#pragma once
// The spherical-ellipse options shared by `disklab map` and `disklab points` (--map, --center,
// --normal, --radius, --point, --two-sided): binding, validation and the output line of one
// sample.
#include <string>

#include <CLI/CLI.hpp>

#include "disklab/ellipse/any_map.h"

namespace disklab::cli {

struct EllipseOptions {
  std::string map;  // empty: not an ellipse run
  std::string center, normal, radius, point;
  bool two_sided = false;

  // Whether any disk/point option was given (they are an error without --map).
  bool any_scene_option() const {
    return !center.empty() || !normal.empty() || !radius.empty() || !point.empty() || two_sided;
  }
};

// "area, gamito, ..." (for --help and messages).
std::string ellipse_map_list();

// Adds --map, --center, --normal, --radius, --point, --two-sided bound to `o`.
void add_ellipse_options(CLI::App& sub, EllipseOptions& o);

// Checks that --map and --strategy are not both given, and that scene options come with --map.
void check_ellipse_exclusive(const EllipseOptions& o, const std::string& strategy);

// Validates the options (known name; every scene option present and finite; radius > 0; normal
// non-zero; the point sees the disk) and builds the map. Throws UsageError with one line.
ellipse::AnyMap make_ellipse_map(const EllipseOptions& o);

// One-line description of the scene for titles: "c=(...) n=(...) r=... o=(...)".
std::string describe_scene(const EllipseOptions& o);

// "x y z pdf" (%.17g) for a valid sample.
std::string format_sample(const ellipse::EllipseSample& s);

}  // namespace disklab::cli
