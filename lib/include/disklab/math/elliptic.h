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
#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>

namespace disklab::math {

namespace detail {

// Duplication stops when every |X_j| (the arguments' relative spread) is below this, so the
// neglected degree-8 tail, a few times |X|^8 / 10, is below half an ulp. eps^(1/8)/2 is that
// bound with a factor-2 margin for the tail's constant.
template <class Real>
inline Real duplication_tolerance() {
  if constexpr (std::is_same_v<Real, double>) {
    return 0.0055;  // (2^-52)^(1/8) / 2 = 0.01105 / 2
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

// R_C(1, 1 + t) for t > -1: atan(sqrt t)/sqrt t, atanh(sqrt -t)/sqrt -t, or the series
// sum_k (-t)^k / (2k + 1) when |t| is small (DLMF 19.2.19-20 with x = 1, y = 1 + t).
template <class Real>
inline Real rc_one_one_plus(Real t) {
  using std::abs;
  using std::atan;
  using std::atanh;
  using std::sqrt;
  // Nine terms: the first neglected, t^9/19, is below eps/2 for |t| <= 0.01 in double;
  // higher precisions use the closed forms unless t is tiny.
  const Real small = std::is_same_v<Real, double> ? Real(0.01) : Real(1e-6);
  if (abs(t) < small) {
    Real sum = Real(1) / 19;
    for (int k = 8; k >= 0; --k)
      sum = Real(1) / (2 * k + 1) - t * sum;
    return sum;
  }
  if (t > 0) {
    const Real r = sqrt(t);
    return atan(r) / r;
  }
  const Real r = sqrt(-t);
  return atanh(r) / r;
}

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Carlson's symmetric integrals (DLMF 19.16.1-2, 19.2.17). Arguments must be >= 0 (p > 0) with at
// most one of x, y, z zero; otherwise the result is NaN (negative input) or +inf (two zeros).

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
  return atanh(sqrt(d / x)) / sqrt(d);
}

// R_F(x, y, z) = (1/2) int_0^inf dt / sqrt((t+x)(t+y)(t+z)), DLMF 19.36.1.
template <class Real>
inline Real carlson_rf(Real x, Real y, Real z) {
  using std::abs;
  using std::max;
  using std::sqrt;
  if (!(x >= 0 && y >= 0 && z >= 0)) return detail::quiet_nan<Real>();
  if ((x == 0) + (y == 0) + (z == 0) >= 2) return std::numeric_limits<Real>::infinity();
  const Real A0 = (x + y + z) / 3;
  Real A = A0;
  // q = max|A0 - x_j| / tol, divided by 4 per step: stop when q <= A (then |X_j| <= tol).
  Real q = max(abs(A0 - x), max(abs(A0 - y), abs(A0 - z))) / detail::duplication_tolerance<Real>();
  while (q > A) {
    const Real sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
    const Real lambda = sx * (sy + sz) + sy * sz;
    x = (x + lambda) / 4;
    y = (y + lambda) / 4;
    z = (z + lambda) / 4;
    A = (A + lambda) / 4;
    q /= 4;
  }
  // A_k - x_k = 4^-k (A0 - x0) (DLMF 19.36.1's X scaling), formed from the final values.
  const Real Xk = (A - x) / A, Yk = (A - y) / A, Zk = -(Xk + Yk);
  const Real E2 = Xk * Yk - Zk * Zk;
  const Real E3 = Xk * Yk * Zk;
  // DLMF 19.36.1 through degree 7.
  const Real series = 1 - E2 / 10 + E3 / 14 + E2 * E2 / 24 - 3 * E2 * E3 / 44 -
                      5 * E2 * E2 * E2 / 208 + 3 * E3 * E3 / 104 + E2 * E2 * E3 / 16;
  return series / sqrt(A);
}

namespace detail {

// Shared duplication of R_F(x, y, z) and R_J(x, y, z, p) (same x, y, z): one loop, 4 square
// roots per step instead of 6 + 3. DLMF 19.36.1 (R_F) and 19.36.2 (R_J, d_k / e_k form).
// Requires x, y, z >= 0 with at most one zero, and p > 0.
template <class Real>
inline void carlson_rf_rj(Real x, Real y, Real z, Real p, Real& rf, Real& rj) {
  using std::abs;
  using std::max;
  using std::sqrt;
  const Real AF0 = (x + y + z) / 3;
  const Real AJ0 = (x + y + z + 2 * p) / 5;
  const Real delta = (p - x) * (p - y) * (p - z);
  Real AF = AF0, AJ = AJ0;
  const Real tol = duplication_tolerance<Real>();
  Real qF = max(abs(AF0 - x), max(abs(AF0 - y), abs(AF0 - z))) / tol;
  Real qJ = max(max(abs(AJ0 - x), abs(AJ0 - y)), max(abs(AJ0 - z), abs(AJ0 - p))) / tol;
  Real scale = 1;   // 4^-k
  Real scale3 = 1;  // 4^-3k
  Real sum = 0;     // sum_k 4^-k R_C(1, 1 + e_k) / d_k
  while (qF > AF || qJ > AJ) {
    const Real sx = sqrt(x), sy = sqrt(y), sz = sqrt(z), sp = sqrt(p);
    const Real lambda = sx * (sy + sz) + sy * sz;
    const Real d = (sp + sx) * (sp + sy) * (sp + sz);
    const Real e = scale3 * delta / (d * d);
    sum += scale * rc_one_one_plus(e) / d;
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
  {
    const Real X = (AF - x) / AF, Y = (AF - y) / AF, Z = -(X + Y);
    const Real E2 = X * Y - Z * Z;
    const Real E3 = X * Y * Z;
    rf = (1 - E2 / 10 + E3 / 14 + E2 * E2 / 24 - 3 * E2 * E3 / 44 - 5 * E2 * E2 * E2 / 208 +
          3 * E3 * E3 / 104 + E2 * E2 * E3 / 16) /
         sqrt(AF);
  }
  {
    const Real X = (AJ - x) / AJ, Y = (AJ - y) / AJ, Z = (AJ - z) / AJ;
    const Real P = -(X + Y + Z) / 2;
    const Real XYZ = X * Y * Z;
    const Real P2 = P * P;
    const Real E2 = X * Y + X * Z + Y * Z - 3 * P2;
    const Real E3 = XYZ + 2 * E2 * P + 4 * P * P2;
    const Real E4 = (2 * XYZ + E2 * P + 3 * P * P2) * P;
    const Real E5 = XYZ * P2;
    // DLMF 19.36.2 through degree 5, plus Carlson's degree-6 and -7 terms.
    const Real series = 1 - 3 * E2 / 14 + E3 / 6 + 9 * E2 * E2 / 88 - 3 * E4 / 22 -
                        9 * E2 * E3 / 52 + 3 * E5 / 26 - E2 * E2 * E2 / 16 + 3 * E3 * E3 / 40 +
                        3 * E2 * E4 / 20 + 45 * E2 * E2 * E3 / 272 - 9 * (E3 * E4 + E2 * E5) / 68;
    rj = scale * series / (AJ * sqrt(AJ)) + 6 * sum;
  }
}

}  // namespace detail

// R_J(x, y, z, p) = (3/2) int_0^inf dt / ((t + p) sqrt((t+x)(t+y)(t+z))), p > 0, DLMF 19.36.2.
template <class Real>
inline Real carlson_rj(Real x, Real y, Real z, Real p) {
  if (!(x >= 0 && y >= 0 && z >= 0 && p > 0)) return detail::quiet_nan<Real>();
  if ((x == 0) + (y == 0) + (z == 0) >= 2) return std::numeric_limits<Real>::infinity();
  Real rf, rj;
  detail::carlson_rf_rj(x, y, z, p, rf, rj);
  return rj;
}

// R_D(x, y, z) = R_J(x, y, z, z), z > 0, DLMF 19.16.5.
template <class Real>
inline Real carlson_rd(Real x, Real y, Real z) {
  return carlson_rj(x, y, z, z);
}

// ---------------------------------------------------------------------------------------------
// Legendre forms.

namespace detail {

// Shared inputs of the Legendre forms at phi in [0, pi/2]: s, c, c^2 and Delta^2 = 1 - m s^2.
template <class Real>
struct LegendreArgs {
  Real s, c, c2, delta2;
};

template <class Real>
inline LegendreArgs<Real> legendre_args(Real phi, Real m, Real one_minus_m) {
  using std::cos;
  using std::sin;
  LegendreArgs<Real> a;
  a.s = sin(phi);
  a.c = cos(phi);
  a.c2 = a.c * a.c;
  // 1 - m s^2 cancels when m s^2 -> 1; c^2 + (1 - m) s^2 is then a sum of positive terms.
  a.delta2 = (m <= Real(0.5)) ? 1 - m * a.s * a.s : a.c2 + one_minus_m * a.s * a.s;
  return a;
}

template <class Real>
inline bool in_phi_domain(Real phi) {
  return phi >= 0 && phi <= Real(std::numbers::pi_v<double>) / 2;
}

// F at phi in [0, pi/2], m <= 1.
template <class Real>
inline Real ellint_f_core(Real phi, Real m, Real one_minus_m) {
  const LegendreArgs<Real> a = legendre_args(phi, m, one_minus_m);
  if (a.s == 0) return phi;
  return a.s * carlson_rf(a.c2, a.delta2, Real(1));
}

// Pi at phi in [0, pi/2], m <= 1, n <= 1. Writes F as well (it comes for free).
template <class Real>
inline Real ellint_pi_core(Real n, Real one_minus_n, Real phi, Real m, Real one_minus_m,
                           Real* f_out = nullptr) {
  using std::atan;
  using std::sqrt;
  const LegendreArgs<Real> a = legendre_args(phi, m, one_minus_m);
  if (a.s == 0) {
    if (f_out) *f_out = phi;
    return phi;
  }
  const Real s3 = a.s * a.s * a.s;
  if (n == 0) {
    const Real f = a.s * carlson_rf(a.c2, a.delta2, Real(1));
    if (f_out) *f_out = f;
    return f;
  }
  const Real N = (m - n) / one_minus_n;  // the transformed characteristic for n < 0
  if (n > 0 || !(N > 0)) {
    // Direct: Pi = s R_F + (n/3) s^3 R_J(c^2, Delta^2, 1, 1 - n s^2); the terms have equal
    // signs for n > 0 (the m < 0 fallback for n < 0 accepts some cancellation).
    const Real p = (n <= Real(0.5)) ? 1 - n * a.s * a.s : a.c2 + one_minus_n * a.s * a.s;
    if (!(p > 0)) {  // n == 1 at phi == pi/2 (only reachable through rounding): divergent
      if (f_out) *f_out = a.s * carlson_rf(a.c2, a.delta2, Real(1));
      return std::numeric_limits<Real>::infinity();
    }
    Real rf, rj;
    carlson_rf_rj(a.c2, a.delta2, Real(1), p, rf, rj);
    const Real f = a.s * rf;
    if (f_out) *f_out = f;
    return f + n / 3 * s3 * rj;
  }
  // n < 0, N = (m - n)/(1 - n) in (0, 1): A&S 17.7.15 rearranged into three non-negative terms
  // (see the header comment). 1 - N = (1 - m)/(1 - n) and 1 - N s^2 = c^2 + (1 - N) s^2.
  const Real one_minus_N = one_minus_m / one_minus_n;
  const Real pN = a.c2 + one_minus_N * a.s * a.s;
  Real rf, rj;
  carlson_rf_rj(a.c2, a.delta2, Real(1), pN, rf, rj);
  const Real f = a.s * rf;
  if (f_out) *f_out = f;
  const Real w = -n / one_minus_n;  // in (0, 1); kept apart so (1 - n)^2 never overflows
  const Real mn = m - n;            // > 0
  const Real delta = sqrt(a.delta2);
  const Real sw = sqrt(w), smn = sqrt(mn);
  const Real term_j = w * (one_minus_m / one_minus_n) / 3 * s3 * rj;
  const Real term_atan = (sw / smn) * atan(sw * smn * a.s * a.c / delta);
  return f / one_minus_n + term_j + term_atan;
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
  return ellint_pi(n, Real(1 - n), phi, m, Real(1 - m));
}

// ---------------------------------------------------------------------------------------------
// Difference forms that avoid cancellation, and the second kind. Domain as above (phi in
// [0, pi/2]; outside it these return NaN rather than reduce).

// D(phi|m) = int_0^phi sin^2 t / sqrt(1 - m sin^2 t) dt = (s^3/3) R_D(c^2, Delta^2, 1)
// (DLMF 19.25.13). F - E = m D without cancellation.
template <class Real>
inline Real ellint_d(Real phi, Real m, Real one_minus_m) {
  if (!(m <= 1) || !(one_minus_m >= 0) || !detail::in_phi_domain(phi))
    return detail::quiet_nan<Real>();
  const auto a = detail::legendre_args(phi, m, one_minus_m);
  if (a.s == 0) return Real(0);
  return a.s * a.s * a.s / 3 * carlson_rd(a.c2, a.delta2, Real(1));
}
template <class Real>
inline Real ellint_d(Real phi, Real m) {
  return ellint_d(phi, m, Real(1 - m));
}

// E(phi|m) = int_0^phi sqrt(1 - m sin^2 t) dt = F - m D (DLMF 19.25.9).
template <class Real>
inline Real ellint_e(Real phi, Real m, Real one_minus_m) {
  if (!(m <= 1) || !(one_minus_m >= 0) || !detail::in_phi_domain(phi))
    return detail::quiet_nan<Real>();
  const auto a = detail::legendre_args(phi, m, one_minus_m);
  if (a.s == 0) return Real(0);
  return a.s * carlson_rf(a.c2, a.delta2, Real(1)) -
         m * a.s * a.s * a.s / 3 * carlson_rd(a.c2, a.delta2, Real(1));
}
template <class Real>
inline Real ellint_e(Real phi, Real m) {
  return ellint_e(phi, m, Real(1 - m));
}

// Complete integrals K(m) = R_F(0, 1 - m, 1), E(m) = K - (m/3) R_D(0, 1 - m, 1) (DLMF 19.25.1),
// taking the complement mc = 1 - m.
template <class Real>
inline Real ellint_k_complete(Real one_minus_m) {
  return carlson_rf(Real(0), one_minus_m, Real(1));
}
template <class Real>
inline Real ellint_e_complete(Real one_minus_m) {
  const Real m = 1 - one_minus_m;
  return carlson_rf(Real(0), one_minus_m, Real(1)) -
         m / 3 * carlson_rd(Real(0), one_minus_m, Real(1));
}

// Pi(n; phi|m) - F(phi|m) = n int_0^phi sin^2 t / ((1 - n sin^2 t) Delta) dt
//                         = (n/3) s^3 R_J(c^2, Delta^2, 1, 1 - n s^2): one term, no cancellation.
template <class Real>
inline Real ellint_pi_minus_f(Real n, Real one_minus_n, Real phi, Real m, Real one_minus_m) {
  if (!(m <= 1) || !(one_minus_m >= 0) || !(n <= 1) || !(one_minus_n >= 0) ||
      !detail::in_phi_domain(phi))
    return detail::quiet_nan<Real>();
  const auto a = detail::legendre_args(phi, m, one_minus_m);
  if (a.s == 0 || n == 0) return Real(0);
  const Real p = (n <= Real(0.5)) ? 1 - n * a.s * a.s : a.c2 + one_minus_n * a.s * a.s;
  return n / 3 * a.s * a.s * a.s * carlson_rj(a.c2, a.delta2, Real(1), p);
}
template <class Real>
inline Real ellint_pi_minus_f(Real n, Real phi, Real m) {
  return ellint_pi_minus_f(n, Real(1 - n), phi, m, Real(1 - m));
}

// (1 - n) Pi(n; phi|m) - F(phi|m) = -n int_0^phi cos^2 t / ((1 - n sin^2 t) Delta) dt, the
// bracket of Guillen et al. 2017 eq. (11) with n = -b_t^2. For n < 0 (and m >= 0) it is
//   (-n (1-m) / (3 (1-n))) s^3 R_J(c^2, Delta^2, 1, 1 - N s^2)
//     + sqrt(-n (1-n) / (m-n)) atan(sqrt(-n (m-n)/(1-n)) s c / Delta),
// two positive terms (the n < 0 form of Pi above times (1 - n), minus F). For 0 <= n < 1 it is
// (1 - n)(Pi - F) - n F, whose terms have opposite signs (relative error ~ eps (1 + n F/|result|)).
template <class Real>
inline Real ellint_one_minus_n_pi_minus_f(Real n, Real one_minus_n, Real phi, Real m,
                                          Real one_minus_m) {
  using std::atan;
  using std::sqrt;
  if (!(m <= 1) || !(one_minus_m >= 0) || !(n <= 1) || !(one_minus_n >= 0) ||
      !detail::in_phi_domain(phi))
    return detail::quiet_nan<Real>();
  const auto a = detail::legendre_args(phi, m, one_minus_m);
  if (a.s == 0 || n == 0) return Real(0);
  const Real s3 = a.s * a.s * a.s;
  if (n < 0 && m >= 0) {
    const Real one_minus_N = one_minus_m / one_minus_n;
    const Real pN = a.c2 + one_minus_N * a.s * a.s;
    const Real rj = carlson_rj(a.c2, a.delta2, Real(1), pN);
    const Real w = -n / one_minus_n;
    const Real mn = m - n;
    const Real sw = sqrt(w), smn = sqrt(mn);
    const Real term_j = w * one_minus_m / 3 * s3 * rj;
    const Real term_atan =
        sqrt(-n) * (sqrt(one_minus_n) / smn) * atan(sw * smn * a.s * a.c / sqrt(a.delta2));
    return term_j + term_atan;
  }
  const Real p = (n <= Real(0.5)) ? 1 - n * a.s * a.s : a.c2 + one_minus_n * a.s * a.s;
  Real rf, rj;
  detail::carlson_rf_rj(a.c2, a.delta2, Real(1), p, rf, rj);
  return one_minus_n * (n / 3 * s3 * rj) - n * a.s * rf;
}
template <class Real>
inline Real ellint_one_minus_n_pi_minus_f(Real n, Real phi, Real m) {
  return ellint_one_minus_n_pi_minus_f(n, Real(1 - n), phi, m, Real(1 - m));
}

}  // namespace disklab::math
