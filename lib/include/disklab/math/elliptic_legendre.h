#pragma once
// Legendre's incomplete elliptic integrals F(phi|m) and Pi(n; phi|m), with the overloads that
// take the complements 1 - m and 1 - n, and the cancellation-free forms built on them (D, E,
// Pi - F, (1 - n) Pi - F, complete K and E), templated on the real type like Carlson's forms
// (elliptic_carlson.h) they are computed from. elliptic.h includes both.
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
//  - F = s R_F(c^2, Delta^2, 1), Pi = F + (n/3) s^3 R_J(c^2, Delta^2, 1, 1 - n s^2), with
//    s = sin phi, c = cos phi, Delta^2 = 1 - m s^2 = c^2 + (1 - m) s^2 (the second form is used
//    where it avoids cancellation), and one duplication loop shared by R_F and R_J;
//  - n < 0: the direct formula cancels (its two terms approach each other as n -> -inf), so
//    Pi is rewritten through N = (m - n)/(1 - n) in (m, 1) (A&S 17.7.15, DLMF 19.7.9 family) as
//      Pi(n) = F/(1 - n) + (-n (1-m) / (3 (1-n)^2)) s^3 R_J(c^2, Delta^2, 1, 1 - N s^2)
//              + sqrt(-n/((1-n)(m-n))) atan(sqrt(-n (m-n)/(1-n)) s c / Delta),
//    three non-negative terms: no cancellation at any n < 0.
//
// PRECISION: the Carlson loops run in long double for Real = double (elliptic_carlson.h); F's
// sin, cos stay in double, Pi's portable path computes them, R_C and atan in long double too.
//
// FAST PATH (Pi in double only): on x86-64 CPUs with AVX2 and FMA (checked once at run time;
// a second copy uses AVX-512VL where present), ellint_pi<double> with m in [0, 1] and phi in
// (0, pi/2] runs a double-double version of the same loop (lib/src/math/elliptic_pi_dd_kernel.inc),
// which also carries s, c, the first steps' R_C and the atan term in double-double; it stops the
// duplication at tolerance 0.03 with degree-9 tails, and for -1 <= n < 0 uses the untransformed
// Legendre form (see that file). Elsewhere, and for m < 0 or n = 0, the long-double path
// (ellint_pi_portable) runs, with s, c, R_C and atan in long double. Rounding any of those to
// double costs up to 3 ulp at the domain's corners (phi -> pi/2 with m, n -> 1). Both paths:
// max 1 ulp on the 50-digit table and on a 9000-sample corner sweep against 50-digit Carlson
// (RMS 0.09 / 0.08 ulp kernel, 0.24 / 0.06 portable): test_math
// --gtest_filter='EllipticReference.Pi*'. Speed: bench_elliptic, Pi/mixed/own vs own-portable.
// The three-argument ellint_pi<double> also passes the rounding errors of 1 - n and 1 - m to
// the kernel. Which copy runs is chosen by lib/src/math/elliptic_pi_dd.cpp; the hooks with which
// tests and benchmarks pick a copy are in the private header lib/src/math/elliptic_pi_dd.h (not
// installed).
#include <cmath>
#include <limits>
#include <numbers>
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

// The double-double kernel for Pi in double (see FAST PATH above). The copy in use, as
// ellint_pi<double> calls it (nullptr: none, the portable path only): Pi from n, phi, m in its
// domain (pi_dd_domain), with 1 - n and 1 - m formed exactly (as hi + lo pairs) where used.
using PiDdEntry = double (*)(double n, double phi, double m) noexcept;
extern PiDdEntry pi_dd_entry;
// The same copy with 1 - n and 1 - m as hi + lo pairs (lo = 0 when the caller's complement is
// taken as exact), phi in (0, pi/2], m in [0, 1], n <= 1, all finite. NaN where there is none.
double ellint_pi_dd(double n, double one_minus_n, double one_minus_n_lo, double phi, double m,
                    double one_minus_m, double one_minus_m_lo) noexcept;

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
