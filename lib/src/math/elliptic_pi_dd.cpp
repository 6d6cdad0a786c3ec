// Pi(n; phi|m) in double through a double-double Carlson loop (AVX2 + FMA, chosen at run time).
// See elliptic.h ("FAST PATH") for when it is used; the math is the same as the portable path:
//   Pi = s R_F(c^2, Delta^2, 1) + (n/3) s^3 R_J(c^2, Delta^2, 1, 1 - n s^2)          (n >= 0)
//   Pi = s R_F / (1 - n) + (-n (1-m) / (3 (1-n)^2)) s^3 R_J(c^2, Delta^2, 1, 1 - N s^2)
//        + sqrt(-n/((1-n)(m-n))) atan(sqrt(-n (m-n)/(1-n)) s c / Delta)               (n < 0)
// with N = (m - n)/(1 - n) (A&S 17.7.15), R_F and R_J by duplication (DLMF 19.36.1-2).
//
// Why double-double: in plain double the duplication loop's roundings (square roots, lambda_k,
// d_k) reach 4 ulp on the 50-digit tables; the portable path carries the loop in x87 long double,
// whose square roots and divisions are slow. Here every quantity of the loop is a pair hi + lo
// (|lo| ~ ulp(hi)) updated with error-free transformations (FMA products, two-sums).
//
// Speed design (measured: bench_elliptic, Pi/mixed):
//  - the four arguments (x, y, z, p) of a duplication step sit in one AVX2 register: one vector
//    square root and one division serve all four;
//  - the hi parts follow exactly the plain-double recurrence and are never renormalised with the
//    lo parts, so the lo bookkeeping stays off the loop's critical path (it only feeds the end);
//  - everything that does not depend on the loop (the prefactors and the atan term) is formed
//    before it, so it overlaps with the loop.
#include <algorithm>
#include <cmath>

#include "disklab/math/elliptic.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define DISKLAB_PI_DD 1
#include <immintrin.h>
#endif

namespace disklab::math::detail {

#if DISKLAB_PI_DD

namespace {

#define DL_TARGET __attribute__((target("avx2,fma")))
#define DL_INLINE inline __attribute__((always_inline, target("avx2,fma")))

// A double-double: value hi + lo. Operations below are "sloppy" (no renormalisation): their
// relative error is ~2^-104 plus the neglected lo*lo products, far below the 2^-60 needed here.
struct DD {
  double h, l;
};

DL_INLINE DD two_sum(double a, double b) {  // exact: a + b = s + e (Knuth)
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
DL_INLINE DD two_prod(double a, double b) {  // exact: a b = p + e (FMA)
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}
DL_INLINE DD add(DD a, DD b) {
  const DD s = two_sum(a.h, b.h);
  return {s.h, s.l + (a.l + b.l)};
}
DL_INLINE DD mul(DD a, DD b) {
  const double p = a.h * b.h;
  return {p, std::fma(a.h, b.h, -p) + (a.h * b.l + a.l * b.h)};
}
DL_INLINE DD mul(DD a, double b) {
  const double p = a.h * b;
  return {p, std::fma(a.h, b, -p) + a.l * b};
}
DL_INLINE DD scale(DD a, double power_of_two) {
  return {a.h * power_of_two, a.l * power_of_two};
}
DL_INLINE DD recip(DD a) {  // 1/a: one Newton correction of 1/a.h
  const double h = 1 / a.h;
  return {h, (std::fma(-a.h, h, 1.0) - a.l * h) * h};
}
DL_INLINE DD sqrt_dd(DD a) {  // sqrt(a), a > 0: h + (a - h^2) / (2h)
  const double h = std::sqrt(a.h);
  return {h, (std::fma(-h, h, a.h) + a.l) / (2 * h)};
}
DL_INLINE double value(DD a) {
  return a.h + a.l;
}

constexpr DD kThird = {0x1.5555555555555p-2, 0x1.5555555555555p-56};   // 1/3 to 2^-107
constexpr DD kFifth = {0x1.999999999999ap-3, -0x1.999999999999ap-57};  // 1/5 to 2^-107

// Four double-doubles in AVX2 lanes.
struct DD4 {
  __m256d h, l;
};
DL_INLINE DD4 add(DD4 a, DD4 b) {
  const __m256d s = _mm256_add_pd(a.h, b.h), bb = _mm256_sub_pd(s, a.h);
  const __m256d e = _mm256_add_pd(_mm256_sub_pd(a.h, _mm256_sub_pd(s, bb)), _mm256_sub_pd(b.h, bb));
  return {s, _mm256_add_pd(e, _mm256_add_pd(a.l, b.l))};
}
DL_INLINE DD4 mul(DD4 a, DD4 b) {
  const __m256d p = _mm256_mul_pd(a.h, b.h);
  const __m256d e = _mm256_fmsub_pd(a.h, b.h, p);
  return {p, _mm256_fmadd_pd(a.h, b.l, _mm256_fmadd_pd(a.l, b.h, e))};
}
DL_INLINE DD4 sqrt_dd(DD4 a) {
  const __m256d h = _mm256_sqrt_pd(a.h);
  const __m256d r = _mm256_add_pd(_mm256_fnmadd_pd(h, h, a.h), a.l);
  return {h, _mm256_div_pd(r, _mm256_add_pd(h, h))};
}
DL_INLINE DD4 quarter(DD4 a) {
  const __m256d q = _mm256_set1_pd(0.25);
  return {_mm256_mul_pd(a.h, q), _mm256_mul_pd(a.l, q)};
}
template <int kLanes>
DL_INLINE DD4 permute(DD4 a) {
  return {_mm256_permute4x64_pd(a.h, kLanes), _mm256_permute4x64_pd(a.l, kLanes)};
}
DL_INLINE DD lane0(DD4 a) {
  return {_mm256_cvtsd_f64(a.h), _mm256_cvtsd_f64(a.l)};
}

// Lane selectors for _mm256_permute4x64_pd (lane i of the result takes lane sel_i).
constexpr int lanes(int l0, int l1, int l2, int l3) {
  return l0 | l1 << 2 | l2 << 4 | l3 << 6;
}

// R_F(c^2, Delta^2, 1) and R_J(c^2, Delta^2, 1, p) (DLMF 19.36.1-2), as in rf_rj_loop of
// elliptic.h (same stopping rule and degree-7 tails), in double-double. Requires c > 0,
// Delta^2 > 0, p > 0 (the Legendre arguments at phi in (0, pi/2]).
DL_TARGET void rf_rj_dd(double c, DD delta2, DD p, DD& rf, DD& rj) {
  const DD x = two_prod(c, c);
  DD4 v = {_mm256_setr_pd(x.h, delta2.h, 1.0, p.h), _mm256_setr_pd(x.l, delta2.l, 0.0, p.l)};
  // Stopping rule and tail inputs from the hi parts, as in the portable loop: the tails need a
  // few correct digits only (they are below tol^2 = 1e-4).
  const double x0 = x.h, y0 = delta2.h, p0 = p.h;
  double AF = (x0 + y0 + 1) * (1.0 / 3), AJ = (x0 + y0 + 1 + 2 * p0) * 0.2;
  const double dFx = AF - x0, dFy = AF - y0, dJx = AJ - x0, dJy = AJ - y0, dJz = AJ - 1;
  const double delta = (p0 - x0) * (p0 - y0) * (p0 - 1);
  const double inv_tol = 1 / duplication_tolerance<double>();
  double qF = std::max(std::fabs(dFx), std::max(std::fabs(dFy), std::fabs(AF - 1))) * inv_tol;
  double qJ = std::max(std::max(std::fabs(dJx), std::fabs(dJy)),
                       std::max(std::fabs(dJz), std::fabs(AJ - p0))) *
              inv_tol;
  double scale_k = 1, scale3_k = 1;  // 4^-k, 4^-3k
  DD sum = {0, 0};                   // sum_k 4^-k R_C(1, 1 + e_k) / d_k
  while (qF > AF || qJ > AJ) {
    const DD4 s = sqrt_dd(v);  // sx sy sz sp
    // lambda = sx sy + sy sz + sz sx in every lane, as a b + b c + c a with (a, b, c) the lanes
    // of s rotated (one permute level instead of a horizontal sum and a broadcast).
    const DD4 a = permute<lanes(0, 1, 2, 0)>(s), b = permute<lanes(1, 2, 0, 1)>(s),
              c = permute<lanes(2, 0, 1, 2)>(s);
    const DD4 lam = add(add(mul(a, b), mul(b, c)), mul(c, a));
    // d = (sp + sx)(sp + sy)(sp + sz) (lane 0).
    const DD4 w = add(s, permute<lanes(3, 3, 3, 3)>(s));
    const DD4 d4 = mul(mul(w, permute<lanes(1, 3, 3, 3)>(w)), permute<lanes(2, 3, 3, 3)>(w));
    const DD lambda = lane0(lam), d = lane0(d4);
    const double sp = _mm256_cvtsd_f64(_mm256_permute4x64_pd(s.h, lanes(3, 3, 3, 3)));
    const double ph = _mm256_cvtsd_f64(_mm256_permute4x64_pd(v.h, lanes(3, 3, 3, 3)));
    const DD inv_d = recip(d);
    // e_k and 1 + e_k as in rf_rj_loop; R_C(1, 1 + e) = 1 + (R_C - 1) keeps the leading 1 exact.
    const double e = scale3_k * delta * inv_d.h * inv_d.h;
    const double one_plus_e = 2 * sp * (ph + lambda.h) * inv_d.h;
    const double rc_minus_1 = rc_one_one_plus<double, double>(e, one_plus_e) - 1;
    sum = add(sum, scale(add(inv_d, two_prod(inv_d.h, rc_minus_1)), scale_k));
    v = quarter(add(v, lam));
    AF = (AF + lambda.h) * 0.25;
    AJ = (AJ + lambda.h) * 0.25;
    qF *= 0.25;
    qJ *= 0.25;
    scale_k *= 0.25;
    scale3_k *= 1.0 / 64;
  }
  alignas(32) double hi[4], lo[4];
  _mm256_store_pd(hi, v.h);
  _mm256_store_pd(lo, v.l);
  const DD xyz = add(add(DD{hi[0], lo[0]}, DD{hi[1], lo[1]}), DD{hi[2], lo[2]});
  // A^-1/2 from the tracked double A (h), corrected once with the double-double A:
  // A^-1/2 = h (1 + e/2), e = 1 - A h^2 (|e| ~ 1e-16, so e^2 terms are below 2^-100).
  const double inv_AF = 1 / AF, inv_AJ = 1 / AJ;
  const double hF = std::sqrt(AF) * inv_AF, hJ = std::sqrt(AJ) * inv_AJ;
  {
    const DD A = mul(xyz, kThird);
    const DD t = two_prod(hF, hF);
    const double e = std::fma(-A.h, t.h, 1.0) - A.h * t.l - A.l * t.h;
    const double X = dFx * scale_k * inv_AF, Y = dFy * scale_k * inv_AF, Z = -(X + Y);
    const double E2 = X * Y - Z * Z, E3 = X * Y * Z;
    const double tail = rf_series_tail(E2, E3);
    rf = {hF, hF * (0.5 * e + tail)};
  }
  {
    const DD A = mul(add(xyz, scale(DD{hi[3], lo[3]}, 2)), kFifth);
    const DD t = two_prod(hJ, hJ);
    const double e = std::fma(-A.h, t.h, 1.0) - A.h * t.l - A.l * t.h;
    const DD h3 = mul(t, hJ);  // A^-3/2 = h^3 (1 + 3e/2)
    const double X = dJx * scale_k * inv_AJ, Y = dJy * scale_k * inv_AJ, Z = dJz * scale_k * inv_AJ;
    const double tail = rj_series_tail(X, Y, Z);
    const double head = h3.h * scale_k;
    rj = add(DD{head, h3.l * scale_k + head * (1.5 * e + tail)}, mul(sum, 6.0));
  }
}

DL_TARGET double pi_dd(double n, DD omn, double phi, double m, DD omm) {
  const double s = std::sin(phi), c = std::cos(phi);
  const DD s2 = two_prod(s, s), c2 = two_prod(c, c);
  // Delta^2 = 1 - m s^2 = c^2 + (1 - m) s^2 (the second form where the first cancels).
  const DD delta2 = m <= 0.5 ? add(DD{1, 0}, mul(s2, -m)) : add(c2, mul(s2, omm));
  const DD s3 = mul(s2, s);
  DD rf, rj;
  if (n >= 0) {
    const DD p = n <= 0.5 ? add(DD{1, 0}, mul(s2, -n)) : add(c2, mul(s2, omn));
    const DD kj = mul(s3, mul(kThird, n));  // (n/3) s^3
    rf_rj_dd(c, delta2, p, rf, rj);
    return value(add(mul(rf, s), mul(rj, kj)));
  }
  const DD inv_omn = recip(omn);
  const DD omN = mul(omm, inv_omn);  // 1 - N = (1 - m)/(1 - n)
  const DD pN = add(c2, mul(s2, omN));
  const DD w = mul(inv_omn, -n);  // -n/(1 - n)
  const DD mn = two_sum(m, -n);   // m - n > 0
  const DD k1 = mul(inv_omn, s);
  const DD kj = mul(mul(w, omN), mul(s3, kThird));
  const DD g = sqrt_dd(mul(w, mn));  // sqrt(-n (m - n)/(1 - n))
  const DD arg = mul(mul(g, two_prod(s, c)), recip(sqrt_dd(delta2)));
  // The atan term carries double atan's error (<= 1 ulp of that term), as on the portable path.
  const DD term_atan = mul(mul(g, recip(mn)), std::atan(value(arg)));
  rf_rj_dd(c, delta2, pN, rf, rj);
  return value(add(add(mul(rf, k1), mul(rj, kj)), term_atan));
}

}  // namespace

// Read by pi_dd_covers on every call: a plain flag, set during static initialisation (before
// that it is zero, so a call from another static initialiser takes the portable path).
const bool pi_dd_kernel_flag = [] {
  __builtin_cpu_init();  // static initialisers may run before libgcc's own CPU probe
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}();

bool pi_dd_kernel_available() noexcept {
  return pi_dd_kernel_flag;
}

double ellint_pi_dd(double n, double one_minus_n, double one_minus_n_lo, double phi, double m,
                    double one_minus_m, double one_minus_m_lo) noexcept {
  return pi_dd(n, DD{one_minus_n, one_minus_n_lo}, phi, m, DD{one_minus_m, one_minus_m_lo});
}

#else  // no x86-64 AVX2 kernel in this build: the portable path is always used

const bool pi_dd_kernel_flag = false;
bool pi_dd_kernel_available() noexcept {
  return false;
}

double ellint_pi_dd(double, double, double, double, double, double, double) noexcept {
  return std::numeric_limits<double>::quiet_NaN();
}

#endif

}  // namespace disklab::math::detail
