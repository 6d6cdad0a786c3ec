// The per-shading-point sine series of Omega_r (RadialSeries, radial.h) that the radial maps
// solve with, against the elliptic-integral / Gauss form of solid_angle.h it replaces. The map
// suites only see the series through round trips and statistics; this compares the function
// itself, at every distance the maps are tested on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "disklab/ellipse/map_geometry.h"
#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/solid_angle.h"
#include "ellipse/geometry_scenes.h"
#include "ellipse/map_common.h"

namespace disklab::test {
namespace {

// Both sides are ~1e-16 relative to the quadrant (solid_angle.h is tested against 50-digit
// quadrature; the series drops terms below 1e-17 of it, and Clenshaw's recurrence over at most
// 64 terms adds a few roundings of the quadrant's size): 4e-15 of the quadrant is ~20 ulps.
constexpr double kSeriesTol = 4e-15;
// Lights this far away (in radii) have coefficients decaying fast enough for the series: the
// fallback to solid_angle.h is only for near disks with very eccentric ellipses.
constexpr double kAlwaysSeriesBeyond = 10.0;
constexpr int kGrid = 256;

struct Worst {
  double err = 0.0;
  int fallbacks = 0, scenes = 0;
};

void compare(const Vec3& c, const Vec3& n, double r, const Vec3& o, double distance,
             const std::string& label, Worst& w) {
  const auto g = ellipse::MapGeometry::make(ellipse::Disk{c, n, r, false}, o);
  if (g.empty) return;
  ++w.scenes;
  const auto series = ellipse::RadialSeries::make(g);
  if (series.n == 0) {
    ++w.fallbacks;
    EXPECT_LT(distance, kAlwaysSeriesBeyond) << "series unavailable for " << label;
    return;
  }
  EXPECT_NEAR(series.quadrant, g.quadrant, kSeriesTol * g.quadrant) << label;
  // The radial maps take their total from the series (omega = 4 quadrant, radial.h): it must be
  // the R_J closed form's Omega (solid_angle_stable) to the same accuracy.
  const auto map = ellipse::RadialMap::make(ellipse::Disk{c, n, r, false}, o);
  ASSERT_TRUE(map.valid()) << label;
  EXPECT_NEAR(map.g.omega, g.omega, kSeriesTol * g.omega) << label;
  EXPECT_EQ(map.g.quadrant, series.quadrant) << label;
  for (int i = 0; i <= kGrid; ++i) {
    const double s = math::kHalfPi * i / kGrid;
    const double value = series.omega(s, std::cos(s), std::sin(s));
    // The series' s is the parametric angle of the orthographic ellipse (a cos s, b sin s)
    // (radial.h); solid_angle.h takes the azimuth phi (and works in the tangent ellipse's own
    // parametric angle): compare at the same azimuth, tan phi = (b/a) tan s.
    const double phi = std::atan2(g.b * std::sin(s), g.a * std::cos(s));
    const double ref = ellipse::radial_sector(g, phi);
    const double err = std::fabs(value - ref) / g.quadrant;
    w.err = std::max(w.err, err);
    ASSERT_LE(err, kSeriesTol) << label << " s=" << s << " phi=" << phi << " series " << value
                               << " solid_angle.h " << ref << " (degree " << series.n << ")";
  }
}

TEST(RadialSeries, MatchesSolidAngleOnTheMapConfigurations) {
  Worst w;
  for (const auto& cfg : map_configs())
    compare(cfg.center, cfg.normal, cfg.radius, cfg.point,
            (cfg.point - cfg.center).norm() / cfg.radius, cfg.describe(), w);
  std::printf("  map configurations: %d scenes, %d fallbacks, worst %.3g of the quadrant\n",
              w.scenes, w.fallbacks, w.err);
}

TEST(RadialSeries, MatchesSolidAngleOnRandomScenesFromNearToFar) {
  Worst w;
  for (uint64_t seed = 0; seed < 400; ++seed) {
    const Scene s = random_scene(seed, -3.0, 8.0);
    ellipse::Disk d = s.disk;
    Vec3 normal = d.normal;
    // The maps see one-sided disks: face the point.
    if ((s.point - d.center).dot(normal) < 0.0) normal = -normal;
    compare(d.center, normal, d.radius, s.point, s.distance, s.describe(), w);
    if (HasFatalFailure()) return;
  }
  std::printf("  random scenes: %d, %d fallbacks, worst %.3g of the quadrant\n", w.scenes,
              w.fallbacks, w.err);
}

// The reverted start (RadialSeries::reverted_start) against the converged root: second order
// in the harmonics, so its error is third order, below kReversionBound (|beta_1|^3 + |beta_1
// beta_2| + |beta_3|) with beta_k = b_k / a_0 (the single-harmonic inversion's third-order
// coefficients are 1/2 and 3/2, the cross terms' at most 3: 4 covers them), plus the root's own
// tolerance; and never further from the root than the planar start tau.
constexpr double kReversionBound = 4.0;

TEST(RadialSeries, RevertedStartIsThirdOrderClose) {
  int scenes = 0;
  double worst_ratio = 0.0;
  for (uint64_t seed = 0; seed < 400; ++seed) {
    const Scene sc = random_scene(seed, -3.0, 8.0);
    Vec3 normal = sc.disk.normal;
    if ((sc.point - sc.disk.center).dot(normal) < 0.0) normal = -normal;
    const auto g = ellipse::MapGeometry::make(
        ellipse::Disk{sc.disk.center, normal, sc.disk.radius, false}, sc.point);
    if (g.empty) continue;
    const auto series = ellipse::RadialSeries::make(g);
    if (series.n == 0) continue;
    ++scenes;
    auto beta = [&](int k) { return k <= series.n ? series.b[k - 1] / series.a0 : 0.0; };
    const double b1 = std::abs(beta(1)), b2 = std::abs(beta(2)), b3 = std::abs(beta(3));
    const double bound = kReversionBound * (b1 * b1 * b1 + b1 * b2 + b3) + 1e-14;
    const ellipse::RadialQuadrant q{&g, &series};
    for (int i = 1; i < kGrid; ++i) {
      const double t = static_cast<double>(i) / kGrid, tau = t * math::kHalfPi;
      const double root = q.solve(t).s;
      const double start = series.reverted_start({tau, std::cos(tau), std::sin(tau)}).s;
      const double err = std::abs(start - root);
      ASSERT_LE(err, bound) << sc.describe() << " t=" << t << " beta1=" << beta(1);
      ASSERT_LE(err, std::abs(tau - root) + 1e-14) << sc.describe() << " t=" << t;
      worst_ratio = std::max(worst_ratio, (err - 1e-14) / (bound - 1e-14));
    }
  }
  std::printf("  %d scenes with a series: worst start error %.3g of its bound\n", scenes,
              worst_ratio);
}

}  // namespace
}  // namespace disklab::test
