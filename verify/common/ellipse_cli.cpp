#include "common/ellipse_cli.h"

#include "command.h"
#include "common/args.h"
#include "common/output.h"

namespace disklab::cli {

std::string ellipse_map_list() {
  std::string s;
  for (const auto& n : ellipse::map_names())
    s += (s.empty() ? "" : ", ") + n;
  return s;
}

void add_ellipse_options(CLI::App& sub, EllipseOptions& o) {
  sub.add_option("--map", o.map, "Spherical-ellipse map: " + ellipse_map_list());
  sub.add_option("--center", o.center, "Disk centre X,Y,Z (with --map)");
  sub.add_option("--normal", o.normal,
                 "Disk normal X,Y,Z, any non-zero length; the disk emits towards +normal "
                 "(with --map)");
  sub.add_option("--radius", o.radius, "Disk radius R > 0 (with --map)");
  sub.add_option("--point", o.point, "Shading point X,Y,Z (with --map)");
  sub.add_flag("--two-sided", o.two_sided, "The disk emits from both faces (with --map)");
}

void check_ellipse_exclusive(const EllipseOptions& o, const std::string& strategy) {
  if (!o.map.empty() && !strategy.empty())
    throw UsageError(
        "--strategy and --map are mutually exclusive (--strategy: square-to-disk maps; --map: "
        "spherical-ellipse maps)");
  if (o.map.empty() && o.any_scene_option())
    throw UsageError(
        "--center, --normal, --radius, --point and --two-sided describe the scene of --map; "
        "give --map NAME (" +
        ellipse_map_list() + ")");
}

namespace {
const std::string& require_given(const std::string& value, const char* what, const char* hint) {
  if (value.empty()) throw UsageError(std::string(what) + ": missing (" + hint + ")");
  return value;
}
}  // namespace

ellipse::AnyMap make_ellipse_map(const EllipseOptions& o) {
  require_one_of(o.map, ellipse::map_names(), "--map");
  const Vec3 c =
      parse_vec3(require_given(o.center, "--center", "the disk centre X,Y,Z"), "--center");
  const Vec3 n =
      parse_vec3(require_given(o.normal, "--normal", "the disk normal X,Y,Z"), "--normal");
  const double r =
      parse_double(require_given(o.radius, "--radius", "the disk radius, > 0"), "--radius");
  const Vec3 p =
      parse_vec3(require_given(o.point, "--point", "the shading point X,Y,Z"), "--point");
  require_positive(r, "--radius");
  if (!(n.squaredNorm() > 0.0))
    throw UsageError("--normal: '" + o.normal + "' has zero length (the disk has no orientation)");
  ellipse::AnyMap m = ellipse::AnyMap::make(o.map, ellipse::Disk{c, n, r, o.two_sided}, p);
  if (!m.valid())
    throw UsageError("degenerate geometry: the point " + o.point + " sees no disk (it is " +
                     (o.two_sided ? "" : "behind the one-sided disk, ") +
                     "in its plane, or the disk's solid angle underflows)" +
                     (o.two_sided ? "" : "; the disk emits towards +normal (or give --two-sided)"));
  return m;
}

std::string describe_scene(const EllipseOptions& o) {
  return "c=(" + o.center + ") n=(" + o.normal + ") r=" + o.radius + " o=(" + o.point + ")" +
         (o.two_sided ? " two-sided" : "");
}

std::string format_sample(const ellipse::EllipseSample& s) {
  return fmt17(s.direction.x()) + " " + fmt17(s.direction.y()) + " " + fmt17(s.direction.z()) +
         " " + fmt17(s.pdf);
}

}  // namespace disklab::cli
