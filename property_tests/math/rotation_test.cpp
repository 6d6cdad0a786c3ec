// The rotation of an angle's cosine and sine by a small step (math/rotation.h): each tier of the
// step's Taylor polynomials is accurate to rounding against long double, and a moved angle's
// cosine and sine agree with the library's at the new angle.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "disklab/math/rotation.h"
#include "disklab/sequence/random.h"

namespace {
using disklab::math::AngleCosSin;
constexpr double kEps = std::numeric_limits<double>::epsilon();

// sin(d) and 1 - cos(d) = 2 sin^2(d / 2) in long double (64-bit significand on x86-64: its own
// error, ~1e-19 relative, is far below the double tolerances).
void reference(double d, long double& sin_d, long double& vers_d) {
  sin_d = std::sin(static_cast<long double>(d));
  const long double h = std::sin(static_cast<long double>(d) / 2);
  vers_d = 2 * h * h;
}

// Every tier's remainder is below 3e-18 relative and its Horner sum rounds to about an ulp: two
// ulps of each value.
void expect_small_step_accurate(double d) {
  double sin_d, vers_d;
  disklab::math::sin_and_versine_small(d, sin_d, vers_d);
  long double rs, rv;
  reference(d, rs, rv);
  EXPECT_LE(std::abs(sin_d - rs), 2 * kEps * std::abs(rs)) << "d = " << d;
  EXPECT_LE(std::abs(vers_d - rv), 2 * kEps * rv) << "d = " << d;
}

TEST(Rotation, EveryTierAccurateUpToItsBoundAndJustBeyond) {
  // The tiers' edges (1e-4, 1/32, kSmallRotation) from both sides, in both signs.
  for (const double edge : {1e-4, 1.0 / 32, disklab::math::kSmallRotation}) {
    for (const double d : {std::nextafter(edge, 0.0), edge, std::nextafter(edge, 1.0)}) {
      if (d > disklab::math::kSmallRotation) continue;
      expect_small_step_accurate(d);
      expect_small_step_accurate(-d);
    }
  }
  // Log-uniform steps from 1e-150 (below, d^2 and so 1 - cos d underflow) to the largest.
  disklab::sequence::Pcg32 rng(11);
  for (int i = 0; i < 20000; ++i) {
    const double d = disklab::math::kSmallRotation * std::pow(10.0, -150.0 * rng.next_double());
    expect_small_step_accurate(rng.next_double() < 0.5 ? d : -d);
  }
  // And uniform ones over the whole range (where the larger tiers' remainders peak).
  for (int i = 0; i <= 4000; ++i)
    expect_small_step_accurate(disklab::math::kSmallRotation * i / 4000.0);
}

RC_GTEST_PROP(Rotation, MovedAngleMatchesTheLibrary, ()) {
  const double a = (*rc::gen::inRange(-1000000, 1000000) / 1000000.0) * 3.2;
  // Steps across every tier and past kSmallRotation (where no rotation is used).
  const double d = std::pow(10.0, -*rc::gen::inRange(0, 14000) / 1000.0) * 0.3 *
                   (*rc::gen::arbitrary<bool>() ? 1.0 : -1.0);
  const AngleCosSin at{a, std::cos(a), std::sin(a)};
  const double x = a + d;
  const AngleCosSin moved = disklab::math::moved_to(at, x);
  RC_ASSERT(moved.s == x);
  // Each of at's values is within an ulp of the truth, the rotation adds about an ulp of |d|
  // and the final sum half an ulp, and std::sin(x) is within an ulp: 4 eps of their scale.
  // Steps past kSmallRotation to an x in [0, 7] take turn_sincos (2 ulps, TurnSincos below),
  // others the library: with std::sin's ulp, within 4 eps |sin x| <= 4 eps (|at.ss| + dd).
  const double dd = std::abs(x - a);
  RC_ASSERT(std::abs(moved.ss - std::sin(x)) <= 4 * kEps * (std::abs(at.ss) + dd));
  RC_ASSERT(std::abs(moved.cs - std::cos(x)) <= 4 * kEps * (std::abs(at.cs) + dd));
}

TEST(Rotation, NoStepReturnsTheSameValues) {
  const AngleCosSin at{0.7, std::cos(0.7), std::sin(0.7)};
  const AngleCosSin moved = disklab::math::moved_to(at, 0.7);
  EXPECT_EQ(moved.cs, at.cs);
  EXPECT_EQ(moved.ss, at.ss);
}

}  // namespace

namespace {

// Distance of a double from a long-double reference in ulps of the value (an ulp of v taken as
// 2^(ilogb(v) - 52)); a zero reference (sin 0) must be matched exactly.
double ulps(double got, long double ref) {
  if (ref == 0.0L) return got == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  const long double ulp = std::ldexp(1.0L, std::ilogb(static_cast<double>(ref)) - 52);
  return static_cast<double>(std::abs(got - ref) / ulp);
}

// Checks `sincos(x)` against long double within `bound` ulps of each value, keeping the worst.
template <class SinCos>
void expect_sincos_within(SinCos&& sincos, double x, double bound, double& worst) {
  const AngleCosSin a = sincos(x);
  EXPECT_EQ(a.s, x);
  const long double rs = std::sin(static_cast<long double>(x)),
                    rc = std::cos(static_cast<long double>(x));
  const double es = ulps(a.ss, rs), ec = ulps(a.cs, rc);
  worst = std::max({worst, es, ec});
  EXPECT_LE(es, bound) << "x = " << x;
  EXPECT_LE(ec, bound) << "x = " << x;
}

}  // namespace

// quarter_sincos against long double on [0, pi/2]: its Taylor remainders are below 3e-18
// relative, and the roundings of y = pi/2 - x (half an ulp of y) and of the sums make about an
// ulp; 2 ulps of each value.
TEST(Rotation, QuarterSincosAccurateOnTheFirstQuadrant) {
  double worst = 0.0;
  auto check = [&](double x) {
    expect_sincos_within(disklab::math::quarter_sincos, x, 2.0, worst);
  };
  const double half_pi = std::numbers::pi / 2;
  for (const double x : {0.0, 1e-300, 1e-9, half_pi / 2, std::nextafter(half_pi / 2, 0.0),
                         std::nextafter(half_pi / 2, 1.0), std::nextafter(half_pi, 0.0), half_pi})
    check(x);
  for (int i = 0; i <= 200000; ++i)
    check(half_pi * i / 200000.0);
  disklab::sequence::Pcg32 rng(5);
  for (int i = 0; i < 100000; ++i)
    check(half_pi * rng.next_double());
  EXPECT_EQ(disklab::math::quarter_sincos(0.0).cs, 1.0);
  std::printf("  worst %.3f ulp\n", worst);
}

// turn_sincos against long double on [0, 2 pi], the quadrants' ends included (where the reduced
// angle is tiny and its sine, the small one of the two values, must stay accurate relative to
// itself): quarter_sincos's 2 ulps, since the reduction's one rounding is half an ulp of the
// reduced angle, i.e. of the small value.
TEST(Rotation, TurnSincosAccurateOnTheWholeTurn) {
  double worst = 0.0;
  auto check = [&](double x) { expect_sincos_within(disklab::math::turn_sincos, x, 2.0, worst); };
  const double half_pi = std::numbers::pi / 2;
  check(0.0);
  for (int q = 1; q <= 4; ++q) {
    double x = q * half_pi;
    for (int k = 0; k < 8; ++k) {
      check(x);
      check(std::nextafter(q * half_pi, 0.0) - k * 1e-16 * q);
      x = std::nextafter(x, 10.0);
    }
  }
  check(2 * std::numbers::pi);
  for (int i = 0; i <= 200000; ++i)
    check(4 * half_pi * i / 200000.0);
  disklab::sequence::Pcg32 rng(7);
  for (int i = 0; i < 100000; ++i)
    check(4 * half_pi * rng.next_double());
  std::printf("  worst %.3f ulp\n", worst);
}
