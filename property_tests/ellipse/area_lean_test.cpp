// The lean area sampler (area_lean.h), the cost baseline of bench_maps: it must be a correct
// sampler, or the ratios measured against it mean nothing. Its density agrees with the precise
// AreaSampler's, its pdf(direction) with what sample reports, its estimate of the solid angle is
// unbiased, and degenerate input gives "no sample", never NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "disklab/disk/concentric.h"
#include "disklab/ellipse/area.h"
#include "disklab/ellipse/area_lean.h"
#include "disklab/ellipse/solid_angle.h"
#include "disklab/sequence/random.h"

namespace disklab::test {
namespace {

using ellipse::Disk;
using ellipse::LeanAreaSampler;
using ellipse::LeanDiskLight;

struct Scene {
  const char* name;
  Disk disk;
};

const Scene kScenes[] = {
    {"near", {Vec3(0.3, 0.2, 0.5), Vec3(0, 0, -1), 1.0, false}},
    {"mid-tilted", {Vec3(1.0, 0.5, 3.0), Vec3(0.3, -0.2, -1.0), 1.0, false}},
    {"grazing", {Vec3(3.0, 0.0, 0.05), Vec3(0, 0, -1), 1.0, false}},
    {"far", {Vec3(300.0, 200.0, 1000.0), Vec3(0.3, -0.2, -1.0), 2.0, false}},
};

// Both densities are |x - o|^2 / (A cos theta_l) for the same disk point; the lean one forms
// the cosine from the rounded world direction (absolute error ~eps, relative ~eps / cos) and
// the distance from world coordinates (relative ~eps |c - o| / |x - o|). At these scenes'
// cosines (>= 0.016 at grazing) 1e-12 is far above both and far below any formula error.
constexpr double kDensityRel = 1e-12;

TEST(LeanArea, FrameIsOrthonormalAndScaledByTheRadius) {
  for (const Scene& s : kScenes) {
    const LeanDiskLight l = LeanDiskLight::make(s.disk);
    ASSERT_TRUE(l.valid()) << s.name;
    const double r = s.disk.radius;
    // A few ulps of rounding in the branchless basis and the scaling.
    const double tol = 8 * std::numeric_limits<double>::epsilon();
    EXPECT_NEAR(l.normal.norm(), 1.0, tol) << s.name;
    EXPECT_NEAR(l.t1.norm() / r, 1.0, tol) << s.name;
    EXPECT_NEAR(l.t2.norm() / r, 1.0, tol) << s.name;
    EXPECT_NEAR(l.t1.dot(l.t2) / (r * r), 0.0, tol) << s.name;
    EXPECT_NEAR(l.t1.dot(l.normal) / r, 0.0, tol) << s.name;
    EXPECT_NEAR(l.t2.dot(l.normal) / r, 0.0, tol) << s.name;
    EXPECT_NEAR(l.inv_area * std::acos(-1.0) * r * r, 1.0, tol) << s.name;
  }
}

TEST(LeanArea, DensityMatchesThePreciseSamplerAndItsOwnPdf) {
  sequence::Pcg32 rng(11);
  for (const Scene& s : kScenes) {
    const LeanDiskLight light = LeanDiskLight::make(s.disk);
    const LeanAreaSampler lean = LeanAreaSampler::make(light, Vec3::Zero());
    const auto precise = ellipse::AreaSampler::make(s.disk, Vec3::Zero());
    ASSERT_TRUE(lean.valid() && precise.valid()) << s.name;
    for (int i = 0; i < 2000; ++i) {
      const Point2 u{rng.next_double(), rng.next_double()};
      const auto x = lean.sample(u);
      ASSERT_TRUE(x.valid) << s.name;
      EXPECT_NEAR(x.direction.norm(), 1.0, 4 * std::numeric_limits<double>::epsilon());
      // The point is on the disk: in its plane and within its radius (relative rounding).
      const Vec3 off = x.point - s.disk.center;
      EXPECT_LE(off.norm(), s.disk.radius * (1 + 1e-14)) << s.name;
      EXPECT_NEAR(off.dot(light.normal) / s.disk.radius, 0.0, 1e-13) << s.name;
      EXPECT_NEAR(lean.pdf(x.direction) / x.pdf, 1.0, kDensityRel) << s.name << " " << i;
      EXPECT_NEAR(precise.pdf(x.direction) / x.pdf, 1.0, kDensityRel) << s.name << " " << i;
    }
  }
}

// The sampler's two-region form (signed radius, angle in [-pi/4, pi/4]) is Shirley and Chiu's
// concentric map, point for point: its disk coordinates match sample_concentric's four-region
// form on every region, edges and centre included. Both round a few operations on numbers of
// order 1 (the 4-region angle reaches 7 pi / 4), and the disk coordinates are read back from
// world coordinates of magnitude |c| + r <= 5 here: 1e-14 is well above that rounding, far below
// any wrong region (an error of order 1).
TEST(LeanArea, TwoRegionFormIsTheConcentricMap) {
  constexpr double kTol = 1e-14;
  sequence::Pcg32 rng(3);
  for (const Scene& s : {kScenes[0], kScenes[1]}) {
    const LeanDiskLight light = LeanDiskLight::make(s.disk);
    const LeanAreaSampler lean = LeanAreaSampler::make(light, Vec3::Zero());
    const double r2 = s.disk.radius * s.disk.radius;
    std::vector<Point2> us = {{0.5, 0.5}, {0.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}, {1.0, 0.0},
                              {0.5, 0.0}, {0.5, 1.0}, {0.0, 0.5}, {1.0, 0.5}, {0.75, 0.75}};
    for (int i = 0; i < 4000; ++i)
      us.push_back({rng.next_double(), rng.next_double()});
    for (const Point2 u : us) {
      const auto x = lean.sample(u);
      ASSERT_TRUE(x.valid) << s.name;
      const Vec3 off = x.point - s.disk.center;
      const Point2 want = disk::sample_concentric(u);
      EXPECT_NEAR(off.dot(light.t1) / r2, want.x, kTol) << s.name << " u " << u.x << "," << u.y;
      EXPECT_NEAR(off.dot(light.t2) / r2, want.y, kTol) << s.name << " u " << u.x << "," << u.y;
    }
  }
}

// E[1 / pdf] = Omega for a density supported on the disk's solid angle. Plain random points and
// a 5-sigma bound from the sample's own spread (a false alarm about once in 1.7 million runs).
TEST(LeanArea, EstimatesTheSolidAngleWithoutBias) {
  sequence::Pcg32 rng(5);
  constexpr int kN = 200000;
  for (const Scene& s : kScenes) {
    const LeanDiskLight light = LeanDiskLight::make(s.disk);
    const LeanAreaSampler lean = LeanAreaSampler::make(light, Vec3::Zero());
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < kN; ++i) {
      const auto x = lean.sample({rng.next_double(), rng.next_double()});
      const double w = x.valid ? 1.0 / x.pdf : 0.0;
      sum += w;
      sum2 += w * w;
    }
    const double mean = sum / kN;
    const double sd = std::sqrt(std::max(0.0, sum2 / kN - mean * mean));
    const double omega = ellipse::solid_angle(s.disk, Vec3::Zero());
    EXPECT_NEAR(mean, omega, 5.0 * sd / std::sqrt(double(kN)) + 1e-14 * omega) << s.name;
  }
}

TEST(LeanArea, PdfIsZeroOffTheDiskAndBehindIt) {
  const Scene& s = kScenes[1];
  const LeanDiskLight light = LeanDiskLight::make(s.disk);
  const LeanAreaSampler lean = LeanAreaSampler::make(light, Vec3::Zero());
  const Vec3 to_center = s.disk.center.normalized();
  EXPECT_GT(lean.pdf(to_center), 0.0);
  EXPECT_EQ(lean.pdf(-to_center), 0.0);                    // away from the light
  EXPECT_EQ(lean.pdf(Vec3(1, 0, 0)), 0.0);                 // misses it
  EXPECT_EQ(lean.pdf(Vec3::Zero()), 0.0);                  // no direction
  EXPECT_EQ(lean.pdf(Vec3(std::nan(""), 0.0, 1.0)), 0.0);  // NaN
  // The rim: a direction through a point just outside the disk misses it.
  const Vec3 outside = s.disk.center + 1.001 * light.t1;
  EXPECT_EQ(lean.pdf(outside.normalized()), 0.0);
  const Vec3 inside = s.disk.center + 0.999 * light.t1;
  EXPECT_GT(lean.pdf(inside.normalized()), 0.0);
}

TEST(LeanArea, DegenerateInputGivesNoSample) {
  const Vec3 c(0, 0, 2), n(0, 0, -1);
  const double nan = std::nan("");
  const Disk bad[] = {
      {c, n, 0.0, false},                // zero radius
      {c, Vec3::Zero(), 1.0, false},     // zero normal
      {Vec3(nan, 0, 2), n, 1.0, false},  // non-finite centre
      {c, n, std::numeric_limits<double>::infinity(), false},
  };
  for (const Disk& d : bad) {
    const LeanDiskLight light = LeanDiskLight::make(d);
    EXPECT_FALSE(light.valid());
    const LeanAreaSampler s = LeanAreaSampler::make(light, Vec3::Zero());
    EXPECT_FALSE(s.valid());
    EXPECT_FALSE(s.sample({0.5, 0.5}).valid);
    EXPECT_EQ(s.pdf(Vec3(0, 0, 1)), 0.0);
  }
  // Behind a one-sided disk, in its plane, or a non-finite shading point: nothing; a two-sided
  // disk is seen from behind.
  const LeanDiskLight one = LeanDiskLight::make({c, n, 1.0, false});
  const LeanDiskLight two = LeanDiskLight::make({c, n, 1.0, true});
  const Vec3 behind(0, 0, 3), in_plane(5, 0, 2);
  EXPECT_FALSE(LeanAreaSampler::make(one, behind).valid());
  EXPECT_FALSE(LeanAreaSampler::make(one, in_plane).valid());
  EXPECT_FALSE(LeanAreaSampler::make(one, Vec3(nan, 0, 0)).valid());
  const LeanAreaSampler back = LeanAreaSampler::make(two, behind);
  ASSERT_TRUE(back.valid());
  const auto x = back.sample({0.3, 0.7});
  ASSERT_TRUE(x.valid);
  EXPECT_GT(x.pdf, 0.0);
  EXPECT_NEAR(back.pdf(x.direction) / x.pdf, 1.0, kDensityRel);
  // u outside the unit square, NaN included: no sample.
  const LeanAreaSampler front = LeanAreaSampler::make(one, Vec3::Zero());
  for (const Point2 u : {Point2{-0.1, 0.5}, Point2{0.5, 1.5}, Point2{nan, 0.5}})
    EXPECT_FALSE(front.sample(u).valid);
}

}  // namespace
}  // namespace disklab::test
