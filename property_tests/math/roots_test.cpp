// Safeguarded root finding (math/roots.h): Halley's variant keeps Newton's contract (the iterate
// never leaves the bracket, the result meets the residual tolerance) and needs fewer evaluations.
// Residuals are compared with f_tol plus the rounding of one evaluation (kEvalRounding).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include "disklab/math/roots.h"
#include "disklab/sequence/random.h"

namespace {
using disklab::math::Derivatives3;

constexpr double kPi = 3.14159265358979323846;
// Evaluating E - e sin E - M near its root rounds to a few ulps of pi: the residual the solvers
// can be held to is f_tol plus that.
constexpr double kEvalRounding = 8 * std::numeric_limits<double>::epsilon() * kPi;
constexpr double kTol = 1e-15;

// Kepler's equation E - e sin E = M on [0, pi]: increasing for e < 1, flat at E = 0 as e -> 1.
Derivatives3 kepler(double e, double m, double x) {
  const double s = std::sin(x), c = std::cos(x);
  return {x - e * s - m, 1.0 - e * c, e * s, e * c};
}

RC_GTEST_PROP(Halley, KeplerConvergesInsideTheBracket, ()) {
  const double e = *rc::gen::inRange(0, 990) / 1000.0;
  const double m = *rc::gen::inRange(0, 1000000) / 1000000.0 * kPi;
  const double x0 = *rc::gen::inRange(0, 1000) / 1000.0 * kPi;
  const auto r = disklab::math::safeguarded_halley([&](double x) { return kepler(e, m, x); }, 0.0,
                                                   kPi, x0, kTol, 1e-17, 64);
  RC_ASSERT(r.converged);
  RC_ASSERT(r.x >= 0.0 && r.x <= kPi);
  RC_ASSERT(std::abs(kepler(e, m, r.x).g) <= kTol + kEvalRounding);
}

RC_GTEST_PROP(Halley, FlatCubicFallsBackInsideTheBracket, ()) {
  // g = x^3 - c on [-1, 2]: g' = 0 at 0, where neither Halley nor Newton can step.
  const double c = *rc::gen::inRange(-1000, 8000) / 1000.0;
  const double x0 = *rc::gen::inRange(-1000, 2000) / 1000.0;
  const auto r = disklab::math::safeguarded_halley(
      [&](double x) {
        return Derivatives3{x * x * x - c, 3 * x * x, 6 * x, 6.0};
      },
      -1.0, 2.0, x0, kTol, 1e-17, 200);
  RC_ASSERT(r.converged);
  RC_ASSERT(r.x >= -1.0 && r.x <= 2.0);
  // Near a flat root the residual pins x only to ~(f_tol / 3 x^2): compare residuals.
  RC_ASSERT(std::abs(r.x * r.x * r.x - c) <=
            kTol + 16 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(c)));
}

// halley_step's one-division form against the textbook two-division form dn / (1 + dn g2 /
// (2 g1)), dn = -g / g1, over values and derivatives of every sign and 20 decades of scale each:
// both round a handful of operations on the same quantities, so they agree to a few ulps of the
// step (16 eps, relative), and choose the same kind of step away from its boundary (denominator
// 1/2). Beyond g1 in [2^-400, 2^400], where g1^2 would leave double's range, the step stays
// finite and is the two-division form itself.
RC_GTEST_PROP(Halley, OneDivisionStepMatchesTheTextbookForm, ()) {
  auto scaled = [](int decade, int mantissa) { return std::pow(10.0, decade) * mantissa / 1000.0; };
  const double g1 = scaled(*rc::gen::inRange(-10, 10), *rc::gen::inRange(1, 10000));
  const double g = scaled(*rc::gen::inRange(-10, 10), *rc::gen::inRange(-10000, 10000));
  const double g2 = scaled(*rc::gen::inRange(-10, 10), *rc::gen::inRange(-10000, 10000));
  const Derivatives3 e{g, g1, g2, 0.0};
  const auto step = disklab::math::halley_step(e);
  const double dn = -g / g1, denom = 1.0 + 0.5 * dn * g2 / g1;
  if (std::abs(denom - 0.5) > 1e-9) RC_ASSERT(step.halley == (denom >= 0.5));
  const double textbook = step.halley ? dn / denom : dn;
  RC_ASSERT(std::abs(step.delta - textbook) <=
            16 * std::numeric_limits<double>::epsilon() * std::abs(textbook));
  // Out of range of g1^2: the two-division form, finite.
  for (const double tiny_or_huge : {0x1p-450, 0x1p450}) {
    const Derivatives3 x{g * tiny_or_huge, g1 * tiny_or_huge, g2 * tiny_or_huge, 0.0};
    const auto s = disklab::math::halley_step(x);
    RC_ASSERT(std::isfinite(s.delta));
    RC_ASSERT(std::abs(s.delta - textbook) <=
              16 * std::numeric_limits<double>::epsilon() * std::abs(textbook));
  }
}

TEST(Halley, FewerEvaluationsThanNewtonOnKepler) {
  // Cubic against quadratic convergence from the same start, with each solver's own final step
  // (Newton's: a step below 1e-9 of the bracket).
  disklab::sequence::Pcg32 rng(3);
  double halley = 0.0, newton = 0.0;
  constexpr int kCases = 4000;
  for (int i = 0; i < kCases; ++i) {
    const double e = 0.9 * rng.next_double(), m = kPi * rng.next_double();
    const double x0 = m;  // the e = 0 solution
    halley += disklab::math::safeguarded_halley([&](double x) { return kepler(e, m, x); }, 0.0, kPi,
                                                x0, kTol, 1e-17, 64)
                  .iterations;
    newton += disklab::math::safeguarded_newton(
                  [&](double x) {
                    const Derivatives3 d = kepler(e, m, x);
                    return std::pair<double, double>(d.g, d.d1);
                  },
                  0.0, kPi, x0, kTol, 1e-17, 64,
                  [&](double, double delta) { return std::abs(delta) <= 1e-9 * kPi; })
                  .iterations;
  }
  std::printf("  mean evaluations: Halley %.2f, Newton %.2f\n", halley / kCases, newton / kCases);
  EXPECT_LT(halley, 0.85 * newton);
}

}  // namespace
