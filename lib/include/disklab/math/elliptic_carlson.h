#pragma once
// Carlson's symmetric elliptic integrals R_C, R_F, R_D, R_J (DLMF 19.16.1-2, 19.2.17), templated
// on the real type so the same code runs in double and in boost::multiprecision::cpp_bin_float_50
// (the reference tables are checked that way). The Legendre forms built on them are in
// elliptic_legendre.h; elliptic.h includes both.
//
// METHOD: duplication (DLMF 19.36.1-2) to the point where the Taylor tail (terms through degree
// 7) is below machine epsilon; R_J's sum uses R_C(1, 1 + e_k), evaluated by its series once e_k
// is small (it shrinks by 64 per step). R_F and R_J with the same x, y, z share one loop.
//
// PRECISION: for Real = double the duplication loops and series run in long double (x87, 64-bit
// significand): the loops are where the rounding of 4-6 steps accumulates (about 4 ulp at worst
// in pure double), and carrying them with 11 extra bits brings the Legendre forms to within
// 2 ulp of the correctly rounded value (measured against the 50-digit tables). Where long
// double is no wider than double the loops run in double. Any other Real (e.g.
// cpp_bin_float_50) computes everything in Real.
#include <cmath>
#include <limits>
#include <type_traits>

namespace disklab::math {

namespace detail {

// Working type of the Carlson loops for an interface type Real (see PRECISION above).
template <class Real>
using work_t = std::conditional_t<std::is_same_v<Real, double> &&
                                      (std::numeric_limits<long double>::digits > 53),
                                  long double, Real>;

// Duplication stops when every |X_j| (the arguments' relative spread) is below this, so the
// neglected degree-8 tail, at most about |X|^8 / 10, is negligible against Real's epsilon.
// For double results: 0.01^8 / 10 = 1e-17, under 0.1 ulp of the double result; on the 50-digit
// tables (and Boost's ellint_1 inputs) it leaves every F and portable Pi bit-identical to 0.005
// and saves half a duplication step, while 0.02 already shows (F 3 ulp, portable Pi 2 ulp, from
// 1, against the correctly rounded values).
// In general eps^(1/8) / 2.
template <class Real>
inline Real duplication_tolerance() {
  if constexpr (std::is_same_v<Real, double> || std::is_same_v<Real, long double>) {
    return Real(0.01);
  } else {
    using std::pow;
    static const Real tol = pow(std::numeric_limits<Real>::epsilon(), Real(1) / 8) / 2;
    return tol;
  }
}

template <class Real>
inline Real quiet_nan() {
  return std::numeric_limits<Real>::quiet_NaN();
}

// R_C(1, 1 + t) for t > -1, given t and 1 + t both to full relative precision (the caller
// forms 1 + t without cancellation): atan(sqrt t)/sqrt t for t > 0, atanh(sqrt -t)/sqrt -t for
// t < 0, or the series sum_k (-t)^k / (2k + 1) when |t| is small (DLMF 19.2.19-20, x = 1).
// Near t = -1, atanh(r) = log((1 + r)/sqrt(1 + t)): 1 - r would cancel, 1 + t does not.
// All in W: for Real = double the closed forms in long double, because their double rounding
// (1 ulp of R_C) reaches the result at the domain's corners (3 ulp measured, see FAST PATH).
template <class Real, class W>
inline W rc_one_one_plus(W t, W one_plus_t) {
  using std::abs;
  using std::atan;
  using std::atanh;
  using std::log;
  using std::sqrt;
  // Ten terms: the first neglected, t^10/21, is below 2^-64 for |t| <= 0.01; higher
  // precisions use the closed forms unless t is tiny. e_k shrinks by 64 per duplication step, so
  // after the first step on the series it is below 2e-4, where five terms suffice
  // (t^5/11 < 2^-64): the short form is the common case.
  const W small = std::is_same_v<Real, double> ? W(0.01) : W(1e-6);
  if (std::is_same_v<Real, double> && abs(t) < W(2e-4))
    return 1 - t * (W(1) / 3 - t * (W(1) / 5 - t * (W(1) / 7 - t * (W(1) / 9))));
  if (abs(t) < small) {
    W sum = W(1) / 19;
    for (int k = 8; k >= 0; --k)
      sum = W(1) / (2 * k + 1) - t * sum;
    return sum;
  }
  if (t > 0) {
    const W r = sqrt(t);
    return atan(r) / r;
  }
  const W r = sqrt(-t);
  if (r < W(0.5)) return atanh(r) / r;
  return log((1 + r) / sqrt(one_plus_t)) / r;
}

// Degree-7 tail of R_F, DLMF 19.36.1, without its leading 1: R_F = A^-1/2 (1 + tail), where
// E2 = XY - Z^2, E3 = XYZ of the relative deviations X_j = (A - x_j)/A (X + Y + Z = 0).
// Divisions by constants are written as products with folded reciprocals (a division costs
// several multiplications, and the tail only needs a few correct digits).
template <class W>
inline W rf_series_tail(W E2, W E3) {
  return E2 * (W(-1) / 10 + E2 * (W(1) / 24 - W(5) / 208 * E2)) +
         E3 * (W(1) / 14 + E2 * (W(-3) / 44 + W(1) / 16 * E2) + W(3) / 104 * E3);
}

// R_J's tail, DLMF 19.36.2 through degree 5 plus Carlson's degree-6 and -7 terms (the 50-digit
// test against the tables would see a wrong coefficient: their size there is tol^6 ~ 1e-38),
// without the leading 1: R_J = A^-3/2 (1 + tail) for the deviations X, Y, Z of x, y, z and
// P = -(X + Y + Z)/2 of p (A = (x + y + z + 2p)/5).
template <class W>
inline W rj_series_tail(W X, W Y, W Z) {
  const W P = -(X + Y + Z) / 2;
  const W XYZ = X * Y * Z;
  const W P2 = P * P;
  const W E2 = X * Y + X * Z + Y * Z - 3 * P2;
  const W E3 = XYZ + 2 * E2 * P + 4 * P * P2;
  const W E4 = (2 * XYZ + E2 * P + 3 * P * P2) * P;
  const W E5 = XYZ * P2;
  return E2 * (W(-3) / 14 + E2 * (W(9) / 88 - W(1) / 16 * E2)) +
         E3 * (W(1) / 6 + E2 * (W(-9) / 52 + W(45) / 272 * E2) + W(3) / 40 * E3 - W(9) / 68 * E4) +
         E4 * (W(-3) / 22 + W(3) / 20 * E2) + E5 * (W(3) / 26 - W(9) / 68 * E2);
}

// R_F from the duplicated arguments (A and two of the x_j).
template <class W>
inline W rf_series(W A, W x, W y) {
  using std::sqrt;
  // A_k - x_k = 4^-k (A0 - x0): DLMF's X_k, formed from the final values.
  const W inv_A = 1 / A;
  const W X = (A - x) * inv_A, Y = (A - y) * inv_A, Z = -(X + Y);
  // The tail (|tail| < tol^2) is summed on its own and applied as r + r * tail: adding each
  // term to 1 in turn would round at ulp(1) every time (up to ~3 ulp in double), and forming
  // 1 + tail before the division rounds once more.
  const W tail = rf_series_tail(X * Y - Z * Z, X * Y * Z);
  const W r = sqrt(inv_A);
  return r + r * tail;
}

// R_F by duplication (DLMF 19.36.1), arguments valid (>= 0, at most one zero). sx0, sz0 are
// sqrt(x), sqrt(z) for the first step: the Legendre forms know them (cos phi and 1), which
// saves two of the square roots that dominate the cost.
template <class Real, class W>
inline W rf_loop(W x, W y, W z, W sx0, W sz0) {
  using std::abs;
  using std::max;
  using std::sqrt;
  W A = (x + y + z) * (W(1) / 3);
  // q = max|A0 - x_j| / tol, divided by 4 per step: stop when q <= A (then |X_j| <= tol).
  W q = max(abs(A - x), max(abs(A - y), abs(A - z))) * (1 / duplication_tolerance<W>());
  for (bool first = true; q > A; first = false) {
    const W sx = first ? sx0 : W(sqrt(x)), sy = sqrt(y), sz = first ? sz0 : W(sqrt(z));
    const W lambda = sx * (sy + sz) + sy * sz;
    x = (x + lambda) / 4;
    y = (y + lambda) / 4;
    z = (z + lambda) / 4;
    A = (A + lambda) / 4;
    q /= 4;
  }
  return rf_series(A, x, y);
}

template <class Real, class W>
inline W rf_loop(W x, W y, W z) {
  using std::sqrt;
  return rf_loop<Real>(x, y, z, W(sqrt(x)), W(sqrt(z)));
}

// R_F(x, y, z) and R_J(x, y, z, p) with the same x, y, z in one duplication loop (4 square
// roots per step instead of 3 + 4). DLMF 19.36.1 (R_F) and 19.36.2 (R_J, d_k / e_k form).
// Requires x, y, z >= 0 with at most one zero, and p > 0. sx0, sz0: sqrt(x), sqrt(z), as in
// rf_loop.
template <class Real, class W>
inline void rf_rj_loop(W x, W y, W z, W p, W sx0, W sz0, W& rf, W& rj) {
  using std::abs;
  using std::max;
  using std::sqrt;
  W AF = (x + y + z) * (W(1) / 3);
  W AJ = (x + y + z + 2 * p) * (W(1) / 5);
  const W delta = (p - x) * (p - y) * (p - z);
  const W inv_tol = 1 / duplication_tolerance<W>();
  W qF = max(abs(AF - x), max(abs(AF - y), abs(AF - z))) * inv_tol;
  W qJ = max(max(abs(AJ - x), abs(AJ - y)), max(abs(AJ - z), abs(AJ - p))) * inv_tol;
  W scale = 1;   // 4^-k
  W scale3 = 1;  // 4^-3k
  W sum = 0;     // sum_k 4^-k R_C(1, 1 + e_k) / d_k
  for (bool first = true; qF > AF || qJ > AJ; first = false) {
    const W sx = first ? sx0 : W(sqrt(x)), sy = sqrt(y), sz = first ? sz0 : W(sqrt(z)),
            sp = sqrt(p);
    const W lambda = sx * (sy + sz) + sy * sz;
    const W d = (sp + sx) * (sp + sy) * (sp + sz);
    const W inv_d = 1 / d;
    // e_k = 4^-3k delta / d_k^2 (DLMF 19.36.2). With d'_k = prod (sqrt p - sqrt x_j), e_k = d'/d
    // and d + d' = 2 sqrt(p) (p + lambda), so 1 + e_k = 2 sqrt(p) (p + lambda) / d_k exactly:
    // a sum of positive terms, accurate even where e_k -> -1 (p much smaller than x, y or z).
    const W e = scale3 * delta * inv_d * inv_d;
    const W one_plus_e = 2 * sp * (p + lambda) * inv_d;
    sum += scale * rc_one_one_plus<Real>(e, one_plus_e) * inv_d;
    x = (x + lambda) / 4;
    y = (y + lambda) / 4;
    z = (z + lambda) / 4;
    p = (p + lambda) / 4;
    AF = (AF + lambda) / 4;
    AJ = (AJ + lambda) / 4;
    qF /= 4;
    qJ /= 4;
    scale /= 4;
    scale3 /= 64;
  }
  rf = rf_series(AF, x, y);
  const W inv_AJ = 1 / AJ;
  const W X = (AJ - x) * inv_AJ, Y = (AJ - y) * inv_AJ, Z = (AJ - z) * inv_AJ;
  // Summed apart from the leading 1 and applied as r + r * tail, as in rf_series.
  const W tail = rj_series_tail(X, Y, Z);
  const W r = scale * inv_AJ * sqrt(inv_AJ);
  rj = (r + r * tail) + 6 * sum;
}

template <class Real, class W>
inline void rf_rj_loop(W x, W y, W z, W p, W& rf, W& rj) {
  using std::sqrt;
  rf_rj_loop<Real>(x, y, z, p, W(sqrt(x)), W(sqrt(z)), rf, rj);
}

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Carlson's symmetric integrals (DLMF 19.16.1-2, 19.2.17). Arguments must be >= 0 (p > 0) with at
// most one of x, y, z zero; otherwise the result is NaN (negative or NaN input) or +inf (two
// zeros).

// R_C(x, y) = (1/2) int_0^inf dt / (sqrt(t + x) (t + y)), x >= 0, y > 0 (DLMF 19.2.17).
template <class Real>
inline Real carlson_rc(Real x, Real y) {
  using std::atan;
  using std::atanh;
  using std::log;
  using std::sqrt;
  if (!(x >= 0) || !(y > 0)) return detail::quiet_nan<Real>();
  if (x == y) return 1 / sqrt(x);
  if (x < y) {
    const Real d = y - x;
    return atan(sqrt(d / x)) / sqrt(d);  // x = 0 gives atan(inf) = pi/2
  }
  const Real d = x - y;
  const Real r = sqrt(d / x);
  if (r < Real(0.5)) return atanh(r) / r / sqrt(x);
  // atanh(r) with 1 - r^2 = y/x: log((sqrt x + sqrt(x - y))/sqrt y), no 1 - r cancellation.
  return log((sqrt(x) + sqrt(d)) / sqrt(y)) / sqrt(d);
}

// R_F(x, y, z) = (1/2) int_0^inf dt / sqrt((t+x)(t+y)(t+z)), DLMF 19.36.1.
template <class Real>
inline Real carlson_rf(Real x, Real y, Real z) {
  using W = detail::work_t<Real>;
  if (!(x >= 0 && y >= 0 && z >= 0)) return detail::quiet_nan<Real>();
  if ((x == 0) + (y == 0) + (z == 0) >= 2) return std::numeric_limits<Real>::infinity();
  return static_cast<Real>(detail::rf_loop<Real>(W(x), W(y), W(z)));
}

// R_J(x, y, z, p) = (3/2) int_0^inf dt / ((t + p) sqrt((t+x)(t+y)(t+z))), p > 0, DLMF 19.36.2.
template <class Real>
inline Real carlson_rj(Real x, Real y, Real z, Real p) {
  using W = detail::work_t<Real>;
  if (!(x >= 0 && y >= 0 && z >= 0 && p > 0)) return detail::quiet_nan<Real>();
  if ((x == 0) + (y == 0) + (z == 0) >= 2) return std::numeric_limits<Real>::infinity();
  W rf, rj;
  detail::rf_rj_loop<Real>(W(x), W(y), W(z), W(p), rf, rj);
  return static_cast<Real>(rj);
}

// R_D(x, y, z) = R_J(x, y, z, z), z > 0, DLMF 19.16.5.
template <class Real>
inline Real carlson_rd(Real x, Real y, Real z) {
  return carlson_rj(x, y, z, z);
}

}  // namespace disklab::math
