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

void add_ellipse_options(Options& sub, EllipseOptions& o) {
  sub.add_option("--map", o.map, "Spherical-ellipse map: " + ellipse_map_list());
  sub.add_option("--center", o.center, "Disk centre X,Y,Z (with --map)");
  sub.add_option("--normal", o.normal,
                 "Disk normal X,Y,Z, any non-zero length; the disk emits towards +normal "
                 "(with --map)");
  sub.add_option("--radius", o.radius, "Disk radius R > 0 (with --map)");
  sub.add_option("--point", o.point, "Shading point X,Y,Z (with --map)");
  sub.add_flag("--two-sided", o.two_sided, "The disk emits from both faces (with --map)");
  sub.add_option("--receiver-normal", o.receiver_normal,
                 "Receiver normal X,Y,Z at the shading point, any non-zero length: the cosine "
                 "that --map projected samples (required with it, refused with other maps)");
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

SceneInput parse_scene(const std::string& center, const std::string& normal,
                       const std::string& radius, const std::string& point, bool two_sided,
                       bool allow_zero_radius) {
  SceneInput in;
  in.disk.center =
      parse_vec3(require_given(center, "--center", "the disk centre X,Y,Z"), "--center");
  in.disk.normal =
      parse_vec3(require_given(normal, "--normal", "the disk normal X,Y,Z"), "--normal");
  in.disk.radius = parse_double(
      require_given(radius, "--radius",
                    allow_zero_radius ? "the disk radius, >= 0" : "the disk radius, > 0"),
      "--radius");
  in.disk.two_sided = two_sided;
  in.point = parse_vec3(require_given(point, "--point", "the shading point X,Y,Z"), "--point");
  if (allow_zero_radius) {
    if (in.disk.radius < 0.0) throw UsageError("--radius: " + radius + " is negative");
  } else {
    require_positive(in.disk.radius, "--radius");
  }
  // Any finite non-zero length: the squared norm of (0, 0, 1e-200) underflows to 0.
  if (!(in.disk.normal.cwiseAbs().maxCoeff() > 0.0))
    throw UsageError("--normal: '" + normal + "' has zero length (the disk has no orientation)");
  return in;
}

ellipse::AnyMap make_ellipse_map(const EllipseOptions& o) {
  require_one_of(o.map, ellipse::map_names(), "--map");
  const SceneInput in = parse_scene(o.center, o.normal, o.radius, o.point, o.two_sided);
  const Vec3& p = in.point;
  const bool projected = o.map == "projected";
  if (projected && o.receiver_normal.empty())
    throw UsageError("--receiver-normal: missing (projected samples the receiver's cosine)");
  if (!projected && !o.receiver_normal.empty())
    throw UsageError("--receiver-normal: only --map projected uses it");
  if (projected) {
    const Vec3 n = parse_vec3(o.receiver_normal, "--receiver-normal");
    if (!(n.cwiseAbs().maxCoeff() > 0.0))
      throw UsageError("--receiver-normal: '" + o.receiver_normal + "' has zero length");
    ellipse::AnyMap m = ellipse::AnyMap::make(o.map, in.disk, p, n);
    if (!m.valid())
      throw UsageError("degenerate geometry: the point " + o.point +
                       " sees no part of the disk above its horizon (receiver normal " +
                       o.receiver_normal + "), or sees no disk at all");
    return m;
  }
  ellipse::AnyMap m = ellipse::AnyMap::make(o.map, in.disk, p);
  if (!m.valid())
    throw UsageError("degenerate geometry: the point " + o.point + " sees no disk (it is " +
                     (o.two_sided ? "" : "behind the one-sided disk, ") +
                     "in its plane, or the disk's solid angle underflows)" +
                     (o.two_sided ? "" : "; the disk emits towards +normal (or give --two-sided)"));
  return m;
}

std::string describe_scene(const EllipseOptions& o) {
  return "c=(" + o.center + ") n=(" + o.normal + ") r=" + o.radius + " o=(" + o.point + ")" +
         (o.two_sided ? " two-sided" : "") +
         (o.receiver_normal.empty() ? "" : " n_o=(" + o.receiver_normal + ")");
}

std::string format_sample(const ellipse::EllipseSample& s) {
  return fmt17(s.direction.x()) + " " + fmt17(s.direction.y()) + " " + fmt17(s.direction.z()) +
         " " + fmt17(s.pdf);
}

}  // namespace disklab::cli
