// The studies' references (verify/study/reference.h): the closed form of a parallel disk, and the
// penumbra quadrature, checked against closed forms it does not use, against an independent
// Monte Carlo estimate, and at its domain's edges.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>

#include "disklab/math/constants.h"
#include "study/convergence.h"
#include "study/reference.h"
#include "support/stats.h"

namespace {
using disklab::Vec3;
using disklab::math::kPi;
using namespace disklab::study;
namespace t = disklab::test;

// ---- Tolerances and sizes (the one place for this suite) ----
constexpr double kEps = std::numeric_limits<double>::epsilon();
// The closed form is a dozen roundings and two square roots: 16 eps relative bounds it.
constexpr double kClosedFormRel = 16.0 * kEps;
// The quadrature's error estimates must be tight as well as true: at most 1e-13 relative on
// these unoccluded scenes (the target is 1e-14; rounding adds a few 1e-15).
constexpr double kQuadratureEstimateRel = 1e-13;
// The printed form 1 - X/Y near the light, where it cancels nothing: 1e-14 absolute on E ~ 1.
constexpr double kPrintedFormAbs = 1e-14;
// The issue's target for the penumbra references' error estimates (relative).
constexpr double kPenumbraTarget = 1e-12;
// Monte Carlo cross-check: samples per point, and the family significance over the 16 points.
constexpr int kMonteCarloSamples = 2'000'000;
constexpr double kFamilyAlpha = 1e-3;

Scene unoccluded(double radius = 1.0, double height = 2.0) {
  Scene s;
  s.light.center = Vec3(0.0, 0.0, height);
  s.light.normal = Vec3(0.0, 0.0, -1.0);
  s.light.radius = radius;
  return s;
}

ShadingPoint ground(double x, double y) {
  return {Vec3(x, y, 0.0), Vec3::UnitZ()};
}

// The quadrature and the closed form agree within the sum of their error bounds.
void expect_agrees(const ReferenceValue& q, double exact, const std::string& what) {
  EXPECT_LE(std::fabs(q.value - exact), q.error_estimate + kClosedFormRel * std::fabs(exact))
      << what << ": quadrature " << q.value << " +- " << q.error_estimate << ", exact " << exact;
  EXPECT_LE(q.error_estimate, kQuadratureEstimateRel * std::fabs(exact))
      << what << ": error estimate too loose";
}

TEST(Reference, ClosedFormEqualsTheMemoIssuesFormulaWhereThatIsAccurate) {
  // Near the light the printed form (1 - X / Y) loses nothing worth measuring.
  for (double d : {0.0, 0.3, 1.0, 2.5}) {
    const double h = 2.0, r = 1.0;
    const double printed = 0.5 * kPi *
                           (1.0 - (h * h + d * d - r * r) /
                                      std::sqrt((h * h + d * d + r * r) * (h * h + d * d + r * r) -
                                                4 * d * d * r * r));
    EXPECT_NEAR(disk_irradiance_parallel(1.0, r, h, d), printed, kPrintedFormAbs) << "d = " << d;
  }
}

TEST(Reference, ClosedFormKeepsItsDigitsFarAndNear) {
  // On axis the form factor is pi R^2 / (h^2 + R^2) exactly; at h = 1e5 the printed 1 - X / Y
  // would keep only about 6 digits, and its rewritten form 4 R^2 h^2 / (Y (Y + X)) cancels
  // close under the disk (X -> -R^2).
  for (double h : {1e-6, 0.05, 1e2, 1e5, 1e8}) {
    const double exact = kPi / (h * h + 1.0);
    EXPECT_NEAR(disk_irradiance_parallel(1.0, 1.0, h, 0.0), exact, kClosedFormRel * exact)
        << "h = " << h;
  }
}

TEST(Reference, QuadratureOfAnUnoccludedDiskIsTheClosedForm) {
  // Foot of the shading point inside the disk, on its axis, near the rim on both sides, far off.
  for (double d : {0.0, 0.4, 0.999999999, 1.0, 1.000000001, 1.7, 3.0, 50.0})
    for (double h : {0.05, 2.0, 30.0}) {
      const Scene s = unoccluded(1.0, h);
      const ReferenceValue q = irradiance_quadrature(s, ground(d * 0.6, -d * 0.8));
      expect_agrees(q, disk_irradiance_parallel(1.0, 1.0, h, d),
                    "d = " + std::to_string(d) + ", h = " + std::to_string(h));
    }
}

TEST(Reference, FullyLitRegionsAreUnoccluded) {
  // The study uses the closed form there; the quadrature with the sphere present must agree.
  const Scene scene = memo_scene();
  for (const StudyRegion& region : memo_regions()) {
    if (!region.fully_lit) continue;
    for (const ShadingPoint& p : region.grid.points()) {
      const double d = std::hypot(p.position.x(), p.position.y());
      expect_agrees(irradiance_quadrature(scene, p), disk_irradiance_parallel(1.0, 1.0, 2.0, d),
                    region.grid.name);
    }
  }
}

TEST(Reference, SphereOnTheAxisLeavesAnAnnulus) {
  // From the origin a sphere of radius r centred at height c on the axis hides the cone of
  // half-angle asin(r / c): on the light's plane (height h) a disk of radius h tan(alpha). The
  // annulus outside it gives pi L (R^2 / (h^2 + R^2) - rho^2 / (h^2 + rho^2)).
  for (double r : {0.1, 0.3, 0.4}) {
    Scene s = unoccluded(1.0, 2.0);
    s.occluders.push_back({Vec3(0.0, 0.0, 1.0), r});
    const double rho = 2.0 * r / std::sqrt(1.0 - r * r);
    const double exact = kPi * (1.0 / 5.0 - rho * rho / (4.0 + rho * rho));
    expect_agrees(irradiance_quadrature(s, ground(0.0, 0.0)), exact, "r = " + std::to_string(r));
  }
}

TEST(Reference, PenumbraErrorEstimatesMeetTheTarget) {
  const Scene scene = memo_scene();
  for (const StudyRegion& region : memo_regions()) {
    if (region.fully_lit) continue;
    for (const ShadingPoint& p : region.grid.points()) {
      const ReferenceValue q = irradiance_quadrature(scene, p);
      const double unoccluded_e =
          disk_irradiance_parallel(1.0, 1.0, 2.0, std::hypot(p.position.x(), p.position.y()));
      EXPECT_LE(q.error_estimate, kPenumbraTarget * q.value) << p.position.transpose();
      // Partly shadowed: strictly between nothing and the whole disk.
      EXPECT_GT(q.value, 0.05 * unoccluded_e) << p.position.transpose();
      EXPECT_LT(q.value, 0.95 * unoccluded_e) << p.position.transpose();
    }
  }
}

TEST(Reference, PenumbraAgreesWithAnIndependentMonteCarloEstimate) {
  // Uniform points on the disk by rejection from the square (std::mt19937_64, none of the
  // library's samplers), the same segment-sphere visibility; |quadrature - MC| <= z SE.
  const Scene scene = memo_scene();
  const auto points = memo_regions()[2].grid.points();
  const double z = t::normal_two_sided_quantile(t::sidak_alpha(kFamilyAlpha, points.size()));
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  for (const ShadingPoint& p : points) {
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < kMonteCarloSamples;) {
      const double x = uni(rng), y = uni(rng);
      if (x * x + y * y > 1.0) continue;
      const double f = kPi * irradiance_integrand(scene, p, Vec3(x, y, 2.0));
      sum += f;
      sum2 += f * f;
      ++i;
    }
    const double mean = sum / kMonteCarloSamples;
    const double se =
        std::sqrt((sum2 / kMonteCarloSamples - mean * mean) / (kMonteCarloSamples - 1));
    const ReferenceValue q = irradiance_quadrature(scene, p);
    EXPECT_LE(std::fabs(q.value - mean), z * se)
        << p.position.transpose() << ": quadrature " << q.value << ", MC " << mean << " +- " << se;
  }
}

TEST(Reference, BehindAOneSidedLightIsDarkAndATwoSidedOneMirrors) {
  Scene s = unoccluded(1.0, 2.0);
  const ShadingPoint above{Vec3(0.3, 0.2, 4.0), -Vec3::UnitZ()};
  EXPECT_EQ(irradiance_quadrature(s, above).value, 0.0);
  s.light.two_sided = true;
  expect_agrees(irradiance_quadrature(s, above),
                disk_irradiance_parallel(1.0, 1.0, 2.0, std::hypot(0.3, 0.2)), "two-sided");
}

TEST(Reference, RefusesWhatItCannotIntegrate) {
  Scene s = unoccluded(1.0, 2.0);
  s.occluders.push_back({Vec3(0.0, 0.0, 0.0), 0.5});
  EXPECT_THROW(irradiance_quadrature(s, ground(0.1, 0.0)), std::domain_error);  // inside it
  s.occluders = {{Vec3(0.0, 0.0, 2.0), 0.5}};
  EXPECT_THROW(irradiance_quadrature(s, ground(0.0, 0.0)), std::domain_error);  // in the plane
  // A receiver facing sideways sees part of the disk below its horizon.
  s.occluders.clear();
  EXPECT_THROW(irradiance_quadrature(s, {Vec3(0.0, 0.0, 0.0), Vec3::UnitX()}), std::domain_error);
}

}  // namespace
