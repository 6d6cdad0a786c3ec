#pragma once
// An angle with its cosine and sine, moved by a step without a library call when the step is
// small: the root solves' iterates move by ever smaller steps, and each step's sine and cosine
// follow from the previous ones by a rotation; larger steps, and starting values, take sine and
// cosine polynomials after a quadrant reduction. All are forced inline: called out of line, the
// call costs as much as the polynomial saves.
#include <cmath>

namespace disklab::math {

struct AngleCosSin {
  double s = 0.0, cs = 1.0, ss = 0.0;  // the angle, its cosine and sine
};

// Steps up to this size take the rotation; larger ones turn_sincos (x in [0, 7]) or the library.
inline constexpr double kSmallRotation = 0.125;

// sin(d) and 1 - cos(d) for |d| <= kSmallRotation by their Taylor series in two tiers: tiny
// steps (a root solve's last ones) through d^3 and d^4, all others through d^11 and d^12; the
// first term left out is below 3e-18 of the value (relative) on each. Two tiers, not more: the
// size of a solve's first steps is as random as its input, and a mispredicted choice of tier
// costs more than the longer polynomial. Estrin's scheme in y = d^2 with the coefficients
// 1 / k!: y <= 1/64 keeps every term after the first below 3e-3 of the sum, so their rounding
// is sub-ulp.
[[gnu::always_inline]] inline void sin_and_versine_small(double d, double& sin_d, double& vers_d) {
  const double y = d * d;
  if (y <= 1e-8) {  // |d| <= 1e-4 (next terms: d^4 / 120, d^4 / 360 relative)
    sin_d = d - d * y * (1.0 / 6);
    vers_d = 0.5 * y - y * y * (1.0 / 24);
  } else {  // next terms: d^12 / 13!, d^12 / 43589145600 relative
    const double y2 = y * y, y4 = y2 * y2;
    const double ps = ((-1.0 / 6 + y * (1.0 / 120)) + y2 * (-1.0 / 5040 + y * (1.0 / 362880))) +
                      y4 * (-1.0 / 39916800);
    const double pv = ((-1.0 / 24 + y * (1.0 / 720)) + y2 * (-1.0 / 40320 + y * (1.0 / 3628800))) +
                      y4 * (-1.0 / 479001600);
    sin_d = d + (d * y) * ps;
    vers_d = 0.5 * y + y2 * pv;
  }
}

// The angle x in [0, pi/2] with its cosine and sine, without a library call (the radial maps'
// per-sample tau = t pi/2): on [0, pi/4] the Taylor series of sin through y^17 and of cos
// through y^16 (remainders below 1e-19 and 3e-18 relative at pi/4), above it the same at
// y = pi/2 - x (exact by Sterbenz's lemma, plus pi/2's rounding 6.1e-17). The small parts
// y^3 P(y^2) <= 0.11 y and y^2/2 <= 0.31 round to a fraction of an ulp of the sums: about one
// ulp in all. Plain products and sums, no std::fma: without FMA hardware in the build's target
// each would be a library call. Inputs outside [0, pi/2] (and NaN) are the caller's to avoid.
[[gnu::always_inline]] inline AngleCosSin quarter_sincos(double x) {
  constexpr double kHalfPiHi = 0x1.921fb54442d18p0, kHalfPiLo = 0x1.1a62633145c07p-54;
  const bool upper = x > 0.5 * kHalfPiHi;
  const double y = upper ? (kHalfPiHi - x) + kHalfPiLo : x;
  const double z = y * y, z2 = z * z, z4 = z2 * z2;
  // sin y = y + y^3 P(z): P = sum_{k=0..7} (-1)^(k+1) z^k / (2k+3)!; cos y = 1 - z/2 + z^2 Q(z):
  // Q = sum_{k=0..6} (-1)^k z^k / (2k+4)!. Estrin's scheme: short dependency chains.
  constexpr double p0 = -1.0 / 6, p1 = 1.0 / 120, p2 = -1.0 / 5040, p3 = 1.0 / 362880,
                   p4 = -1.0 / 39916800, p5 = 1.0 / 6227020800.0, p6 = -1.0 / 1307674368000.0,
                   p7 = 1.0 / 355687428096000.0;
  constexpr double q0 = 1.0 / 24, q1 = -1.0 / 720, q2 = 1.0 / 40320, q3 = -1.0 / 3628800,
                   q4 = 1.0 / 479001600, q5 = -1.0 / 87178291200.0, q6 = 1.0 / 20922789888000.0;
  const double p = ((p0 + p1 * z) + z2 * (p2 + p3 * z)) + z4 * ((p4 + p5 * z) + z2 * (p6 + p7 * z));
  const double q = ((q0 + q1 * z) + z2 * (q2 + q3 * z)) + z4 * ((q4 + q5 * z) + z2 * q6);
  const double sin_y = y + (y * z) * p;
  const double cos_y = (1.0 - 0.5 * z) + z2 * q;
  return upper ? AngleCosSin{x, sin_y, cos_y} : AngleCosSin{x, cos_y, sin_y};
}

// The angle x in [0, 2 pi] with its cosine and sine, without a library call: x = q pi/2 + y,
// q the nearest integer to x / (pi/2) and |y| <= pi/4, y by Cody and Waite's reduction in three
// parts of pi/2 (q kP1 and q kP2 exact for q <= 4, x - q kP1 exact by Sterbenz's lemma, and the
// difference with q kP2 too where y is small), so that y is within half an ulp of itself even
// next to a multiple of pi/2, where its sine is the small one of the two values; then
// quarter_sincos(|y|) with sin y's sign, turned by q quarter turns.
[[gnu::always_inline]] inline AngleCosSin turn_sincos(double x) {
  constexpr double kP1 = 0x1.921fb544p0, kP2 = 0x1.0b4611a6p-34, kP3 = 0x1.3198a2e037073p-69;
  // Rounding by truncation of x (2/pi) + 1/2 (x >= 0; no library call): a q one off at a
  // half-way point still leaves |y| <= pi/4 + a few ulps, within quarter_sincos's range.
  // NOLINTNEXTLINE(bugprone-incorrect-roundings)
  const int q = static_cast<int>(x * (2.0 / 3.141592653589793) + 0.5);
  const double y = ((x - q * kP1) - q * kP2) - q * kP3;
  AngleCosSin r = quarter_sincos(std::abs(y));
  if (y < 0.0) r.ss = -r.ss;
  switch (q & 3) {
    case 1:
      return {x, -r.ss, r.cs};
    case 2:
      return {x, -r.cs, -r.ss};
    case 3:
      return {x, r.ss, -r.cs};
    default:
      return {x, r.cs, r.ss};
  }
}

// The angle `x` with its cosine and sine, from `at`'s. Near at.s the rotation by d = x - at.s:
// sin(x) = sin + (cos sin_d - sin vers_d), cos(x) = cos - (sin sin_d + cos vers_d), whose
// corrections are as small as d (a few ulps more than the library's own rounding). Larger steps
// start afresh: turn_sincos where x is in its range, else std::cos and std::sin.
[[gnu::always_inline]] inline AngleCosSin moved_to(const AngleCosSin& at, double x) {
  const double d = x - at.s;
  if (d == 0.0) return at;
  if (!(std::abs(d) <= kSmallRotation)) {
    if (x >= 0.0 && x <= 7.0) return turn_sincos(x);  // within turn_sincos's range (q <= 4)
    return {x, std::cos(x), std::sin(x)};
  }
  double sin_d, vers_d;
  sin_and_versine_small(d, sin_d, vers_d);
  return {x, at.cs - (at.ss * sin_d + at.cs * vers_d), at.ss + (at.cs * sin_d - at.ss * vers_d)};
}

}  // namespace disklab::math
