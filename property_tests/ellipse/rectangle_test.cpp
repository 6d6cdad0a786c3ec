// The closed-form slice of the spherical rectangle (rectangle.h, "THE SLICE IN CLOSED FORM"), which
// starts Gamito's Newton solve: it must solve G(X) = t to the solve's own tolerance on almost
// every square, so that the solve usually ends at its first evaluation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "disklab/ellipse/rectangle.h"
#include "disklab/sequence/random.h"

namespace disklab::test {
namespace {

using ellipse::SphericalRectangle;
using W = SphericalRectangle::W;

struct StartStats {
  int squares = 0, within_tolerance = 0, not_finite = 0;
  double worst = 0.0;  // max |G(X) - t| / S
};

// Squares at depth h = 10^a and centre offset yc, 10^a or (every third) uniform in [0, 1) (the
// point's foot inside the square's y range), a uniform in [-decades, decades]; u uniform.
StartStats start_residuals(double decades, int count, uint64_t seed) {
  sequence::Pcg32 rng(seed, 5);
  StartStats st;
  for (int i = 0; i < count; ++i) {
    const double h = std::pow(10.0, decades * (2.0 * rng.next_double() - 1.0));
    const double yc =
        i % 3 == 0 ? rng.next_double() : std::pow(10.0, decades * (2.0 * rng.next_double() - 1.0));
    const SphericalRectangle r = SphericalRectangle::make(h, yc);
    if (!r.valid()) continue;
    const double u = rng.next_double();
    const W t = (W(u) - 0.5L) * r.S;
    const double x = r.slice_start(t);
    ++st.squares;
    if (!std::isfinite(x)) {
      ++st.not_finite;
      continue;
    }
    const double e = static_cast<double>(std::fabs(r.G(std::clamp(x, -1.0, 1.0)) - t) / r.S);
    if (e <= ellipse::kRectangleNewtonTol) ++st.within_tolerance;
    st.worst = std::max(st.worst, e);
  }
  std::printf(
      "  h, yc in 1e-%g..1e%g: %d squares, %.5f within the solve's tolerance, worst %.3g "
      "of S, %d not finite\n",
      decades, decades, st.squares, double(st.within_tolerance) / st.squares, st.worst,
      st.not_finite);
  return st;
}

TEST(Rectangle, ClosedFormSliceSolvesTheSliceEquation) {
  // Squares within 1e3 radii of the point: the residual is long double rounding, amplified only
  // where P^2 - s^2 cancels (u within ~1e-3 of 0 or 1 on squares seen edge-on), where it just
  // exceeds the tolerance (about 1 draw in 10^4 here). The worst-case bound leaves 30x margin
  // over what that cancellation gives at h = 1e-3; a wrong P^2 or Q^2 gives 1e-10..1e-2.
  const StartStats st = start_residuals(3.0, 100000, 1);
  EXPECT_EQ(st.not_finite, 0);
  EXPECT_GE(st.within_tolerance, 0.999 * st.squares);
  EXPECT_LT(st.worst, 1e-13);
}

TEST(Rectangle, ClosedFormSliceIsFiniteAtExtremeScales) {
  // 1e-9..1e9 radii: more squares seen edge-on, so more near-end draws need Newton's steps;
  // the start must still be finite and within tolerance on 99% (it is at 99.9%).
  const StartStats st = start_residuals(9.0, 100000, 2);
  EXPECT_EQ(st.not_finite, 0);
  EXPECT_GE(st.within_tolerance, 0.99 * st.squares);
}

TEST(Rectangle, ClosedFormSliceIsOddAndCentred) {
  // G is odd in X, and so is its inverse: exactly, since only sin(t/2) changes sign.
  for (const double h : {1e-3, 0.5, 2.0, 1e4})
    for (const double yc : {0.0, 0.3, 1.0, 7.0, 1e5}) {
      const SphericalRectangle r = SphericalRectangle::make(h, yc);
      ASSERT_TRUE(r.valid()) << h << " " << yc;
      EXPECT_EQ(r.slice_start(0.0L), 0.0);
      for (const double f : {0.1, 0.3, 0.49}) {
        const W t = W(f) * r.S;
        EXPECT_EQ(r.slice_start(-t), -r.slice_start(t)) << h << " " << yc << " " << f;
      }
    }
}

}  // namespace
}  // namespace disklab::test
