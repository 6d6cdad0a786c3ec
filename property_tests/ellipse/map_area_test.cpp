// Area preservation of stratum images: for an n x n grid of [0,1]^2, the solid angle of each
// stratum's image equals measure / n^2. The image's solid angle is computed from the mapped
// boundary alone, as a spherical polygon (fan of pole triangles in the ellipse frame, refined
// and Richardson-extrapolated; support/spherical.h), never from the map's Jacobian or pdf.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <sstream>

#include "ellipse/map_common.h"
#include "support/spherical.h"

namespace disklab::test {
namespace {

// ---- tolerances (one place) ----
// The boundary polygon is refined until two Richardson estimates agree to kQuadratureRel of the
// stratum (kinks of the image boundary sit at the stratum corners, which every refinement
// samples, so the chord error expansion is in even powers of 1/k on each smooth piece).
constexpr double kQuadratureRel = 1e-10;
// Largest boundary sampling before giving up (the test then fails on the area check).
constexpr std::size_t kMaxBoundaryPoints = 1 << 14;
// Area agreement: quadrature 1e-10, the maps' Newton tolerance 1e-15 of Omega per boundary point
// (relative to a stratum of Omega/256: 3e-13), rounding of the pole-triangle sum (~k ulps).
// 1e-9 is two orders above the sum of those.
constexpr double kAreaRel = 1e-9;
// The solid angle from the disk's rim as a polygon vs the maps' Omega (eq. 19 integrated):
// quadrature 1e-11 plus rounding.
constexpr double kOmegaRel = 1e-10;

struct AreaCheck {
  double worst_rel = 0.0;
  std::string worst;
};

// Checks every stratum of an n x n grid of `sample`; `measure` is the image's expected total.
AreaCheck check_strata(const std::function<ellipse::EllipseSample(Point2)>& sample, double measure,
                       int n) {
  AreaCheck out;
  for (int iy = 0; iy < n; ++iy) {
    for (int ix = 0; ix < n; ++ix) {
      const double x0 = double(ix) / n, x1 = double(ix + 1) / n, y0 = double(iy) / n,
                   y1 = double(iy + 1) / n;
      auto boundary = [&](double t) { return sample(stratum_boundary(x0, x1, y0, y1, t)).local; };
      const double expected = measure / (n * n);
      const RefinedSolidAngle a =
          refined_solid_angle(boundary, 16, kQuadratureRel, 0.0, kMaxBoundaryPoints);
      // Orientation: strata are traced counter-clockwise in the square; maps may reverse it.
      const double rel = std::abs(std::abs(a.value) - expected) / expected;
      if (rel > out.worst_rel || !std::isfinite(rel)) {
        std::ostringstream s;
        s.precision(17);
        s << "stratum (" << ix << "," << iy << ") of " << n << "x" << n << ": polygon " << a.value
          << " (+-" << a.error << ", " << a.points << " pts) vs measure/n^2 " << expected << " rel "
          << rel;
        out.worst = s.str();
        out.worst_rel = std::isfinite(rel) ? rel : 1e300;
      }
    }
  }
  return out;
}

class MapAreaPreservation : public ::testing::TestWithParam<std::string> {};

TEST_P(MapAreaPreservation, StratumImagesHaveEqualSolidAngle) {
  for (const DiskConfig& c : map_configs()) {
    const AnyMap m = make_map(GetParam(), c);
    // n = 16 (256 strata) on the three configurations that stress the maps most (tilted,
    // grazing, 1e8 radii), n = 4 elsewhere: the CI budget (~1 s per map).
    const bool fine = c.name == "grazing" || c.name == "far-1e8" || c.name == "tilted-mid";
    const int n = fine ? 16 : 4;
    const auto t0 = std::chrono::steady_clock::now();
    const AreaCheck r = check_strata([&](Point2 u) { return m.sample(u, nullptr); }, m.measure, n);
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LE(r.worst_rel, kAreaRel) << m.name << " on " << c.describe() << "\n  worst " << r.worst;
    std::cout << "[area] " << m.name << " " << c.name << " n=" << n << " worst rel " << r.worst_rel
              << " (" << secs << " s)\n";
  }
}

INSTANTIATE_TEST_SUITE_P(All, MapAreaPreservation, ::testing::ValuesIn(bijective_map_names()),
                         [](const auto& info) {
                           std::string s = info.param;
                           for (char& ch : s)
                             if (ch == '-') ch = '_';
                           return s;
                         });

// The same check must reject a map that is not area-preserving: the radial map with eps2
// squared (a density that grows towards the rim).
TEST(MapAreaPreservationControl, DetectsNonUniformVariant) {
  const DiskConfig c = map_configs()[3];
  const auto radial = ellipse::RadialMap::make(c.disk(), c.point);
  const AreaCheck r = check_strata(
      [&](Point2 u) {
        return radial.sample({u.x, u.y * u.y});
      },
      radial.g.omega, 4);
  EXPECT_GT(r.worst_rel, 100 * kAreaRel) << r.worst;
}

// Omega of the maps vs the disk's rim traced as a spherical polygon (independent of eq. 19).
TEST(MapSolidAngle, OmegaMatchesRimPolygon) {
  for (const DiskConfig& c : map_configs()) {
    const auto g = ellipse::MapGeometry::make(c.disk(), c.point);
    const Vec3 e1 = g.frame.x, e2 = g.normal.cross(e1);
    const Vec3 cl = g.to_local(c.center - c.point);
    auto rim = [&](double t) {
      const double th = math::kTwoPi * t;
      const Vec3 off = c.radius * (std::cos(th) * e1 + std::sin(th) * e2);
      return Vec3(cl + g.to_local(off)).normalized();
    };
    const RefinedSolidAngle a = refined_solid_angle(rim, 64, 1e-13, 0.0, 1 << 20);
    EXPECT_NEAR(std::abs(a.value) / g.omega, 1.0, kOmegaRel)
        << c.describe() << " polygon " << a.value << " omega " << g.omega;
  }
}

}  // namespace
}  // namespace disklab::test
