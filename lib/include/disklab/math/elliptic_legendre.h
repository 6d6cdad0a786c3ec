#pragma once
// Legendre's incomplete elliptic integrals F(phi|m) and Pi(n; phi|m), with the overloads that
// take the complements 1 - m and 1 - n, the complete integrals K(m) and Pi(n|m) at exactly
// pi/2, and the cancellation-free forms built on them (D, E, Pi - F, (1 - n) Pi - F, complete
// E), templated on the real type like Carlson's forms (elliptic_carlson.h) they are computed
// from. elliptic.h includes both.
//
// CONVENTION (docs/design.md section 3; parameter m, not modulus k):
//   F(phi|m)     = int_0^phi dt / sqrt(1 - m sin^2 t)
//   Pi(n; phi|m) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t))
// Boost's ellint_1(k, phi) / ellint_3(k, n, phi) take the MODULUS k = sqrt(m) (and the same n).
//
// DOMAIN (accuracy is tested here): m in [0, 1), n < 1 (including large negative n, e.g. the
// parallel map's n = -b_t^2), phi in [0, pi/2]. Inside it the functions never return NaN and
// never throw. Callers that know 1 - m or 1 - n more accurately than the subtraction would give
// (m -> 1, n -> 1) pass the complements to the overloads that accept them.
//
// ANY FINITE phi (F and Pi; tested for accuracy too): the integrands are even and pi-periodic,
// so F(-phi) = -F(phi) and F(phi + j pi) = F(phi) + 2j K(m), and the same for Pi with Pi(n|m).
// phi is reduced modulo pi/2 in long double with pi/2 to 160 bits (detail::quadrant: exact to
// 2^-63 relative below |phi| = 2^52), and the reduced part and the complete integral are added
// before the one rounding: F stays faithfully rounded and Pi within 2 ulp at any phi
// (EllipticComplete.FAndPiAtAnyPhiWithinTwoUlpOf50Digits, and on Boost's own ellint_1 inputs, phi
// up to 1185: EllipticReference.FFaithfullyRoundedOnBothTables). Beyond |phi| = 1/eps = 2^52,
// where the period is below an ulp of phi, the result is the mean growth 2 |phi| K / pi
// (2 |phi| Pi(n|m) / pi). These are the semantics of Boost.Math's ellint_1 and ellint_3, in the
// convention m = k^2.
//
// OUTSIDE THE DOMAIN (defined, not tested for accuracy):
//  - m < 0 is valid for the integrals and computed by the same formulas;
//  - m == 1 or n == 1: the integral is finite for phi < pi/2 and computed; it diverges at
//    phi = pi/2 (returns +inf there when it can, a huge finite number otherwise);
//  - m > 1, n > 1, non-finite phi, or any NaN argument: returns quiet NaN.
//
// METHODS (all from the defining integrals' Carlson forms, DLMF 19.25 and 19.36):
//  - F = s R_F(c^2, Delta^2, 1), Pi = F + (n/3) s^3 R_J(c^2, Delta^2, 1, 1 - n s^2), with
//    s = sin phi, c = cos phi, Delta^2 = 1 - m s^2 = c^2 + (1 - m) s^2 (the second form is used
//    where it avoids cancellation), and one duplication loop shared by R_F and R_J;
//  - n < 0: the direct formula cancels (its two terms approach each other as n -> -inf), so
//    Pi is rewritten through N = (m - n)/(1 - n) in (m, 1) (A&S 17.7.15, DLMF 19.7.9 family) as
//      Pi(n) = F/(1 - n) + (-n (1-m) / (3 (1-n)^2)) s^3 R_J(c^2, Delta^2, 1, 1 - N s^2)
//              + sqrt(-n/((1-n)(m-n))) atan(sqrt(-n (m-n)/(1-n)) s c / Delta),
//    three non-negative terms: no cancellation at any n < 0.
//
// PRECISION: the Carlson loops run in long double for Real = double (elliptic_carlson.h). F's
// portable path carries s, c and the product s R_F in long double too (sincos_wide; s rounded to
// double alone costs up to 1/2 ulp), so F is faithfully rounded, below 1 ulp of the exact value
// (EllipticReference.FFaithfullyRoundedOnBothTables, on both paths). Pi's portable path computes
// s, c, R_C and atan in long double.
//
// FAST PATH (F and Pi in double only). F: on the same CPUs as Pi's kernel below, ellint_f<double>
// with m in [0, 1] and 0 < |phi| <= pi/2 runs one of three paths (lib/src/math/
// elliptic_pi_dd_kernel.inc, each with its error bound relative to F before the one rounding,
// all below 2^-54, so F is faithfully rounded): at phi <= 0.72, phi (1 + eps) with eps from
// Taylor series in phi^2 and the series in the roots of R_F's arguments, in plain double with a
// few exact pairs (0.375 * 2^-53); near pi/2, K(m) - F(psi|m) with F(psi|m) the same way and K
// from tabulated polynomials (0.44 * 2^-53); else a double-double duplication on the square roots
// of R_F's arguments, as many steps as their spread needs, with a degree-17 series in them
// (2^-57.2). phi beyond pi/2 and m < 0 take the portable path. Speed: bench_elliptic,
// F/mixed/own vs own-portable, and by path.
// Pi: on x86-64 CPUs with AVX2 and FMA (checked once at run time;
// a second copy uses AVX-512VL where present), ellint_pi<double> with m in [0, 1] and phi in
// (0, pi/2] runs a double-double version of the same loop (lib/src/math/elliptic_pi_dd_kernel.inc),
// which also carries s, c, the first steps' R_C and the atan term in double-double; it stops the
// duplication at tolerance 0.03 with degree-9 tails, and for -1 <= n < 0 uses the untransformed
// Legendre form (see that file). Elsewhere, and for m < 0 or n = 0, the long-double path
// (ellint_pi_portable) runs, with s, c, R_C and atan in long double. Rounding any of those to
// double costs up to 3 ulp at the domain's corners (phi -> pi/2 with m, n -> 1). Both paths:
// max 1 ulp on the 50-digit table and on a 9000-sample corner sweep against 50-digit Carlson
// (RMS 0.022 / 0.018 ulp kernel, 0.24 / 0.06 portable): test_math
// --gtest_filter='EllipticReference.Pi*'. Speed: bench_elliptic, Pi/mixed/own vs own-portable.
// The three-argument ellint_pi<double> also passes the rounding errors of 1 - n and 1 - m to
// the kernel. Which copy runs is chosen by lib/src/math/elliptic_pi_dd.cpp; the hooks with which
// tests and benchmarks pick a copy are in the private header lib/src/math/elliptic_pi_dd.h (not
// installed).
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <type_traits>

#include "disklab/math/elliptic_carlson.h"

namespace disklab::math {

namespace detail {

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

// Shared inputs of the Legendre forms at phi in [0, pi/2]: s, c, c^2 and Delta^2 = 1 - m s^2 in
// the working type, from s and c given in W (legendre_args_from) or from Real's sin and cos of
// phi (legendre_args: D, E and the difference forms).
template <class W>
struct LegendreArgs {
  W s, c, c2, delta2;
};

template <class Real, class W>
inline LegendreArgs<W> legendre_args_from(W s, W c, Real m, Real one_minus_m) {
  LegendreArgs<W> a;
  a.s = s;
  a.c = c;
  a.c2 = c * c;
  // 1 - m s^2 cancels when m s^2 -> 1; c^2 + (1 - m) s^2 is then a sum of positive terms.
  a.delta2 = (m <= Real(0.5)) ? 1 - W(m) * s * s : a.c2 + W(one_minus_m) * s * s;
  return a;
}

template <class Real, class W = work_t<Real>>
inline LegendreArgs<W> legendre_args(Real phi, Real m, Real one_minus_m) {
  using std::cos;
  using std::sin;
  return legendre_args_from(W(sin(phi)), W(cos(phi)), m, one_minus_m);
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

// pi/2 as p[0] + p[1] + p[2] + p[3] in the working type (Cody and Waite), for reducing phi: for
// the built-in types p[0..2] carry 32 bits each and p[3] the next 53 (pi/2 to 2^-160), so the
// products with an integer of 32 bits, or of 20 bits times 2^32, are exact in x87 long double.
// Other types carry pi/2 whole.
template <class W>
struct HalfPiParts {
  W p[4];
  W half_pi;  // p[0] + p[1], rounded: enough to choose the quadrant
};
template <class W>
inline const HalfPiParts<W>& half_pi_parts() {
  if constexpr (std::is_floating_point_v<W>) {
    static constexpr HalfPiParts<W> parts{
        {W(0x1.921fb544p+0), W(0x1.0b4611a6p-34), W(0x1.3198a2ep-69), W(0x1.b839a252049c1p-104)},
        W(0x1.921fb544p+0) + W(0x1.0b4611a6p-34)};
    return parts;
  } else {
    using std::atan;
    static const HalfPiParts<W> parts{{2 * atan(W(1)), W(0), W(0), W(0)}, 2 * atan(W(1))};
    return parts;
  }
}

// For x >= 0 below 2^52: q, the integer nearest x / (pi/2), returned, and t = x - q pi/2 with
// |t| <= pi/4 (up to a rounding). With q = q_hi + q_lo (q_hi a multiple of 2^32 below 2^52,
// q_lo < 2^32) the products with p[0..2] are exact (those with p[3], below 2^-100 x, round
// harmlessly), and each subtraction is exact where the running value is within a factor 2 of
// the term taken off (Sterbenz); where it is not, the running value is already of the size of
// t. So t keeps a relative error near 2^-63 however close x comes to a multiple of pi/2: F and
// Pi need that as sin t -> 0 at an odd multiple, where they are most sensitive for m -> 1.
template <class W>
inline W quadrant(W x, W& t) {
  using std::floor;
  using std::round;
  const HalfPiParts<W>& hp = half_pi_parts<W>();
  const W q = round(x / hp.half_pi);
  const W q_hi = floor(q * W(0x1p-32)) * W(0x1p32), q_lo = q - q_hi;
  t = x;
  for (const W& p : hp.p)
    t = (t - q_hi * p) - q_lo * p;
  return q;
}

// sin and cos of t, |t| <= pi/4 (up to a rounding), in the working type. For x87 long double
// (Real = double) by their Taylor series (A&S 4.3.65-66): through t^19 and t^18 the first
// omitted terms are below 2^-71 and 2^-68 relative, and with the rounding of about a dozen
// long-double steps the error stays below 2^-60, 1/128 of a double's ulp
// (EllipticReference.WideSinCosWithin2em60Of50Digits). libm's sinl and cosl are as accurate but
// several times slower; sin and cos in double cost F up to 1/2 ulp, and so its faithful
// rounding. Other working types take their own sin and cos.
template <class W>
inline void sincos_quarter(W t, W& s, W& c) {
  if constexpr (std::is_same_v<W, long double> && std::numeric_limits<W>::digits == 64) {
    const W u = t * t;
    // sin t = t + t u S(u), S = sum_{k=1..9} (-1)^k u^(k-1) / (2k+1)!;
    // cos t = 1 - u/2 + u^2 C(u), C = sum_{k=2..9} (-1)^k u^(k-2) / (2k)!. Horner in u.
    constexpr W kS[] = {W(-1) / 6,
                        W(1) / 120,
                        W(-1) / 5040,
                        W(1) / 362880,
                        W(-1) / 39916800,
                        W(1) / 6227020800,
                        W(-1) / 1307674368000,
                        W(1) / 355687428096000,
                        W(-1) / 121645100408832000};
    constexpr W kC[] = {
        W(1) / 24,        W(-1) / 720,         W(1) / 40320,          W(-1) / 3628800,
        W(1) / 479001600, W(-1) / 87178291200, W(1) / 20922789888000, W(-1) / 6402373705728000};
    // Their terms from u^2 on are below 5.2e-5 of sin t and 5.1e-6 of cos t at |t| = pi/4: in
    // double (SSE, beside the x87 steps) their few roundings of 2^-53 cost below 2^-65 relative.
    const double ud = static_cast<double>(u);
    double Sd = static_cast<double>(kS[8]), Cd = static_cast<double>(kC[7]);
    for (int k = 7; k >= 2; --k)
      Sd = static_cast<double>(kS[k]) + ud * Sd;
    for (int k = 6; k >= 2; --k)
      Cd = static_cast<double>(kC[k]) + ud * Cd;
    const W S = kS[0] + u * (kS[1] + u * W(Sd)), C = kC[0] + u * (kC[1] + u * W(Cd));
    s = t + t * u * S;
    c = (1 - u / 2) + u * u * C;
  } else {
    using std::cos;
    using std::sin;
    s = sin(t);
    c = cos(t);
  }
}

// sin and cos of phi in [0, pi/2]. For x87 long double: phi > pi/4 becomes t = phi - pi/2,
// subtracting the parts of pi/2 in turn (the first exactly, by Sterbenz: t keeps a relative
// accuracy near 2^-63, and cos phi = -sin t with it as phi -> pi/2), then sincos_quarter. Other
// working types take their own sin and cos.
template <class W>
inline void sincos_wide(W phi, W& s, W& c) {
  if constexpr (std::is_same_v<W, long double> && std::numeric_limits<W>::digits == 64) {
    const bool reflect = phi > W(0x1.921fb54442d18p-1);  // fl(pi/4)
    W t = phi;
    if (reflect)
      for (const W& p : half_pi_parts<W>().p)
        t -= p;
    W st, ct;
    sincos_quarter(t, st, ct);
    s = reflect ? ct : st;
    c = reflect ? -st : ct;
  } else {
    using std::cos;
    using std::sin;
    s = sin(phi);
    c = cos(phi);
  }
}

// F from s = sin phi, c = cos phi (both >= 0) in the working type: s R_F(c^2, Delta^2, 1), with
// the duplication loop and the product in W, rounded once by the caller.
template <class Real, class W>
inline W ellint_f_sc(W s, W c, Real m, Real one_minus_m) {
  if (s == 0) return W(0);
  const LegendreArgs<W> a = legendre_args_from(s, c, m, one_minus_m);
  return a.s * rf_legendre<Real>(a.c, a.c2, a.delta2);
}

// F at phi in [0, pi/2], m <= 1, in the working type (s and c from sincos_wide).
template <class Real, class W = work_t<Real>>
inline W ellint_f_wide(W phi, Real m, Real one_minus_m) {
  W s, c;
  sincos_wide(phi, s, c);
  if (s == 0) return phi;
  return ellint_f_sc<Real>(s, c, m, one_minus_m);
}

// F at phi in [0, pi/2], m <= 1, on the portable path (x87 long double where it exists).
template <class Real>
inline Real ellint_f_core(Real phi, Real m, Real one_minus_m) {
  using W = work_t<Real>;
  return static_cast<Real>(ellint_f_wide<Real>(W(phi), m, one_minus_m));
}

// K(m) = R_F(0, 1 - m, 1) (DLMF 19.25.1) in the working type, m <= 1; +inf at m = 1.
template <class Real, class W = work_t<Real>>
inline W ellint_k_wide(Real one_minus_m) {
  if (!(one_minus_m > 0)) return std::numeric_limits<W>::infinity();
  return rf_loop<Real>(W(0), W(one_minus_m), W(1));
}

// The double-double kernel for Pi in double (see FAST PATH above). The copy in use, as
// ellint_pi<double> calls it (nullptr: none, the portable path only): Pi from n, phi, m in its
// domain (pi_dd_domain), with 1 - n and 1 - m formed exactly (as hi + lo pairs) where used.
using PiDdEntry = double (*)(double n, double phi, double m) noexcept;
extern PiDdEntry pi_dd_entry;
// The same copy with 1 - n and 1 - m as hi + lo pairs (lo = 0 when the caller's complement is
// taken as exact), phi in (0, pi/2], m in [0, 1], n <= 1, all finite. NaN where there is none.
double ellint_pi_dd(double n, double one_minus_n, double one_minus_n_lo, double phi, double m,
                    double one_minus_m, double one_minus_m_lo) noexcept;

// The double-double kernel for F in double (see FAST PATH above), the same copy as Pi's: F from
// phi in (0, pi/2] and m in [0, 1] with 1 - m formed exactly (f_dd_entry; nullptr: none), or with
// the caller's 1 - m taken as exact (ellint_f_dd, NaN where there is no kernel).
using FDdEntry = double (*)(double phi, double m) noexcept;
extern FDdEntry f_dd_entry;
double ellint_f_dd(double phi, double m, double one_minus_m) noexcept;

// F in double at phi in [0, pi/2] or [-pi/2, 0) (odd), m <= 1: the kernel where it runs (m in
// [0, 1]; the caller's complement only where m > 0.5, as on the portable path, which forms
// Delta^2 from m below that), else the portable path.
inline double ellint_f_double(double phi, double m, double one_minus_m, bool exact_complement) {
  const double a = phi < 0 ? -phi : phi;
  double value;
  if (f_dd_entry != nullptr && m >= 0 && a > 0)
    value = (exact_complement || m <= 0.5) ? f_dd_entry(a, m) : ellint_f_dd(a, m, one_minus_m);
  else
    value = ellint_f_core(a, m, one_minus_m);
  return phi < 0 ? -value : value;
}

// Whether these (already validated: phi in [0, pi/2], m <= 1, n <= 1) arguments are in the
// kernel's domain. n = 0 stays on the portable path, which answers it with F itself
// (Pi(0; phi|m) == F(phi|m) exactly). n below -2^1000 also does: the kernel's double-double
// intermediates (m - n and its products, with their error terms) overflow within a few ulps of
// -DBL_MAX (NaN at n = -1.7976931348623151e308), while the portable path's long
// double has the exponent range. The second form also checks a caller's 1 - n.
inline bool pi_dd_domain(double n, double phi, double m) {
  return phi > 0 && m >= 0 && n != 0 && n > -0x1p1000;
}
inline bool pi_dd_domain(double n, double one_minus_n, double phi, double m) {
  return pi_dd_domain(n, phi, m) && one_minus_n < std::numeric_limits<double>::infinity();
}

// The portable path: Pi at phi in [0, pi/2], m <= 1, n <= 1, with the Carlson loops in
// work_t<Real> (for double: long double where it is wider) on every machine. This form takes
// s = sin phi, c = cos phi (both >= 0) in W and returns the value in W (the reduction of phi
// adds to it). n = 0 is F itself (Pi(0; phi|m) = F).
template <class Real, class W>
inline W ellint_pi_portable_sc(Real n, Real one_minus_n, W s, W c, Real m, Real one_minus_m) {
  using std::atan;
  using std::sqrt;
  if (n == 0) return ellint_f_sc<Real>(s, c, m, one_minus_m);
  const LegendreArgs<W> a = legendre_args_from(s, c, m, one_minus_m);
  const W s3 = a.s * a.s * a.s;
  const Real N = (m - n) / one_minus_n;  // the transformed characteristic for n < 0
  if (n > 0 || !(N > 0)) {
    // Direct: Pi = s R_F + (n/3) s^3 R_J(c^2, Delta^2, 1, 1 - n s^2); the terms have equal
    // signs for n > 0 (the m < 0 fallback for n < 0 accepts some cancellation).
    const W p = one_minus_n_s2(n, one_minus_n, a);
    if (!(p > 0)) return std::numeric_limits<W>::infinity();  // n == 1 at phi == pi/2
    W rf, rj;
    rf_rj_legendre<Real>(a.c, a.c2, a.delta2, p, rf, rj);
    return a.s * rf + W(n) * (W(1) / 3) * s3 * rj;
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
  return a.s * rf * inv_one_minus_n + term_j + term_atan;
}

// The same at phi in [0, pi/2] in W. s and c in W (libm's sinl, cosl for long double): at the
// corners (phi -> pi/2 with m, n -> 1) Pi amplifies their rounding in Real past 2 ulp (measured: 3
// ulp on random samples against 50 digits).
template <class Real, class W = work_t<Real>>
inline W ellint_pi_portable_wide(Real n, Real one_minus_n, W phi, Real m, Real one_minus_m) {
  using std::cos;
  using std::sin;
  if (n == 0) return ellint_f_wide<Real>(phi, m, one_minus_m);  // exactly F (Pi(0; phi|m) = F)
  const W s = sin(phi);
  if (s == 0) return phi;
  return ellint_pi_portable_sc<Real>(n, one_minus_n, s, W(cos(phi)), m, one_minus_m);
}

template <class Real>
inline Real ellint_pi_portable(Real n, Real one_minus_n, Real phi, Real m, Real one_minus_m) {
  using W = work_t<Real>;
  return static_cast<Real>(ellint_pi_portable_wide<Real>(n, one_minus_n, W(phi), m, one_minus_m));
}

// Pi(n|m) = Pi(n; pi/2|m) in the working type, m <= 1, n <= 1, from Carlson's complete forms
// (DLMF 19.25.2): K + (n/3) R_J(0, 1 - m, 1, 1 - n) for n > 0; for n < 0 the same
// transformation as the incomplete Pi, whose atan term vanishes at phi = pi/2 (c = 0):
// K/(1 - n) + (-n (1-m) / (3 (1-n)^2)) R_J(0, 1 - m, 1, 1 - N), two positive terms. +inf where
// the integral diverges (m = 1 or n = 1).
template <class Real, class W = work_t<Real>>
inline W ellint_pi_complete_wide(Real n, Real one_minus_n, Real m, Real one_minus_m) {
  if (!(one_minus_m > 0) || !(one_minus_n > 0)) return std::numeric_limits<W>::infinity();
  if (n == 0) return ellint_k_wide<Real>(one_minus_m);
  W rf, rj;
  const Real N = (m - n) / one_minus_n;
  if (n > 0 || !(N > 0)) {
    rf_rj_loop<Real>(W(0), W(one_minus_m), W(1), W(one_minus_n), rf, rj);
    return rf + W(n) * (W(1) / 3) * rj;
  }
  const W inv_one_minus_n = 1 / W(one_minus_n);
  const W one_minus_N = W(one_minus_m) * inv_one_minus_n;
  rf_rj_loop<Real>(W(0), W(one_minus_m), W(1), one_minus_N, rf, rj);
  const W w = W(-n) * inv_one_minus_n;
  return rf * inv_one_minus_n + w * one_minus_N * (W(1) / 3) * rj;
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

// I(phi) for any finite phi, I = F or Pi, from core(s, c) = I at the angle with sine s >= 0 and
// cosine c >= 0, and complete() = I(pi/2), both in the working type. The integrands are even and
// pi-periodic, so I is odd and I(j pi + r) = 2j I(pi/2) + I(r). With phi = q pi/2 + t,
// |t| <= pi/4 (quadrant):
//   q even: I = q I(pi/2) + sign(t) I(|t|);
//   q odd:  I = (q + 1) I(pi/2) - I(pi/2 - t) for t >= 0, (q - 1) I(pi/2) + I(pi/2 + t) for t < 0,
// with the sine and cosine of pi/2 -+ t read off those of t (no cancellation: the first form is
// at least I(pi/2)). As Boost.Math does, beyond |phi| = 1/eps (where an ulp of phi exceeds 1/2
// and phi carries no information about its position in the period) the result is the mean
// growth 2 |phi| I(pi/2) / pi, within 1/(4j) relative of I at any phi that ulp covers. NaN for
// non-finite phi; one rounding to Real at the end.
template <class Real, class Core, class Complete>
inline Real reduce_phi(Real phi, Core core, Complete complete) {
  using W = work_t<Real>;
  using std::abs;
  using std::fmod;
  const Real a = abs(phi);
  if (!(a < std::numeric_limits<Real>::infinity())) return quiet_nan<Real>();
  const W x = W(a);
  W value;
  if (a > 1 / std::numeric_limits<Real>::epsilon()) {
    value = x * complete() / half_pi_parts<W>().half_pi;
  } else {
    W t, s, c;
    const W q = quadrant(x, t);
    sincos_quarter(t, s, c);
    if (fmod(q, W(2)) == 0) {
      const W part = t < 0 ? W(-core(W(-s), c)) : W(core(s, c));
      value = q == 0 ? part : q * complete() + part;
    } else if (t >= 0) {
      value = (q + 1) * complete() - core(c, s);
    } else {
      const W part = core(c, W(-s));
      value = q == 1 ? part : (q - 1) * complete() + part;
    }
  }
  return phi < 0 ? -static_cast<Real>(value) : static_cast<Real>(value);
}

}  // namespace detail

// F(phi|m) with the complement 1 - m supplied by the caller (exact near m -> 1).
template <class Real>
inline Real ellint_f(Real phi, Real m, Real one_minus_m) {
  using W = detail::work_t<Real>;
  if (!(m <= 1) || !(one_minus_m >= 0)) return detail::quiet_nan<Real>();
  if constexpr (std::is_same_v<Real, double>) {
    if (detail::in_phi_domain(phi) || detail::in_phi_domain(-phi))
      return detail::ellint_f_double(phi, m, one_minus_m, false);
  }
  if (detail::in_phi_domain(phi)) return detail::ellint_f_core(phi, m, one_minus_m);
  if (detail::in_phi_domain(-phi)) return -detail::ellint_f_core(-phi, m, one_minus_m);  // odd
  return detail::reduce_phi(
      phi, [&](W s, W c) { return detail::ellint_f_sc<Real>(s, c, m, one_minus_m); },
      [&] { return detail::ellint_k_wide<Real>(one_minus_m); });
}

// F(phi|m) = int_0^phi dt / sqrt(1 - m sin^2 t).
template <class Real>
inline Real ellint_f(Real phi, Real m) {
  if constexpr (std::is_same_v<Real, double>) {
    // The kernel's domain in one test (NaN fails it); it forms 1 - m exactly itself, and F is odd.
    const double a = std::fabs(phi);
    const detail::FDdEntry kernel = detail::f_dd_entry;
    if (kernel != nullptr && a > 0 && a <= std::numbers::pi / 2 && m >= 0 && m <= 1)
      return std::copysign(kernel(a, m), phi);
    if (m <= 1 && (detail::in_phi_domain(phi) || detail::in_phi_domain(-phi)))
      return detail::ellint_f_double(phi, m, 1 - m, true);
  }
  return ellint_f(phi, m, Real(1 - m));
}

// Pi(n; phi|m) with both complements supplied (exact near n -> 1 and m -> 1).
template <class Real>
inline Real ellint_pi(Real n, Real one_minus_n, Real phi, Real m, Real one_minus_m) {
  if (!(m <= 1) || !(one_minus_m >= 0) || !(n <= 1) || !(one_minus_n >= 0))
    return detail::quiet_nan<Real>();
  using W = detail::work_t<Real>;
  if constexpr (std::is_same_v<Real, double>) {
    // Pi(0; phi|m) is F(phi|m), computed by F's own path (which may be F's kernel).
    if (n == 0 && (detail::in_phi_domain(phi) || detail::in_phi_domain(-phi)))
      return ellint_f(phi, m, one_minus_m);
  }
  if (detail::in_phi_domain(phi))
    return detail::ellint_pi_core(n, one_minus_n, phi, m, one_minus_m);
  if (detail::in_phi_domain(-phi))  // odd
    return -detail::ellint_pi_core(n, one_minus_n, -phi, m, one_minus_m);
  // Beyond [0, pi/2] the reduced part and the complete integral stay in W (the portable path's
  // loops), so the sum is rounded once.
  return detail::reduce_phi(
      phi,
      [&](W s, W c) {
        return detail::ellint_pi_portable_sc<Real>(n, one_minus_n, s, c, m, one_minus_m);
      },
      [&] { return detail::ellint_pi_complete_wide<Real>(n, one_minus_n, m, one_minus_m); });
}

// Pi(n; phi|m) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t)).
template <class Real>
inline Real ellint_pi(Real n, Real phi, Real m) {
  if constexpr (std::is_same_v<Real, double>) {
    // The fast path takes the complements exactly (their rounding errors as lo parts, Knuth's
    // two-sum); for large |n| the rounding of 1 - n alone would be half an ulp of the result.
    if (n == 0 && m <= 1 && (detail::in_phi_domain(phi) || detail::in_phi_domain(-phi)))
      return ellint_f(phi, m);  // Pi(0; phi|m) = F(phi|m), by F's own path
    if (m <= 1 && n <= 1 && detail::in_phi_domain(phi)) {
      const detail::PiDdEntry kernel = detail::pi_dd_entry;
      if (kernel != nullptr && detail::pi_dd_domain(n, phi, m)) return kernel(n, phi, m);
      return detail::ellint_pi_portable(n, 1 - n, phi, m, 1 - m);
    }
    if (m <= 1 && n <= 1 && detail::in_phi_domain(-phi)) return -ellint_pi(n, -phi, m);  // odd
  }
  return ellint_pi(n, Real(1 - n), phi, m, Real(1 - m));
}

// ---------------------------------------------------------------------------------------------
// Complete integrals at exactly phi = pi/2, not at fl(pi/2) = pi/2 - 6.1e-17: the integrals
// differ by about 6.1e-17 / ((1 - n) sqrt(1 - m)), which near n, m -> 1 is many ulps (millions
// at n = 1 - 2^-53: EllipticComplete.KAndPiWithinTwoUlpOf50DigitBoost prints it).

// K(m) = F(pi/2|m) = R_F(0, 1 - m, 1) (DLMF 19.25.1), with the complement 1 - m supplied.
// m <= 1 (m < 0 included); +inf at m = 1; NaN outside.
template <class Real>
inline Real ellint_k(Real m, Real one_minus_m) {
  if (!(m <= 1) || !(one_minus_m >= 0)) return detail::quiet_nan<Real>();
  return static_cast<Real>(detail::ellint_k_wide<Real>(one_minus_m));
}
template <class Real>
inline Real ellint_k(Real m) {
  return ellint_k(m, Real(1 - m));
}

// Pi(n|m) = Pi(n; pi/2|m) = R_F(0, 1 - m, 1) + (n/3) R_J(0, 1 - m, 1, 1 - n) (DLMF 19.25.2),
// with both complements supplied (exact near n, m -> 1); for n < 0 computed without
// cancellation (detail::ellint_pi_complete_wide). m <= 1, n <= 1; +inf at m = 1 or n = 1; NaN
// outside.
template <class Real>
inline Real ellint_pi_complete(Real n, Real one_minus_n, Real m, Real one_minus_m) {
  if (!(m <= 1) || !(one_minus_m >= 0) || !(n <= 1) || !(one_minus_n >= 0))
    return detail::quiet_nan<Real>();
  return static_cast<Real>(detail::ellint_pi_complete_wide<Real>(n, one_minus_n, m, one_minus_m));
}
template <class Real>
inline Real ellint_pi_complete(Real n, Real m) {
  return ellint_pi_complete(n, Real(1 - n), m, Real(1 - m));
}

// ---------------------------------------------------------------------------------------------
// Difference forms that avoid cancellation, and the second kind. Domain as above (phi in
// [0, pi/2]; outside it these return NaN rather than reduce).

// D(phi|m) = int_0^phi sin^2 t / sqrt(1 - m sin^2 t) dt = (s^3/3) R_D(c^2, Delta^2, 1)
// (DLMF 19.25.13). F - E = m D without cancellation.
namespace detail {
// sin(phi), R_F and R_D of the Legendre arguments, shared by D and E; nullopt outside the domain.
template <class Real>
struct SinRfRd {
  work_t<Real> s, rf, rd;
};
template <class Real>
inline std::optional<SinRfRd<Real>> legendre_rf_rd(Real phi, Real m, Real one_minus_m) {
  using W = work_t<Real>;
  if (!(m <= 1) || !(one_minus_m >= 0) || !in_phi_domain(phi)) return std::nullopt;
  const auto a = legendre_args(phi, m, one_minus_m);
  if (a.s == 0) return SinRfRd<Real>{W(0), W(0), W(0)};
  W rf, rd;
  rf_rj_legendre<Real>(a.c, a.c2, a.delta2, W(1), rf, rd);
  return SinRfRd<Real>{a.s, rf, rd};
}
}  // namespace detail

template <class Real>
inline Real ellint_d(Real phi, Real m, Real one_minus_m) {
  const auto t = detail::legendre_rf_rd(phi, m, one_minus_m);
  if (!t) return detail::quiet_nan<Real>();
  if (t->s == 0) return Real(0);
  return static_cast<Real>(t->s * t->s * t->s / 3 * t->rd);
}
template <class Real>
inline Real ellint_d(Real phi, Real m) {
  return ellint_d(phi, m, Real(1 - m));
}

// E(phi|m) = int_0^phi sqrt(1 - m sin^2 t) dt = F - m D (DLMF 19.25.9).
template <class Real>
inline Real ellint_e(Real phi, Real m, Real one_minus_m) {
  const auto t = detail::legendre_rf_rd(phi, m, one_minus_m);
  if (!t) return detail::quiet_nan<Real>();
  if (t->s == 0) return Real(0);
  using W = detail::work_t<Real>;
  return static_cast<Real>(t->s * t->rf - W(m) * t->s * t->s * t->s / 3 * t->rd);
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
