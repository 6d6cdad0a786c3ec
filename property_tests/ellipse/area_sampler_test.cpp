// Area sampling's directions in the ellipse frame must be accurate relative to the ellipse's
// size at every distance: the exact maps' inverses and the bijectivity suite take them as the
// ground truth. The disk's rim must land on the tangent ellipse (x/a_t)^2 + (y/b_t)^2 = 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "disklab/ellipse/area.h"

namespace disklab::test {
namespace {

// The rim point is c + r (cos t e1 + sin t e2) in R_e: the offset is formed to a few ulps of r
// and the centre by the closed form of geometry.h, so x/z and y/z carry a few ulps relative to
// a_t, b_t; the residual of the squared sum is a few of those. 1e-13 is ~450 ulps: far above
// rounding, far below the 1e-8 that projecting c - o onto the frame (eps |c - o| / r) gave at
// 1e8 radii.
constexpr double kRimResidual = 1e-13;

TEST(AreaSampler, RimLiesOnTheEllipseAtEveryDistance) {
  const Vec3 normal = Vec3(0.3, -0.2, -1.0).normalized();
  for (const double d : {1.0, 1e2, 1e4, 1e6, 1e8}) {
    const Vec3 center(0.3 * d, 0.2 * d, d);
    const auto area =
        ellipse::AreaSampler::make(ellipse::Disk{center, normal, 1.0, false}, Vec3::Zero());
    ASSERT_TRUE(area.valid()) << d;
    double worst = 0.0;
    for (int i = 0; i < 4096; ++i) {
      // Walk the square's boundary: the concentric map sends it onto the disk's rim.
      const double t = (i + 0.5) / 4096;
      const Point2 u = t < 0.25   ? Point2{4 * t, 0}
                       : t < 0.5  ? Point2{1, 4 * t - 1}
                       : t < 0.75 ? Point2{3 - 4 * t, 1}
                                  : Point2{0, 4 - 4 * t};
      const auto w = area.sample(u);
      ASSERT_TRUE(w.valid);
      const double x = w.local.x() / w.local.z() / area.g.a_t;
      const double y = w.local.y() / w.local.z() / area.g.b_t;
      worst = std::max(worst, std::abs(x * x + y * y - 1.0));
    }
    std::printf("  distance %g radii: worst rim residual %.3g\n", d, worst);
    EXPECT_LE(worst, kRimResidual) << "distance " << d << " radii";
  }
}

// The closed-form centre agrees with projecting c - o where that projection is accurate (near).
TEST(AreaSampler, ClosedFormCentreMatchesProjectionNearby) {
  const Vec3 normal = Vec3(0.3, -0.2, -1.0).normalized();
  for (const double d : {0.5, 1.0, 3.0, 10.0}) {
    const Vec3 center(0.3 * d, 0.2 * d, d);
    const auto area =
        ellipse::AreaSampler::make(ellipse::Disk{center, normal, 1.0, false}, Vec3::Zero());
    const Vec3 projected = area.g.to_local(center);
    // Projection error ~eps |c - o| per component; 16 eps |c - o| covers the frame's rounding.
    const double tol = 16 * std::numeric_limits<double>::epsilon() * center.norm();
    EXPECT_NEAR(area.center_local.x(), projected.x(), tol) << d;
    EXPECT_NEAR(area.center_local.y(), projected.y(), tol) << d;
    EXPECT_NEAR(area.center_local.z(), projected.z(), tol) << d;
  }
}

// The same where the shape is computed for a raised height (o under the disk or above its rim,
// closer than kMinShapeHeight radii). For r below ~1e-158 the raised height kMinShapeHeight r
// is subnormal, and forming it so put the closed form ~1e-11 off the frame (fuzz_maps found an
// area sample whose direction was that far off, against a cosine of 5e-152). Heights that small
// survive only in coordinates near 0 along an axis-aligned normal, as here. c - o is nearby
// (|c - o| <= r), so its projection, in units scaled by a power of two (exact), is accurate to a
// few ulps of |c - o|.
TEST(AreaSampler, ClosedFormCentreMatchesProjectionAtRaisedHeightsAndAnyRadius) {
  int raised_subnormal = 0;
  for (const int k : {-530, -545, -560, -10, 0, 200}) {
    const double r = std::ldexp(1.3, k);
    for (const double tilt : {0.0, 1e-20}) {
      const Vec3 normal(tilt, 0.0, 1.0);
      for (const double rho : {0.0, 0.5, 1.0}) {  // the point's offset from the axis, in radii
        const double t = 1e-152;                  // its height above the disk, in radii
        const Vec3 o(0.0, rho * r, t * r);
        const auto area =
            ellipse::AreaSampler::make(ellipse::Disk{Vec3::Zero(), normal, r, false}, o);
        ASSERT_TRUE(area.valid()) << k;
        ASSERT_TRUE(area.g.shape_raised()) << k;
        if (ellipse::SphericalEllipse::kMinShapeHeight * r < std::numeric_limits<double>::min())
          ++raised_subnormal;
        const Vec3 projected = area.g.to_local(std::ldexp(1.0, -k) * (Vec3::Zero() - o));
        const Vec3 closed = std::ldexp(1.0, -k) * area.center_local;
        const double tol = 16 * std::numeric_limits<double>::epsilon() * projected.norm();
        EXPECT_LE((closed - projected).norm(), tol)
            << "r = 1.3 * 2^" << k << ", tilt " << tilt << ", rho " << rho;
      }
    }
  }
  EXPECT_EQ(raised_subnormal, 18);  // the scales this test is for were reached
}

}  // namespace
}  // namespace disklab::test
