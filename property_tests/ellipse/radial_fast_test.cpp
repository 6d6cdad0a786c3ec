// radial-fast's two modes (radial_fast.h): where its sine series of the inverse map is accurate
// to kDirectTol (checked at set-up at the transform's midpoints), samples take it directly with
// no evaluation of Omega_r; elsewhere Newton starts from it. Both must give the exact radial
// map's samples: this measures the series between the checks on a dense grid, and the samples'
// eps1 through the exact map's inverse, over random scenes from 1e-3 to 1e8 radii.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/radial_fast.h"
#include "ellipse/geometry_scenes.h"

namespace disklab::test {
namespace {

using ellipse::RadialFastMap;

// The checks sample the interpolation error where it peaks (the transform's midpoints), so
// between them the residual exceeds the checked bound only by rounding and by the error's
// shape; 2x kDirectTol leaves room for both (measured: at most ~1.05x).
constexpr double kBetweenChecks = 2.0 * RadialFastMap::kDirectTol;
// The maps' promise for eps1 (radial.h: kRadialNewtonTol keeps it to 2.5e-16): every sample's
// eps1, recovered by the exact map's inverse (itself exact to a few ulps of t), within 1e-14.
constexpr double kEps1Tol = 1e-14;
// From this far away (radii) the inverse's series always fits beside Omega_r's: only disks seen
// from near their rim plane need more terms than a sampler keeps.
constexpr double kAlwaysDirectBeyond = 10.0;
constexpr int kDenseGrid = 4096;
constexpr int kScenes = 400;

ellipse::Disk facing(const Scene& sc) {
  Vec3 normal = sc.disk.normal;
  if ((sc.point - sc.disk.center).dot(normal) < 0.0) normal = -normal;
  return ellipse::Disk{sc.disk.center, normal, sc.disk.radius, false};
}

TEST(RadialFast, DirectModeMeetsItsTolerance) {
  int scenes = 0, direct = 0;
  double worst = 0.0;
  for (uint64_t seed = 0; seed < kScenes; ++seed) {
    const Scene sc = random_scene(seed, -3.0, 8.0);
    const auto m = RadialFastMap::make(facing(sc), sc.point);
    if (!m.valid()) continue;
    ++scenes;
    if (!m.is_direct()) {
      EXPECT_LT(sc.distance, kAlwaysDirectBeyond) << "Newton mode for " << sc.describe();
      continue;
    }
    ++direct;
    const ellipse::RadialQuadrant q = m.radial.quadrant();
    const double quadrant = q.quadrant_solid_angle();
    for (int i = 0; i <= kDenseGrid; ++i) {
      const double t = static_cast<double>(i) / kDenseGrid;
      const ellipse::ParametricAngle s = m.radial.series.seed(t);
      ASSERT_GE(s.s, 0.0);
      ASSERT_LE(s.s, math::kHalfPi);
      const double r = std::abs(q.sector_s(s.s) - t * quadrant) / quadrant;
      worst = std::max(worst, r);
      ASSERT_LE(r, kBetweenChecks) << sc.describe() << " t=" << t << " terms " << m.seed_terms()
                                   << " + " << m.radial.series.n;
    }
  }
  std::printf(
      "  %d scenes, %d direct; worst residual between checks %.3g of the quadrant "
      "(checks: %.3g)\n",
      scenes, direct, worst, RadialFastMap::kDirectTol);
  // Direct mode is the common case, not a corner: most random scenes take it.
  EXPECT_GT(direct, scenes * 3 / 4);
}

// Both modes sample the exact radial map: eps1 of every sample's local direction, by the exact
// map's inverse, is u.x, on a grid that includes the seams and the corners.
TEST(RadialFast, SamplesAreTheExactMapsInBothModes) {
  int modes[2] = {0, 0};
  double worst = 0.0;
  for (uint64_t seed = 0; seed < kScenes; ++seed) {
    const Scene sc = random_scene(seed, -3.0, 8.0);
    const auto fast = RadialFastMap::make(facing(sc), sc.point);
    const auto exact = ellipse::RadialMap::make(facing(sc), sc.point);
    ASSERT_EQ(fast.valid(), exact.valid()) << sc.describe();
    if (!fast.valid()) continue;
    ++modes[fast.is_direct() ? 1 : 0];
    for (int i = 0; i <= 64; ++i) {
      const Point2 u{i / 64.0, (i % 7 + 0.5) / 7.0};
      int evaluations = -1;
      const auto s = fast.sample(u, &evaluations);
      ASSERT_TRUE(s.valid) << sc.describe();
      if (fast.is_direct()) {
        EXPECT_EQ(evaluations, 0) << sc.describe();
      }
      // In the ellipse's frame (a world direction's rounding alone moves eps1 by ~1e-16 / alpha
      // for distant disks). eps1 is periodic: the seam at 1 is the seam at 0.
      double d = std::abs(exact.invert_local(s.local).x - u.x);
      d = std::min(d, 1.0 - d);
      worst = std::max(worst, d);
      ASSERT_LE(d, kEps1Tol) << sc.describe() << " u.x=" << u.x
                             << (fast.is_direct() ? " direct" : " Newton");
    }
  }
  std::printf("  Newton mode %d scenes, direct %d; worst eps1 error %.3g\n", modes[0], modes[1],
              worst);
  EXPECT_GT(modes[0], 0);  // both modes were exercised
  EXPECT_GT(modes[1], 0);
}

}  // namespace
}  // namespace disklab::test
