// `disklab map`: one sample through one map, forward or inverse (a contract scripts rely on).
//
// Planar strategies (Christensen 2018, Sec. 3):
//   disklab map --strategy NAME --uv U,V           -> "x y" per disk point (%.17g)
//   disklab map --strategy NAME --inverse --xy X,Y -> "u v"
// Per strategy:
//   polar, concentric          one line "x y"; inverse of any point of the closed unit disk.
//   polar4, concentric4        four lines, copies k = 0..3 rotated by k * 90 degrees (memo
//                              Appendix A); the inverse prints the square point whose copy k is
//                              the given point (k is the point's quadrant, counter-clockwise
//                              from +x, half-open: k = 0 holds x > 0, y >= 0).
//   pad-zero                   one line "x y weight": the point of [-1,1]^2 and its estimator
//                              weight, 4/pi inside the disk, 0 outside (the padding). The
//                              inverse accepts any point of [-1,1]^2.
//   rejection                  one line "x y" when the point lands in the disk, else the single
//                              word "rejected" (exit 0: a rejection is a valid outcome; a
//                              sequence would move on to its next point). Inverse: disk points.
//
// Spherical-ellipse maps (Guillén et al. 2017; ellipse/any_map.h):
//   disklab map --map NAME --center X,Y,Z --normal X,Y,Z --radius R --point X,Y,Z --uv U,V
//     -> "x y z pdf": the unit direction from the point and its solid-angle pdf (%.17g);
//        radial4 prints four lines (the reflections into quadrants 0..3, counter-clockwise);
//        gamito and tabulated try one candidate: "rejected" when it misses (exit 0), else the
//        direction with the PROPOSAL pdf (what an unbiased zero-on-rejection estimator divides by).
//   ... --inverse --dir X,Y,Z -> "u v" (direction of any length; exit 2 when it misses the disk
//        or the map has no inverse: gamito).
//
// Structure: options live in MapState; run_map() picks the mode from the options given and
// calls one function per mode.
#include <array>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.h"
#include "common/args.h"
#include "common/ellipse_cli.h"
#include "common/output.h"
#include "disklab/disk/strategy.h"

namespace disklab::cli {
namespace {

struct MapState {
  // planar strategies
  std::string strategy;
  std::string uv;  // "U,V" (forward)
  std::string xy;  // "X,Y" (inverse)
  bool inverse = false;
  // spherical-ellipse maps
  EllipseOptions ellipse;
  std::string dir;  // "X,Y,Z" (inverse)
};

void print_point(Point2 p) {
  std::printf("%s %s\n", fmt17(p.x).c_str(), fmt17(p.y).c_str());
}

disk::Strategy require_strategy(const std::string& name) {
  require_one_of(name, disk::strategy_names(), "--strategy");
  return *disk::parse_strategy(name);
}

int run_planar_forward(const MapState& s) {
  const disk::Strategy strategy = require_strategy(s.strategy);
  if (!s.xy.empty()) throw UsageError("--xy is the input of --inverse; the forward map takes --uv");
  if (s.uv.empty()) throw UsageError("--uv: missing (the square point U,V to map)");
  const Point2 uv = parse_point2(s.uv, "--uv");
  require_range(uv.x, 0.0, 1.0, "--uv (u)");
  require_range(uv.y, 0.0, 1.0, "--uv (v)");
  switch (strategy) {
    case disk::Strategy::polar:
      print_point(disk::sample_polar(uv));
      break;
    case disk::Strategy::concentric:
      print_point(disk::sample_concentric(uv));
      break;
    case disk::Strategy::polar4:
      for (Point2 p : disk::sample_polar4(uv))
        print_point(p);
      break;
    case disk::Strategy::concentric4:
      for (Point2 p : disk::sample_concentric4(uv))
        print_point(p);
      break;
    case disk::Strategy::pad_zero: {
      const disk::PadZeroSample p = disk::sample_pad_zero(uv);
      std::printf("%s %s %s\n", fmt17(p.point.x).c_str(), fmt17(p.point.y).c_str(),
                  fmt17(p.weight).c_str());
      break;
    }
    case disk::Strategy::rejection: {
      const disk::RejectionTry r = disk::try_rejection(uv);
      if (r.accepted)
        print_point(r.point);
      else
        std::printf("rejected\n");
      break;
    }
  }
  return 0;
}

int run_planar_inverse(const MapState& s) {
  const disk::Strategy strategy = require_strategy(s.strategy);
  if (!s.uv.empty()) throw UsageError("--uv is the input of the forward map; --inverse takes --xy");
  if (s.xy.empty()) throw UsageError("--xy: missing (the disk point X,Y to invert)");
  const Point2 p = parse_point2(s.xy, "--xy");
  const bool in_square = p.x >= -1.0 && p.x <= 1.0 && p.y >= -1.0 && p.y <= 1.0;
  if (strategy == disk::Strategy::pad_zero) {
    if (!in_square)
      throw UsageError("--xy: (" + fmt17(p.x) + ", " + fmt17(p.y) +
                       ") is outside pad-zero's square [-1,1]^2");
  } else if (!disk::inside_unit_disk(p)) {
    throw UsageError("--xy: (" + fmt17(p.x) + ", " + fmt17(p.y) + ") is outside the unit disk");
  }
  Point2 uv;
  switch (strategy) {
    case disk::Strategy::polar:
      uv = disk::invert_polar(p);
      break;
    case disk::Strategy::concentric:
      uv = disk::invert_concentric(p);
      break;
    case disk::Strategy::polar4:
      uv = disk::invert_polar4(p).uv;
      break;
    case disk::Strategy::concentric4:
      uv = disk::invert_concentric4(p).uv;
      break;
    case disk::Strategy::pad_zero:
    case disk::Strategy::rejection:
      uv = disk::centered_to_square(p);
      break;
  }
  print_point(uv);
  return 0;
}

bool is_rejection_sampler(ellipse::MapKind k) {
  return k == ellipse::MapKind::gamito || k == ellipse::MapKind::tabulated;
}

int run_ellipse_forward(const MapState& s) {
  if (!s.dir.empty())
    throw UsageError("--dir is the input of --inverse; the forward map takes --uv");
  if (!s.xy.empty()) throw UsageError("--xy belongs to --strategy; --map takes --uv or --dir");
  if (s.uv.empty()) throw UsageError("--uv: missing (the square point U,V to map)");
  const Point2 uv = parse_point2(s.uv, "--uv");
  require_range(uv.x, 0.0, 1.0, "--uv (u)");
  require_range(uv.y, 0.0, 1.0, "--uv (v)");
  const ellipse::AnyMap m = make_ellipse_map(s.ellipse);
  std::array<ellipse::EllipseSample, 4> out;
  const int n = m.sample_copies(uv, out);
  std::string text;
  for (int k = 0; k < n; ++k) {
    if (out[k].valid) {
      text += format_sample(out[k]) + "\n";
    } else if (is_rejection_sampler(m.kind())) {
      text += "rejected\n";
    } else {
      throw std::runtime_error("map " + std::string(m.name()) + " returned no sample for u = (" +
                               fmt17(uv.x) + ", " + fmt17(uv.y) + ") on a valid geometry");
    }
  }
  std::fputs(text.c_str(), stdout);
  return 0;
}

int run_ellipse_inverse(const MapState& s) {
  if (!s.uv.empty())
    throw UsageError("--uv is the input of the forward map; --inverse takes --dir");
  if (!s.xy.empty()) throw UsageError("--xy belongs to --strategy; --map --inverse takes --dir");
  if (s.dir.empty()) throw UsageError("--dir: missing (the direction X,Y,Z to invert)");
  const Vec3 d = parse_vec3(s.dir, "--dir");
  if (!(d.cwiseAbs().maxCoeff() > 0.0)) throw UsageError("--dir: '" + s.dir + "' has zero length");
  const ellipse::AnyMap m = make_ellipse_map(s.ellipse);
  if (!m.has_inverse())
    throw UsageError("--inverse: map " + std::string(m.name()) +
                     " has no inverse (a rejection sampler over a spherical rectangle)");
  // The CLI prints radial4's four copies forward, so its inverse is the copies' (invert_copy).
  const std::optional<Point2> u = m.invert_copy(d);
  if (!u)
    throw UsageError("--dir: (" + s.dir + ") misses the disk (outside the spherical ellipse)");
  print_point(*u);
  return 0;
}

int run_map(const MapState& s) {
  check_ellipse_exclusive(s.ellipse, s.strategy);
  if (!s.ellipse.map.empty()) return s.inverse ? run_ellipse_inverse(s) : run_ellipse_forward(s);
  if (!s.dir.empty()) throw UsageError("--dir belongs to --map --inverse");
  if (!s.strategy.empty()) return s.inverse ? run_planar_inverse(s) : run_planar_forward(s);
  std::string valid;
  for (const auto& n : disk::strategy_names())
    valid += " " + n;
  throw UsageError("--strategy or --map: missing (strategies:" + valid +
                   "; maps: " + ellipse_map_list() + ")");
}

std::function<int()> setup_map(Options& sub) {
  auto state = std::make_shared<MapState>();
  std::string names;
  for (const auto& n : disk::strategy_names()) {
    if (!names.empty()) names += ", ";
    names += n;
  }
  sub.add_option("--strategy", state->strategy, "Square-to-disk strategy: " + names);
  sub.add_option("--uv", state->uv, "Square point U,V in [0,1]^2 (forward)");
  sub.add_option("--xy", state->xy, "Disk point X,Y (with --inverse)");
  sub.add_flag("--inverse", state->inverse,
               "Map a disk point (--xy) or a direction (--dir) back to the square");
  add_ellipse_options(sub, state->ellipse);
  sub.add_option("--dir", state->dir,
                 "Direction X,Y,Z from the point, any length (--map --inverse)");
  sub.footer(
      "Output: one line per point, numbers with %.17g (they read back exactly).\n"
      "  polar, concentric: 'x y'; polar4, concentric4: four lines, copies rotated by 0, 90,\n"
      "  180, 270 degrees; pad-zero: 'x y weight' (weight 4/pi inside the disk, 0 outside);\n"
      "  rejection: 'x y', or 'rejected' when the point falls outside the disk.\n"
      "  --inverse prints 'u v' (polar4/concentric4: the square point of which the given point\n"
      "  is copy k, k = its quadrant counter-clockwise from +x; pad-zero: any point of\n"
      "  [-1,1]^2).\n"
      "Spherical-ellipse maps (--map, exclusive with --strategy) print 'x y z pdf': the unit\n"
      "  direction from --point and its pdf in solid angle (1/Omega for the uniform maps).\n"
      "  radial4: four lines, the reflections into quadrants 0..3 counter-clockwise.\n"
      "  gamito, tabulated: one candidate; 'rejected' (exit 0) when it misses the disk, else\n"
      "  the PROPOSAL pdf (an unbiased estimator counts rejections as zero).\n"
      "  --inverse --dir X,Y,Z prints 'u v' (radial4: the u of which the direction is copy k,\n"
      "  k = its quadrant); exit 2 if the direction misses the disk or the map is gamito\n"
      "  (no inverse). tabulated jumps at its table's cell edges (eps1 = j/1024): there the\n"
      "  inverse returns the side rounding falls on. A point behind the one-sided disk or in\n"
      "  its plane is an error (exit 2).\n"
      "Examples:\n"
      "  disklab map --strategy polar --uv 0.25,0.5\n"
      "  disklab map --strategy polar4 --uv 0.25,0.5\n"
      "  disklab map --strategy concentric --inverse --xy 0.3,-0.4\n"
      "  disklab map --strategy pad-zero --uv 0.05,0.95\n"
      "  disklab map --map radial --center 0,0,1 --normal 0,0,-1 --radius 1 --point 0,0,0 "
      "--uv 0.3,0.7\n"
      "  disklab map --map radial --center 0,0,1 --normal 0,0,-1 --radius 1 --point 0,0,0 "
      "--inverse --dir 0.1,0.2,1");
  return [state] { return run_map(*state); };
}

const Registrar kMap{Command{
    "map",
    "Map one sample through a disk strategy or a spherical-ellipse map (forward or inverse)",
    setup_map,
    {}}};

}  // namespace
}  // namespace disklab::cli
