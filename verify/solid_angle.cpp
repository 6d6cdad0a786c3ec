// `disklab solid-angle`: the solid angle of a disk seen from a point, by each formula.
//
//   disklab solid-angle --center X,Y,Z --normal X,Y,Z --radius R --point X,Y,Z [--two-sided]
//       [--method stable|radial|parallel|on-axis|quadrature|all] [--json]
//
// Methods (lib/include/disklab/ellipse/solid_angle.h):
//   stable      production, cancellation-free (R_J closed form); the default
//   radial      Guillén et al. 2017 eq. (19) as printed (cancels far away)
//   parallel    eq. (11) as printed, doubled by eq. (7) (cancels far away)
//   on-axis     2 pi r^2 / (L (d + L)); only for points on the axis (in-plane offset at most
//               1e-8 of the distance, where the closed form is exact to double precision)
//   quadrature  boundary (wedge) quadrature, no ellipse formula (slow; the test reference)
//   all         one line "method value" per method (on-axis only on axis; quadrature left out,
//               with a note on stderr, where it does not converge)
// --json prints every method (null where not applicable or not converged) plus the ellipse's
// a, b, alpha, beta, a_t, b_t, h, e. --method quadrature near the rim, where it cannot converge,
// exits 2 like on-axis off the axis: the chosen method cannot answer, use stable.
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.h"
#include "common/args.h"
#include "common/ellipse_cli.h"
#include "common/output.h"
#include "disklab/ellipse/geometry.h"
#include "disklab/ellipse/solid_angle.h"

namespace disklab::cli {
namespace {

const std::vector<std::string> kMethods = {"stable",  "radial",     "parallel",
                                           "on-axis", "quadrature", "all"};

// In-plane offset (relative to the distance) up to which a point counts as on the axis: the
// closed form's error is O((e/D)^2) = 1e-16 there.
constexpr double kOnAxisOffset = 1e-8;
// Stopping tolerance of the double-precision boundary quadrature (relative change per level), and
// its interval budget: 2^26 (~3 s) suffices everywhere but within ~1e-8 radii of the rim, where
// the integrand has a peak of width ~distance to the rim.
constexpr double kQuadratureTol = 1e-15;
constexpr int kQuadratureMaxLog2 = 26;

struct SolidAngleState {
  std::string center, normal, radius, point;
  bool two_sided = false;
  std::string method = "stable";
  bool json = false;
};

bool on_axis(const ellipse::SphericalEllipse& se) {
  return se.empty || se.e <= kOnAxisOffset * std::hypot(se.h, se.e);
}

// Boundary quadrature in double; nullopt where it does not reach kQuadratureTol within
// 2^kQuadratureMaxLog2 intervals (only points within ~1e-8 radii of the rim).
std::optional<double> quadrature(const ellipse::SphericalEllipse& se) {
  if (se.empty) return 0.0;
  const auto q = ellipse::solid_angle_boundary_quadrature<double>(
      se.h / se.radius, se.e / se.radius, 1.0, kQuadratureTol, kQuadratureMaxLog2);  // scale-free
  if (!q.converged) return std::nullopt;
  return q.value;
}

// The value of one method; nullopt for on-axis off the axis and a quadrature that did not
// converge.
std::optional<double> evaluate(const ellipse::SphericalEllipse& se, const std::string& method) {
  if (method == "stable") return se.omega;
  if (method == "radial") return ellipse::solid_angle_radial_printed(se);
  if (method == "parallel") return ellipse::solid_angle_parallel_printed(se);
  if (method == "on-axis") {
    if (!on_axis(se)) return std::nullopt;
    return se.empty ? 0.0 : ellipse::solid_angle_on_axis(se.h, se.radius);
  }
  if (method == "quadrature") return quadrature(se);
  return std::nullopt;
}

std::string quadrature_failure(const ellipse::SphericalEllipse& se) {
  return "quadrature: no convergence within 2^" + std::to_string(kQuadratureMaxLog2) +
         " intervals (the point is within " +
         fmt17(std::hypot(se.e - se.radius, se.h) / se.radius) + " radii of the rim)";
}

int run_solid_angle(const SolidAngleState& s) {
  const SceneInput in =
      parse_scene(s.center, s.normal, s.radius, s.point, s.two_sided, /*allow_zero_radius=*/true);
  require_one_of(s.method, kMethods, "--method");
  const ellipse::Disk& disk = in.disk;
  const Vec3& o = in.point;
  ellipse::SphericalEllipse se;
  try {
    se = ellipse::make_spherical_ellipse(disk, o);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (s.method == "on-axis" && !on_axis(se))
    throw UsageError("--method on-axis: the point is not on the disk's axis (in-plane offset " +
                     fmt17(se.e) + "); use stable");

  if (s.json) {
    nlohmann::json j;
    j["empty"] = se.empty;
    j["two_sided"] = disk.two_sided;
    for (const std::string m : {"stable", "radial", "parallel", "on-axis", "quadrature"}) {
      const auto v = evaluate(se, m);
      j["omega"][m] = v ? nlohmann::json(*v) : nlohmann::json(nullptr);
      if (m == "quadrature") j["quadrature_converged"] = v.has_value();
    }
    j["omega"]["production"] = se.omega;
    j["a"] = se.a;
    j["b"] = se.b;
    j["alpha"] = se.alpha;
    j["beta"] = se.beta;
    j["a_t"] = se.a_t;
    j["b_t"] = se.b_t;
    j["h"] = se.h;
    j["e"] = se.e;
    std::printf("%s\n", j.dump(2).c_str());
    return 0;
  }
  if (s.method == "all") {
    std::string lines;  // all computed before anything is printed
    bool quadrature_failed = false;
    for (const std::string m : {"stable", "radial", "parallel", "on-axis", "quadrature"}) {
      const auto v = evaluate(se, m);
      if (v) lines += m + " " + fmt17(*v) + "\n";
      if (!v && m == "quadrature") quadrature_failed = true;
    }
    std::fputs(lines.c_str(), stdout);
    if (quadrature_failed)
      std::fprintf(stderr, "disklab: note: %s; left out\n", quadrature_failure(se).c_str());
    return 0;
  }
  const auto v = evaluate(se, s.method);  // on-axis off the axis was refused above
  if (!v) throw UsageError("--method " + quadrature_failure(se) + "; use stable");
  std::printf("%s\n", fmt17(*v).c_str());
  return 0;
}

std::function<int()> setup_solid_angle(Options& sub) {
  auto state = std::make_shared<SolidAngleState>();
  sub.add_option("--center", state->center, "Disk centre X,Y,Z");
  sub.add_option("--normal", state->normal, "Disk normal X,Y,Z (any length; lit side +normal)");
  sub.add_option("--radius", state->radius, "Disk radius (>= 0)");
  sub.add_option("--point", state->point, "Shading point X,Y,Z");
  sub.add_flag("--two-sided", state->two_sided, "The disk emits from both faces");
  sub.add_option("--method", state->method,
                 "stable (default, production), radial (eq. 19 as printed), parallel (eq. 11 as "
                 "printed), on-axis (closed form, on the axis only), quadrature (boundary "
                 "quadrature, no ellipse formula), all");
  sub.add_flag("--json", state->json, "Every method plus a, b, alpha, beta, a_t, b_t, h, e");
  sub.footer(
      "Output: one number (%.17g) in steradians; 0 when the point sees nothing (behind a\n"
      "one-sided disk, in its plane, radius 0). --method all prints 'method value' lines.\n"
      "Examples:\n"
      "  disklab solid-angle --center 0,0,0 --normal 0,0,1 --radius 1 --point 0,0,1\n"
      "  disklab solid-angle --center 0,0,0 --normal 0,0,1 --radius 1 --point 3e7,0,1e8 "
      "--method all\n"
      "  disklab solid-angle --center 1,2,3 --normal 0,1,1 --radius 0.5 --point 0,0,0 "
      "--two-sided --json");
  return [state] { return run_solid_angle(*state); };
}

const Registrar kSolidAngle{Command{"solid-angle",
                                    "Solid angle of a disk seen from a point, by each formula",
                                    setup_solid_angle,
                                    {}}};

}  // namespace
}  // namespace disklab::cli
