#pragma once
// Carlson's symmetric elliptic integrals R_C, R_F, R_D, R_J and Legendre's incomplete integrals
// F(phi|m) and Pi(n; phi|m), templated on the real type so the same code runs in double and in
// boost::multiprecision::cpp_bin_float_50 (the reference tables are checked that way).
//
// CONVENTION (DESIGN.md section 3; parameter m, not modulus k):
//   F(phi|m)     = int_0^phi dt / sqrt(1 - m sin^2 t)
//   Pi(n; phi|m) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t))
// Boost's ellint_1(k, phi) / ellint_3(k, n, phi) take the MODULUS k = sqrt(m) (and the same n).
//
// DOMAIN (accuracy is tested here): m in [0, 1), n < 1 (including large negative n, e.g. the
// parallel map's n = -b_t^2), phi in [0, pi/2]. Inside it the functions never return NaN and
// never throw. Callers that know 1 - m or 1 - n more accurately than the subtraction would give
// (m -> 1, n -> 1) pass the complements to the overloads that accept them.
//
// OUTSIDE THE DOMAIN (defined, not tested for accuracy):
//  - phi outside [0, pi/2]: reduced with the exact identities F(-phi) = -F(phi) and
//    F(phi + k pi) = F(phi) + 2k K(m) (same for Pi with its complete integral), so any finite
//    phi gives the integral's value (rounding of the reduction by pi is not compensated);
//  - m < 0 is valid for the integrals and computed by the same formulas;
//  - m == 1 or n == 1: the integral is finite for phi < pi/2 and computed; it diverges at
//    phi = pi/2 (returns +inf there when it can, a huge finite number otherwise);
//  - m > 1, n > 1, non-finite phi, or any NaN argument: returns quiet NaN.
//
// METHODS (all from the defining integrals' Carlson forms, DLMF 19.25 and 19.36):
//  - R_F, R_D, R_J by duplication to the point where the Taylor tail (terms through degree 7)
//    is below machine epsilon, DLMF 19.36.1-2; R_J's sum uses R_C(1, 1 + e_k), evaluated by its
//    series once e_k is small (it shrinks by 64 per step);
//  - F = s R_F(c^2, Delta^2, 1), Pi = F + (n/3) s^3 R_J(c^2, Delta^2, 1, 1 - n s^2), with
//    s = sin phi, c = cos phi, Delta^2 = 1 - m s^2 = c^2 + (1 - m) s^2 (the second form is used
//    where it avoids cancellation), and one duplication loop shared by R_F and R_J;
//  - n < 0: the direct formula cancels (its two terms approach each other as n -> -inf), so
//    Pi is rewritten through N = (m - n)/(1 - n) in (m, 1) (A&S 17.7.15, DLMF 19.7.9 family) as
//      Pi(n) = F/(1 - n) + (-n (1-m) / (3 (1-n)^2)) s^3 R_J(c^2, Delta^2, 1, 1 - N s^2)
//              + sqrt(-n/((1-n)(m-n))) atan(sqrt(-n (m-n)/(1-n)) s c / Delta),
//    three non-negative terms: no cancellation at any n < 0.
//
// PRECISION: for Real = double the duplication loops and series run in long double (x87, 64-bit
// significand) while sin, cos, atan, log stay in double: the loops are where the rounding of
// 4-6 steps accumulates (about 4 ulp at worst in pure double), and carrying them with 11
// extra bits brings F and Pi to within 2 ulp of the correctly rounded value (measured against
// the 50-digit tables). Where long double is no wider than double the loops run in double.
// Any other Real (e.g. cpp_bin_float_50) computes everything in Real.
//
// FAST PATH (Pi in double only): on x86-64 CPUs with AVX2 and FMA (checked once at run time;
// a second copy uses AVX-512VL where present), ellint_pi<double> with m in [0, 1] and phi in
// (0, pi/2] runs a double-double version of the same loop (lib/src/math/elliptic_pi_dd_kernel.h),
// which also carries s, c, the first steps' R_C and the atan term in double-double; it stops the
// duplication at tolerance 0.03 with degree-9 tails, and for -1 <= n < 0 uses the
// untransformed Legendre form (see that file). Elsewhere,
// and for m < 0 or n = 0, the long-double path (ellint_pi_portable) runs, with s, c, R_C and
// atan in long double. Rounding any of those to double costs up to 3 ulp at the domain's
// corners (phi -> pi/2 with m, n -> 1). Both paths:
// max 1 ulp on the 50-digit table and on a 9000-sample corner sweep against 50-digit Carlson
// (RMS 0.09 / 0.08 ulp kernel, 0.24 / 0.06 portable): test_math
// --gtest_filter='EllipticReference.Pi*'. Speed: bench_elliptic, Pi/mixed/own vs own-portable.
// The three-argument ellint_pi<double> also passes the rounding errors of 1 - n and 1 - m to
// the kernel.
#include <cmath>
#include <limits>
#include <numbers>
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
// tables it leaves every F and Pi bit-identical to 0.005 (error RMS 0.456 ulp either way) and
// saves half a duplication step (~8% of Pi's time), while 0.02 already shows (max 3.3 ulp).
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

// The same tails through degree 9, for the double-double kernel (lib/src/math/elliptic_pi_dd.cpp),
// which stops its duplication at tolerance 0.03 instead of 0.01. The degree-N term of Carlson's
// expansion is (a)_N/(b)_N times the degree-N part of (1 + E2 - E3 + E4 - E5)^-1/2: 1/(2N+1)
// for R_F (a = 1/2, b = 3/2) and 3/(2N+3) for R_J (a = 3/2, b = 5/2); through degree 7 this
// reproduces the coefficients above (repeated here: written as the degree-7 tails plus the
// degree-8 and -9 terms, the kernel measured 2% slower in bench_elliptic Pi/mixed).
// EllipticReference.SeriesTailsOfDegree9 checks them against 50-digit R_F and R_J.
template <class W>
inline W rf_series_tail9(W E2, W E3) {
  const W e2 = E2 * (W(-1) / 10 + E2 * (W(1) / 24 + E2 * (W(-5) / 208 + E2 * (W(35) / 2176))));
  const W e3 = W(1) / 14 + E2 * (W(-3) / 44 + E2 * (W(1) / 16 + E2 * (W(-35) / 608)));
  const W e33 = W(3) / 104 + E2 * (W(-15) / 272) + E3 * (W(5) / 304);
  return e2 + E3 * (e3 + E3 * e33);
}

template <class W>
inline W rj_series_tail9(W X, W Y, W Z) {
  const W P = -(X + Y + Z) / 2;
  const W XYZ = X * Y * Z, P2 = P * P;
  const W E2 = X * Y + X * Z + Y * Z - 3 * P2;
  const W E3 = XYZ + 2 * E2 * P + 4 * P * P2;
  const W E4 = (2 * XYZ + E2 * P + 3 * P * P2) * P;
  const W E5 = XYZ * P2;
  const W t2 = E2 * (W(-3) / 14 + E2 * (W(9) / 88 + E2 * (W(-1) / 16 + E2 * (W(105) / 2432))));
  const W t3 = E3 * (W(1) / 6 + E2 * (W(-9) / 52 + E2 * (W(45) / 272 + E2 * (W(-5) / 32))));
  const W t4 = E4 * (W(-3) / 22 + E2 * (W(3) / 20 + E2 * (W(-45) / 304)));
  const W t5 = E5 * (W(3) / 26 + E2 * (W(-9) / 68 + E2 * (W(15) / 112)));
  const W t33 = E3 * E3 * (W(3) / 40 + E2 * (W(-45) / 304) + E3 * (W(5) / 112));
  const W t34 = E3 * (E4 * (W(-9) / 68 + E2 * (W(15) / 56)) + E5 * (W(9) / 76));
  const W t44 = E4 * (E4 * (W(9) / 152) + E5 * (W(-3) / 28));
  return ((t2 + t3) + (t4 + t5)) + ((t33 + t34) + t44);
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

// The Legendre forms' R_F(c^2, Delta^2, 1) [and R_J(.., p)]: sqrt(c^2) = |c| and sqrt(1) = 1
// for the first duplication step (|c|: a reduced phi can exceed pi/2 by a rounding).
template <class Real, class W>
inline W rf_legendre(W c, W c2, W delta2) {
  using std::abs;
  return rf_loop<Real>(c2, delta2, W(1), W(abs(c)), W(1));
}
template <class Real, class W>
inline void rf_rj_legendre(W c, W c2, W delta2, W p, W& rf, W& rj) {
  using std::abs;
  rf_rj_loop<Real>(c2, delta2, W(1), p, W(abs(c)), W(1), rf, rj);
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

// ---------------------------------------------------------------------------------------------
// Legendre forms.

namespace detail {

// Shared inputs of the Legendre forms at phi in [0, pi/2]: s, c (in Real, from Real's sin/cos),
// and c^2, Delta^2 = 1 - m s^2 in the working type.
template <class W>
struct LegendreArgs {
  W s, c, c2, delta2;
};

template <class Real, class W = work_t<Real>, bool kWideSinCos = false>
inline LegendreArgs<W> legendre_args(Real phi, Real m, Real one_minus_m) {
  using std::cos;
  using std::sin;
  LegendreArgs<W> a;
  a.s = kWideSinCos ? sin(W(phi)) : W(sin(phi));
  a.c = kWideSinCos ? cos(W(phi)) : W(cos(phi));
  a.c2 = a.c * a.c;
  // 1 - m s^2 cancels when m s^2 -> 1; c^2 + (1 - m) s^2 is then a sum of positive terms.
  a.delta2 = (m <= Real(0.5)) ? 1 - W(m) * a.s * a.s : a.c2 + W(one_minus_m) * a.s * a.s;
  return a;
}

// 1 - n s^2 (the R_J argument p), without cancellation as n -> 1.
template <class Real, class W>
inline W one_minus_n_s2(Real n, Real one_minus_n, const LegendreArgs<W>& a) {
  return (n <= Real(0.5)) ? 1 - W(n) * a.s * a.s : a.c2 + W(one_minus_n) * a.s * a.s;
}

template <class Real>
inline bool in_phi_domain(Real phi) {
  return phi >= 0 && phi <= Real(std::numbers::pi_v<double>) / 2;
}

// F at phi in [0, pi/2], m <= 1.
template <class Real>
inline Real ellint_f_core(Real phi, Real m, Real one_minus_m) {
  using W = work_t<Real>;
  const LegendreArgs<W> a = legendre_args(phi, m, one_minus_m);
  if (a.s == 0) return phi;
  return static_cast<Real>(a.s * rf_legendre<Real>(a.c, a.c2, a.delta2));
}

// The double-double kernel for Pi in double (lib/src/math/elliptic_pi_dd_kernel.h; see FAST
// PATH above), compiled twice: for AVX2 + FMA, and for AVX2 + FMA + AVX-512VL (whose reciprocal
// estimate spares a division per duplication step). The best copy the CPU runs is chosen once,
// at start-up: pi_dd_kernel() (kNone: none, the portable path only).
enum class PiKernel { kNone, kAvx2Fma, kAvx512 };
PiKernel pi_dd_kernel() noexcept;
bool pi_dd_kernel_supported(PiKernel kernel) noexcept;    // compiled in, and this CPU runs it
const char* pi_dd_kernel_name(PiKernel kernel) noexcept;  // "AVX2+FMA", ...
bool pi_dd_kernel_available() noexcept;                   // pi_dd_kernel() != kNone
// For tests and benchmarks: makes ellint_pi<double> run the given copy from now on (kNone: the
// portable path). Not thread-safe (no evaluation may run meanwhile); false, and no change,
// where the copy is not supported.
bool use_pi_dd_kernel(PiKernel kernel) noexcept;
// The copy in use, as ellint_pi<double> calls it (nullptr: none): Pi from n, phi, m in its
// domain (pi_dd_domain), with 1 - n and 1 - m formed exactly (as hi + lo pairs) where used.
using PiDdEntry = double (*)(double n, double phi, double m) noexcept;
extern PiDdEntry pi_dd_entry;
// ellint_pi_dd takes 1 - n and 1 - m as hi + lo pairs (lo = 0 when the caller's complement is
// taken as exact), phi in (0, pi/2], m in [0, 1], n <= 1, all finite, and runs the copy in use;
// the forms taking a PiKernel run the given copy (for tests and benchmarks; the last one is that
// copy's pi_dd_entry). NaN where there is none.
double ellint_pi_dd(double n, double one_minus_n, double one_minus_n_lo, double phi, double m,
                    double one_minus_m, double one_minus_m_lo) noexcept;
double ellint_pi_dd(PiKernel kernel, double n, double one_minus_n, double one_minus_n_lo,
                    double phi, double m, double one_minus_m, double one_minus_m_lo) noexcept;
double ellint_pi_dd(PiKernel kernel, double n, double phi, double m) noexcept;
// The kernel's double-double elementary functions in the given copy, exported for their
// accuracy tests (results as {hi, lo} pairs; NaN where the copy is not supported): sin and cos
// of phi in [0, pi/2], atan of x >= 0, log of x >= 1, and R_C(1, 1 + e) - 1 for
// 0.01 <= |e| < 1.
struct DoubleDouble {
  double hi, lo;
};
void pi_dd_sincos(PiKernel kernel, double phi, DoubleDouble& sin_phi,
                  DoubleDouble& cos_phi) noexcept;
DoubleDouble pi_dd_atan(PiKernel kernel, DoubleDouble x) noexcept;
DoubleDouble pi_dd_log(PiKernel kernel, DoubleDouble x) noexcept;
DoubleDouble pi_dd_rc_minus_1(PiKernel kernel, DoubleDouble e) noexcept;

// The rounding error of one_minus_x = fl(1 - x), exactly: (1 - x) - one_minus_x (Knuth's
// two-sum error of 1 + (-x)).
inline double complement_error(double x, double one_minus_x) {
  const double bb = one_minus_x - 1.0;
  return (1.0 - (one_minus_x - bb)) + (-x - bb);
}

// Whether these (already validated: phi in [0, pi/2], m <= 1, n <= 1) arguments are in the
// kernel's domain. n = 0 stays on the portable path, which answers it with F itself
// (Pi(0; phi|m) == F(phi|m) exactly). The second form also checks a caller's 1 - n.
inline bool pi_dd_domain(double n, double phi, double m) {
  return phi > 0 && m >= 0 && n != 0 && n > -std::numeric_limits<double>::infinity();
}
inline bool pi_dd_domain(double n, double one_minus_n, double phi, double m) {
  return pi_dd_domain(n, phi, m) && one_minus_n < std::numeric_limits<double>::infinity();
}

// Pi at phi in [0, pi/2], m <= 1, n <= 1, with the Carlson loops in work_t<Real> (for double:
// long double where it is wider) on every machine.
template <class Real>
inline Real ellint_pi_portable(Real n, Real one_minus_n, Real phi, Real m, Real one_minus_m) {
  using W = work_t<Real>;
  using std::atan;
  using std::sqrt;
  if (n == 0) return ellint_f_core(phi, m, one_minus_m);  // exactly F (Pi(0; phi|m) = F)
  // s and c in W: at the corners (phi -> pi/2 with m, n -> 1) Pi amplifies their rounding in
  // Real past 2 ulp (measured: 3 ulp on random samples against 50 digits).
  const LegendreArgs<W> a = legendre_args<Real, W, true>(phi, m, one_minus_m);
  if (a.s == 0) return phi;
  const W s3 = a.s * a.s * a.s;
  const Real N = (m - n) / one_minus_n;  // the transformed characteristic for n < 0
  if (n > 0 || !(N > 0)) {
    // Direct: Pi = s R_F + (n/3) s^3 R_J(c^2, Delta^2, 1, 1 - n s^2); the terms have equal
    // signs for n > 0 (the m < 0 fallback for n < 0 accepts some cancellation).
    const W p = one_minus_n_s2(n, one_minus_n, a);
    if (!(p > 0)) return std::numeric_limits<Real>::infinity();  // n == 1 at phi == pi/2
    W rf, rj;
    rf_rj_legendre<Real>(a.c, a.c2, a.delta2, p, rf, rj);
    return static_cast<Real>(a.s * rf + W(n) * (W(1) / 3) * s3 * rj);
  }
  // n < 0, N = (m - n)/(1 - n) in (0, 1): A&S 17.7.15 rearranged into three non-negative terms
  // (see the header comment). 1 - N = (1 - m)/(1 - n) and 1 - N s^2 = c^2 + (1 - N) s^2.
  const W inv_one_minus_n = 1 / W(one_minus_n);
  const W one_minus_N = W(one_minus_m) * inv_one_minus_n;
  const W pN = a.c2 + one_minus_N * a.s * a.s;
  W rf, rj;
  rf_rj_legendre<Real>(a.c, a.c2, a.delta2, pN, rf, rj);
  const W w = W(-n) * inv_one_minus_n;  // in (0, 1); kept apart so (1 - n)^2 never overflows
  const W mn = W(m) - W(n);             // > 0
  const W sw = sqrt(w), smn = sqrt(mn);
  const W term_j = w * one_minus_N * (W(1) / 3) * s3 * rj;
  const W arg = sw * smn * a.s * a.c / sqrt(a.delta2);
  const W term_atan = (sw / smn) * atan(arg);
  return static_cast<Real>(a.s * rf * inv_one_minus_n + term_j + term_atan);
}

// Pi at phi in [0, pi/2], m <= 1, n <= 1. The *_lo arguments (double only) are the rounding
// errors of the complements, when known (the three-argument ellint_pi forms them exactly).
template <class Real>
inline Real ellint_pi_core(Real n, Real one_minus_n, Real phi, Real m, Real one_minus_m,
                           Real one_minus_n_lo = 0, Real one_minus_m_lo = 0) {
  if constexpr (std::is_same_v<Real, double>) {
    if (pi_dd_entry != nullptr && pi_dd_domain(n, one_minus_n, phi, m))
      return ellint_pi_dd(n, one_minus_n, one_minus_n_lo, phi, m, one_minus_m, one_minus_m_lo);
  }
  return ellint_pi_portable(n, one_minus_n, phi, m, one_minus_m);
}

// Reduction of any finite phi to [0, pi/2]: phi = k pi + r with |r| <= pi/2, then
// I(phi) = 2k I_complete + sign(r) I(|r|) for I = F or Pi (the integrands are even and
// pi-periodic).
template <class Real, class Core, class Complete>
inline Real reduce_phi(Real phi, Core core, Complete complete) {
  using std::abs;
  using std::round;
  const Real pi = Real(std::numbers::pi_v<double>);
  if (!(abs(phi) < std::numeric_limits<Real>::infinity())) return quiet_nan<Real>();
  const Real k = round(phi / pi);
  const Real r = phi - k * pi;
  const Real part = r < 0 ? -core(-r) : core(r);
  return k == 0 ? part : 2 * k * complete() + part;
}

}  // namespace detail

// F(phi|m) with the complement 1 - m supplied by the caller (exact near m -> 1).
template <class Real>
inline Real ellint_f(Real phi, Real m, Real one_minus_m) {
  if (!(m <= 1) || !(one_minus_m >= 0)) return detail::quiet_nan<Real>();
  if (detail::in_phi_domain(phi)) return detail::ellint_f_core(phi, m, one_minus_m);
  return detail::reduce_phi(
      phi, [&](Real r) { return detail::ellint_f_core(r, m, one_minus_m); },
      [&] { return carlson_rf(Real(0), one_minus_m, Real(1)); });
}

// F(phi|m) = int_0^phi dt / sqrt(1 - m sin^2 t).
template <class Real>
inline Real ellint_f(Real phi, Real m) {
  return ellint_f(phi, m, Real(1 - m));
}

// Pi(n; phi|m) with both complements supplied (exact near n -> 1 and m -> 1).
template <class Real>
inline Real ellint_pi(Real n, Real one_minus_n, Real phi, Real m, Real one_minus_m) {
  if (!(m <= 1) || !(one_minus_m >= 0) || !(n <= 1) || !(one_minus_n >= 0))
    return detail::quiet_nan<Real>();
  if (detail::in_phi_domain(phi))
    return detail::ellint_pi_core(n, one_minus_n, phi, m, one_minus_m);
  const Real half_pi = Real(std::numbers::pi_v<double>) / 2;
  return detail::reduce_phi(
      phi, [&](Real r) { return detail::ellint_pi_core(n, one_minus_n, r, m, one_minus_m); },
      [&] { return detail::ellint_pi_core(n, one_minus_n, half_pi, m, one_minus_m); });
}

// Pi(n; phi|m) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t)).
template <class Real>
inline Real ellint_pi(Real n, Real phi, Real m) {
  if constexpr (std::is_same_v<Real, double>) {
    // The fast path takes the complements exactly (their rounding errors as lo parts, Knuth's
    // two-sum); for large |n| the rounding of 1 - n alone would be half an ulp of the result.
    if (m <= 1 && n <= 1 && detail::in_phi_domain(phi)) {
      const detail::PiDdEntry kernel = detail::pi_dd_entry;
      if (kernel != nullptr && detail::pi_dd_domain(n, phi, m)) return kernel(n, phi, m);
      return detail::ellint_pi_portable(n, 1 - n, phi, m, 1 - m);
    }
  }
  return ellint_pi(n, Real(1 - n), phi, m, Real(1 - m));
}

// ---------------------------------------------------------------------------------------------
// Difference forms that avoid cancellation, and the second kind. Domain as above (phi in
// [0, pi/2]; outside it these return NaN rather than reduce).

// D(phi|m) = int_0^phi sin^2 t / sqrt(1 - m sin^2 t) dt = (s^3/3) R_D(c^2, Delta^2, 1)
// (DLMF 19.25.13). F - E = m D without cancellation.
template <class Real>
inline Real ellint_d(Real phi, Real m, Real one_minus_m) {
  using W = detail::work_t<Real>;
  if (!(m <= 1) || !(one_minus_m >= 0) || !detail::in_phi_domain(phi))
    return detail::quiet_nan<Real>();
  const auto a = detail::legendre_args(phi, m, one_minus_m);
  if (a.s == 0) return Real(0);
  W rf, rd;
  detail::rf_rj_legendre<Real>(a.c, a.c2, a.delta2, W(1), rf, rd);
  return static_cast<Real>(a.s * a.s * a.s / 3 * rd);
}
template <class Real>
inline Real ellint_d(Real phi, Real m) {
  return ellint_d(phi, m, Real(1 - m));
}

// E(phi|m) = int_0^phi sqrt(1 - m sin^2 t) dt = F - m D (DLMF 19.25.9).
template <class Real>
inline Real ellint_e(Real phi, Real m, Real one_minus_m) {
  using W = detail::work_t<Real>;
  if (!(m <= 1) || !(one_minus_m >= 0) || !detail::in_phi_domain(phi))
    return detail::quiet_nan<Real>();
  const auto a = detail::legendre_args(phi, m, one_minus_m);
  if (a.s == 0) return Real(0);
  W rf, rd;
  detail::rf_rj_legendre<Real>(a.c, a.c2, a.delta2, W(1), rf, rd);
  return static_cast<Real>(a.s * rf - W(m) * a.s * a.s * a.s / 3 * rd);
}
template <class Real>
inline Real ellint_e(Real phi, Real m) {
  return ellint_e(phi, m, Real(1 - m));
}

// Complete integrals K(m) = R_F(0, 1 - m, 1), E(m) = K - (m/3) R_D(0, 1 - m, 1) (DLMF 19.25.1),
// taking the complement mc = 1 - m (m = 1 - mc).
template <class Real>
inline Real ellint_k_complete(Real one_minus_m) {
  return carlson_rf(Real(0), one_minus_m, Real(1));
}
template <class Real>
inline Real ellint_e_complete(Real one_minus_m) {
  using W = detail::work_t<Real>;
  if (!(one_minus_m > 0)) return one_minus_m == 0 ? Real(1) : detail::quiet_nan<Real>();
  W rf, rd;
  detail::rf_rj_loop<Real>(W(0), W(one_minus_m), W(1), W(1), rf, rd);
  return static_cast<Real>(rf - (1 - W(one_minus_m)) / 3 * rd);
}

// Pi(n; phi|m) - F(phi|m) = n int_0^phi sin^2 t / ((1 - n sin^2 t) Delta) dt
//                         = (n/3) s^3 R_J(c^2, Delta^2, 1, 1 - n s^2): one term, no cancellation.
template <class Real>
inline Real ellint_pi_minus_f(Real n, Real one_minus_n, Real phi, Real m, Real one_minus_m) {
  using W = detail::work_t<Real>;
  if (!(m <= 1) || !(one_minus_m >= 0) || !(n <= 1) || !(one_minus_n >= 0) ||
      !detail::in_phi_domain(phi))
    return detail::quiet_nan<Real>();
  const auto a = detail::legendre_args(phi, m, one_minus_m);
  if (a.s == 0 || n == 0) return Real(0);
  const W p = detail::one_minus_n_s2(n, one_minus_n, a);
  if (!(p > 0)) return std::numeric_limits<Real>::infinity();
  W rf, rj;
  detail::rf_rj_legendre<Real>(a.c, a.c2, a.delta2, p, rf, rj);
  return static_cast<Real>(W(n) / 3 * a.s * a.s * a.s * rj);
}
template <class Real>
inline Real ellint_pi_minus_f(Real n, Real phi, Real m) {
  return ellint_pi_minus_f(n, Real(1 - n), phi, m, Real(1 - m));
}

// (1 - n) Pi(n; phi|m) - F(phi|m) = -n int_0^phi cos^2 t / ((1 - n sin^2 t) Delta) dt, the
// bracket of Guillen et al. 2017 eq. (11) with n = -b_t^2. For n < 0 (and m >= 0) it is
//   ((-n) (1-m) / (3 (1-n))) s^3 R_J(c^2, Delta^2, 1, 1 - N s^2)
//     + sqrt(-n (1-n) / (m-n)) atan(sqrt(-n (m-n)/(1-n)) s c / Delta),
// two positive terms (the n < 0 form of Pi above times (1 - n), minus F). For 0 <= n < 1 it is
// (1 - n)(Pi - F) - n F, whose terms have opposite signs (relative error ~ eps (1 + n F/|result|)).
template <class Real>
inline Real ellint_one_minus_n_pi_minus_f(Real n, Real one_minus_n, Real phi, Real m,
                                          Real one_minus_m) {
  using W = detail::work_t<Real>;
  using std::atan;
  using std::sqrt;
  if (!(m <= 1) || !(one_minus_m >= 0) || !(n <= 1) || !(one_minus_n >= 0) ||
      !detail::in_phi_domain(phi))
    return detail::quiet_nan<Real>();
  const auto a = detail::legendre_args(phi, m, one_minus_m);
  if (a.s == 0 || n == 0) return Real(0);
  const W s3 = a.s * a.s * a.s;
  W rf, rj;
  if (n < 0 && m >= 0) {
    const W one_minus_N = W(one_minus_m) / W(one_minus_n);
    const W pN = a.c2 + one_minus_N * a.s * a.s;
    detail::rf_rj_legendre<Real>(a.c, a.c2, a.delta2, pN, rf, rj);
    const W w = W(-n) / W(one_minus_n);
    const W mn = W(m) - W(n);
    const W sw = sqrt(w), smn = sqrt(mn);
    const W term_j = w * W(one_minus_m) / 3 * s3 * rj;  // (-n)(1-m)/(3(1-n)) s^3 R_J
    const W arg = sw * smn * a.s * a.c / sqrt(a.delta2);
    const W term_atan =
        sqrt(W(-n)) * (sqrt(W(one_minus_n)) / smn) * W(atan(static_cast<Real>(arg)));
    return static_cast<Real>(term_j + term_atan);
  }
  const W p = detail::one_minus_n_s2(n, one_minus_n, a);
  if (!(p > 0)) return detail::quiet_nan<Real>();
  detail::rf_rj_legendre<Real>(a.c, a.c2, a.delta2, p, rf, rj);
  return static_cast<Real>(W(one_minus_n) * (W(n) / 3 * s3 * rj) - W(n) * a.s * rf);
}
template <class Real>
inline Real ellint_one_minus_n_pi_minus_f(Real n, Real phi, Real m) {
  return ellint_one_minus_n_pi_minus_f(n, Real(1 - n), phi, m, Real(1 - m));
}

}  // namespace disklab::math
