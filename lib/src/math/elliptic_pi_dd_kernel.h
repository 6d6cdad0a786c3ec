// Pi(n; phi|m) in double through a double-double Carlson loop (x86-64 with AVX2 + FMA).
// See elliptic.h ("FAST PATH") for when it is used. The math:
//   Pi = s R_F(c^2, Delta^2, 1) + (n/3) s^3 R_J(c^2, Delta^2, 1, 1 - n s^2)          (n >= -1)
//   Pi = s R_F / (1 - n) + (-n (1-m) / (3 (1-n)^2)) s^3 R_J(c^2, Delta^2, 1, 1 - N s^2)
//        + sqrt(-n/((1-n)(m-n))) atan(sqrt(-n (m-n)/(1-n)) s c / Delta)               (n < -1)
// with N = (m - n)/(1 - n) (A&S 17.7.15), R_F and R_J by duplication (DLMF 19.36.1-2). The
// portable path uses the second form for all n < 0 (in long double the cancellation of the first
// for -1 <= n < 0, a factor 2 at most, would cost a bit); it stops its duplication at tolerance
// 0.01 with degree-7 tails, this kernel at 0.03 with degree-9 tails (see kKernelTolerance).
//
// Why double-double: in plain double the duplication loop's roundings (square roots, lambda_k,
// d_k) reach 4 ulp on the 50-digit tables; the portable path carries the loop in x87 long double,
// whose square roots and divisions are slow. Here every quantity of the loop is a pair hi + lo
// (|lo| ~ ulp(hi)) updated with error-free transformations (FMA products, two-sums).
// Three more inputs are kept in double-double, because at the domain's corners (phi -> pi/2
// with m, n -> 1) each alone costs up to 3-4 ulp when rounded to double (measured against
// 50-digit Carlson, EllipticReference.PiAndFWithinTwoUlpOf50DigitsAtCorners):
//  - s = sin(phi) and c = cos(phi) (sincos_dd, instead of libm's correctly rounded doubles);
//    their 2^-54.5 relative error is the largest of the kernel's elementary functions
//    (EllipticReference.KernelElementaryFunctionsWithin2em55Of50Digits prints them);
//  - R_C(1, 1 + e_k) where |e_k| >= 0.01 (the first duplication steps), by closed forms in
//    double-double (atan_dd, log_dd), and e_k from delta formed of double-double differences;
//  - the atan term of n < -1 (atan_dd).
//
// Speed design (measured: bench_elliptic, Pi/mixed):
//  - the four arguments (x, y, z, p) of a duplication step sit in one AVX2 register: one vector
//    square root serves all four;
//  - the hi parts follow a plain-double recurrence and are never renormalised with the lo
//    parts, so the lo bookkeeping stays off the loop's critical path (it only feeds the end);
//  - the recurrence is scaled by 4^k (no multiplication by 1/4 on the path) and the stopping
//    rule needs one running sum (Lambda); the loop holds no call (the rare closed forms of R_C
//    wait for its end), so its state can stay in registers (with AVX2's 16 vector registers
//    GCC still spills a few scalars; the AVX-512VL copy's 32 hold it all);
//  - everything that does not depend on the loop (the prefactors and the atan term) is formed
//    before it, so it overlaps with the loop;
//  - the AVX-512VL copy also replaces the loop's vector division by a reciprocal estimate (see
//    sqrt_dd). Same run: Pi/mixed/own 0.388x Boost with that copy, Pi/mixed/own-avx2 0.40x.
//
// Not a normal header: it is compiled twice, by elliptic_pi_dd_avx2.cpp and
// elliptic_pi_dd_avx512.cpp, which define before including it
//   DL_KERNEL_NS  the namespace of the copy's entry points (declared in elliptic_pi_dd_entry.h),
//   DL_ISA        the copy's instruction sets, as a GCC target string,
//   DL_RCP14      1 where AVX-512VL's reciprocal estimate replaces a division (see sqrt_dd).
// elliptic_pi_dd.cpp chooses the copy at run time.
#include <immintrin.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "elliptic_pi_dd_entry.h"

namespace disklab::math::detail {

namespace {

#define DL_TARGET __attribute__((target(DL_ISA)))
#define DL_INLINE inline __attribute__((always_inline, target(DL_ISA)))

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
DL_INLINE DD normalize(DD a) {  // |lo| <= ulp(hi)/2 again (after a cancellation, say)
  const double s = a.h + a.l;
  return {s, a.l - (s - a.h)};
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

// sin and cos of phi in [0, pi/2] as double-doubles: relative error below 2^-54 (three roundings
// of a Taylor correction at most 0.103 of the value), a third of a correctly rounded double's
// worst case, and far less where it matters (phi -> pi/2: c = sin t with t tiny). phi > pi/4 is
// reduced exactly to t = pi/2 - phi (Sterbenz: pi/2 - phi is exact there; pi/2's tail is added as
// t's lo part), then sin and cos swap. Both are Taylor series on |t| <= pi/4 (A&S 4.3.65-66) up to
// t^17 and t^16 (first omitted terms below 2^-58 relative), evaluated by Estrin's scheme in u = t^2
// (shorter latency than Horner).
constexpr DD kHalfPi = {0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54};

DL_INLINE void sincos_dd(double phi, DD& sin_phi, DD& cos_phi) {
  const bool reflect = phi > 0.5 * kHalfPi.h;
  const double d = reflect ? kHalfPi.h - phi : phi;  // exact
  const DD t = two_sum(d, reflect ? kHalfPi.l : 0.0);
  const double u = t.h * t.h, u2 = u * u, u4 = u2 * u2;
  // sin t = t + t^3 S(u), S = sum_k (-1)^(k+1) u^k / (2k+3)!, k = 0..7.
  constexpr double s0 = -1.0 / 6, s1 = 1.0 / 120, s2 = -1.0 / 5040, s3 = 1.0 / 362880,
                   s4 = -1.0 / 39916800, s5 = 1.0 / 6227020800, s6 = -1.0 / 1307674368000,
                   s7 = 1.0 / 355687428096000;
  const double S = (std::fma(s1, u, s0) + u2 * std::fma(s3, u, s2)) +
                   u4 * (std::fma(s5, u, s4) + u2 * std::fma(s7, u, s6));
  // cos t = 1 - u/2 + u^2 C(u), C = sum_k (-1)^k u^k / (2k+4)!, k = 0..6.
  constexpr double c0 = 1.0 / 24, c1 = -1.0 / 720, c2 = 1.0 / 40320, c3 = -1.0 / 3628800,
                   c4 = 1.0 / 479001600, c5 = -1.0 / 87178291200, c6 = 1.0 / 20922789888000;
  const double C =
      (std::fma(c1, u, c0) + u2 * std::fma(c3, u, c2)) + u4 * (std::fma(c5, u, c4) + u2 * c6);
  // sin(t_h + t_l) = sin t_h + t_l cos t_h, |t_l| <= 2^-53 |t_h|: cos t_h ~ 1 - u/2 suffices.
  const DD sn = two_sum(t.h, std::fma(t.h * u, S, t.l * (1 - 0.5 * u)));
  // cos: 1 - u/2 with u = t_h^2 exact (two_prod); cos(t_h + t_l) = cos t_h - t_l t_h.
  const DD uu = two_prod(t.h, t.h);
  const DD one_minus = two_sum(1.0, -0.5 * uu.h);
  const DD cs = two_sum(one_minus.h, one_minus.l - 0.5 * uu.l + std::fma(u2, C, -t.l * t.h));
  sin_phi = reflect ? cs : sn;
  cos_phi = reflect ? sn : cs;
}

// atan(x) for a double-double x >= 0, as a double-double (relative error ~2^-60). x > 1 is
// reflected, atan x = pi/2 - atan(1/x); then atan r = atan(a) + atan(u) with a = j/8 the
// nearest eighth and u = (r - a)/(1 + r a), |u| <= 1/16, where the Taylor series through u^13
// leaves below 2^-59 relative. atan(j/8) as double-doubles (mpmath, 200 bits).
constexpr DD kAtanEighths[9] = {{0x0.0p+0, 0x0.0p+0},
                                {0x1.fd5ba9aac2f6ep-4, -0x1.cd37686760c17p-59},
                                {0x1.f5b75f92c80ddp-3, 0x1.8ab6e3cf7afbdp-57},
                                {0x1.6f61941e4def1p-2, -0x1.c63aae6f6e918p-56},
                                {0x1.dac670561bb4fp-2, 0x1.a2b7f222f65e2p-56},
                                {0x1.1e00babdefeb4p-1, -0x1.928df287a668fp-58},
                                {0x1.4978fa3269ee1p-1, 0x1.2419a87f2a458p-56},
                                {0x1.700a7c5784634p-1, -0x1.8c34d25aadef6p-56},
                                {0x1.921fb54442d18p-1, 0x1.1a62633145c07p-55}};

DL_INLINE DD atan_dd(DD x) {
  const bool reflect = x.h > 1;
  const double inv = 1 / x.h;
  const DD r = reflect ? DD{inv, (std::fma(-x.h, inv, 1.0) - x.l * inv) * inv} : x;
  const int j = static_cast<int>(r.h * 8 + 0.5);  // r.h in [0, 1]: j in 0..8
  const double a = j * 0.125;
  const double num = r.h - a;  // exact (Sterbenz for j >= 1; a = 0 otherwise)
  const DD ra = two_prod(r.h, a);
  const DD den = two_sum(1.0, ra.h);
  const double den_l = den.l + ra.l + r.l * a;
  const double inv_den = 1 / den.h;
  const double uh = num * inv_den;
  const double ul = (std::fma(-uh, den.h, num) + r.l - uh * den_l) * inv_den;
  const double v = uh * uh, v2 = v * v;
  // atan u = u + u^3 P(v), P = sum_k (-1)^(k+1) v^k / (2k+3), k = 0..5.
  const double P = (std::fma(1.0 / 5, v, -1.0 / 3) + v2 * std::fma(1.0 / 9, v, -1.0 / 7)) +
                   v2 * v2 * std::fma(1.0 / 13, v, -1.0 / 11);
  const DD base = kAtanEighths[j];
  const DD hs = two_sum(base.h, uh);
  const DD res = {hs.h, hs.l + base.l + std::fma(uh * v, P, ul)};
  const DD d = two_sum(kHalfPi.h, -res.h);
  return reflect ? DD{d.h, d.l + kHalfPi.l - res.l} : res;
}

// log(x) for a double-double x >= 1, as a double-double (relative error ~2^-60): x = 2^k f,
// f in [1, 2); log f = log a + 2 atanh(u) with a = 1 + j/16 the nearest sixteenth and
// u = (f - a)/(f + a), |u| <= 1/65, where atanh's series through u^9 leaves below 2^-63.
// log(1 + j/16) as double-doubles (mpmath, 200 bits); ln 2's head has 42 bits, so k ln2_hi is
// exact for the k < 2^11 met here.
constexpr DD kLogSixteenths[17] = {{0x0.0p+0, 0x0.0p+0},
                                   {0x1.f0a30c01162a6p-5, 0x1.85f325c5bbacdp-59},
                                   {0x1.e27076e2af2e6p-4, -0x1.61578001e0162p-60},
                                   {0x1.5ff3070a793d4p-3, -0x1.bc60efafc6f6ep-58},
                                   {0x1.c8ff7c79a9a22p-3, -0x1.4f689f8434012p-57},
                                   {0x1.1675cababa60ep-2, 0x1.ce63eab883717p-61},
                                   {0x1.4618bc21c5ec2p-2, 0x1.f42decdeccf1dp-56},
                                   {0x1.739d7f6bbd007p-2, -0x1.8c76ceb014b04p-56},
                                   {0x1.9f323ecbf984cp-2, -0x1.a92e513217f5cp-59},
                                   {0x1.c8ff7c79a9a22p-2, -0x1.4f689f8434012p-56},
                                   {0x1.f128f5faf06edp-2, -0x1.328df13bb38c3p-56},
                                   {0x1.0be72e4252a83p-1, -0x1.259da11330801p-55},
                                   {0x1.1e85f5e7040d0p-1, 0x1.ef62cd2f9f1e3p-56},
                                   {0x1.307d7334f10bep-1, 0x1.fb590a1f566dap-57},
                                   {0x1.41d8fe84672aep-1, 0x1.9192f30bd1806p-55},
                                   {0x1.52a2d265bc5abp-1, -0x1.1883750ea4d0ap-57},
                                   {0x1.62e42fefa39efp-1, 0x1.abc9e3b39803fp-56}};
constexpr DD kLn2 = {0x1.62e42fefa3800p-1, 0x1.ef35793c76730p-45};

DL_INLINE DD log_dd(DD x) {
  x = normalize(x);  // the first-order u below needs |x.l| ~ ulp(x.h)
  int k;
  const double fh = 2 * std::frexp(x.h, &k);  // x.h = fh 2^(k-1), fh in [1, 2)
  --k;
  const double fl = std::ldexp(x.l, -k);
  const int j = static_cast<int>((fh - 1) * 16 + 0.5);
  const double a = 1 + j * 0.0625;
  const double num = fh - a;  // exact (Sterbenz)
  const DD den = two_sum(fh, a);
  const double inv_den = 1 / den.h;
  const double uh = num * inv_den;
  const double ul = (std::fma(-uh, den.h, num) + fl - uh * (den.l + fl)) * inv_den;
  const double v = uh * uh;
  const double P = std::fma(v, std::fma(v, std::fma(v, 1.0 / 9, 1.0 / 7), 1.0 / 5), 1.0 / 3);
  const DD base = add(DD{k * kLn2.h, k * kLn2.l}, kLogSixteenths[j]);
  const DD hs = two_sum(base.h, 2 * uh);
  return {hs.h, hs.l + base.l + 2 * std::fma(uh * v, P, ul)};
}

// R_C(1, 1 + e) - 1 for |e| >= 0.01 in double-double (DLMF 19.2.8-9: atan(r)/r with r = sqrt(e)
// for e > 0, atanh(r)/r = log((1 + r)/(1 - r))/(2r) with r = sqrt(-e) for e < 0; |e| < 1 for
// the duplication's e_k). Only the first duplication steps reach it; in double the closed forms'
// rounding (1 ulp of R_C) alone costs the final result up to 3 ulp at the domain's corners.
__attribute__((noinline, target(DL_ISA))) DD rc_minus_1_large(DD e) {
  if (e.h > 0) {
    const DD r = sqrt_dd(e);
    const DD at = atan_dd(r);
    return mul(add(at, DD{-r.h, -r.l}), recip(r));
  }
  const DD r = sqrt_dd(DD{-e.h, -e.l});
  // 1 - r is exact in its hi part (Sterbenz), so its lo is r's: renormalised for recip.
  const DD ratio = mul(add(DD{1, 0}, r), recip(normalize(add(DD{1, 0}, DD{-r.h, -r.l}))));
  const DD lg = log_dd(ratio);  // 2 atanh(r)
  return add(mul(lg, recip(scale(r, 2))), DD{-1, 0});
}

// R_C(1, 1 + e) - 1 by its Maclaurin series in e (DLMF 19.2.8's atan(r)/r = sum (-e)^k/(2k+1))
// for |e| < 0.01, without the leading 1 (so it carries no rounding of 1): ten terms (the first
// omitted one, e^10/21, is below 2^-70 relative to 1), five below |e| = 2e-4.
DL_INLINE double rc_minus_1_small(double e) {
  const double e2 = e * e;
  if (std::fabs(e) < 2e-4)
    return e * (std::fma(e, 1.0 / 5, -1.0 / 3) + e2 * std::fma(e, 1.0 / 9, -1.0 / 7));
  const double e4 = e2 * e2;
  return e * ((std::fma(e, 1.0 / 5, -1.0 / 3) + e2 * std::fma(e, 1.0 / 9, -1.0 / 7)) +
              e4 * (std::fma(e, 1.0 / 13, -1.0 / 11) + e2 * std::fma(e, 1.0 / 17, -1.0 / 15) +
                    e4 * std::fma(e, 1.0 / 21, -1.0 / 19)));
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
// sqrt(a) = h + (a - h^2) / (2h) (all lanes > 0 here).
#if DL_RCP14
// 1/h from AVX-512VL's estimate (relative error below 2^-14): it only scales the correction,
// |a - h^2 + a.l| / (2h) < 2^-52 h, so the pair's error grows by less than 2^-66 h, and the
// divider, shared by every division and square root, serves the square root alone. (A 2% error
// in this factor instead costs 6 ulp on the table: EllipticReference.Pi* would fail.)
DL_INLINE DD4 sqrt_dd(DD4 a) {
  const __m256d h = _mm256_sqrt_pd(a.h);
  const __m256d r = _mm256_add_pd(_mm256_fnmadd_pd(h, h, a.h), a.l);
  return {h, _mm256_mul_pd(r, _mm256_mul_pd(_mm256_set1_pd(0.5), _mm256_rcp14_pd(h)))};
}
#else
// 1/(2h) = h / (2a): the division 1/(2a) is issued with the square root instead of after it
// (both sit on the loop's critical path otherwise).
DL_INLINE DD4 sqrt_dd(DD4 a) {
  const __m256d inv = _mm256_div_pd(_mm256_set1_pd(0.5), a.h);
  const __m256d h = _mm256_sqrt_pd(a.h);
  const __m256d r = _mm256_add_pd(_mm256_fnmadd_pd(h, h, a.h), a.l);
  return {h, _mm256_mul_pd(r, _mm256_mul_pd(h, inv))};
}
#endif
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

DL_INLINE double pow2(int k) {  // 2^k, 0 <= k < 1024
  return std::bit_cast<double>(static_cast<uint64_t>(1023 + k) << 52);
}

// The kernel's series tails go to degree 9 (rf_series_tail9, rj_series_tail9 in elliptic.h),
// so that its duplication may stop at tolerance 0.03 instead of 0.01 (log_4 3 = 0.8 steps
// fewer). Their truncation error scales as tol^10. Checked by mutation: zeroing a degree-8
// coefficient (R_J's E2^4) gives 23 ulp on the table, tolerance 0.05 gives 3 ulp (both fail
// EllipticReference.Pi*); the degree-9 terms are margin, below what the tables resolve at 0.03
// (EllipticReference.SeriesTailsOfDegree9 checks them directly).
constexpr double kKernelTolerance = 0.03;

// (p - x)(p - y)(p - 1) in double-double (differences first: they keep their relative accuracy).
DL_INLINE DD pxyz_dd(DD p, DD x, DD y) {
  return mul(mul(add(p, DD{-x.h, -x.l}), add(p, DD{-y.h, -y.l})), add(p, DD{-1, 0}));
}

DL_TARGET void rf_rj_dd(DD x, DD delta2, DD p, DD& rf, DD& rj) {
  DD4 v = {_mm256_setr_pd(x.h, delta2.h, 1.0, p.h), _mm256_setr_pd(x.l, delta2.l, 0.0, p.l)};
  // Stopping rule and tail inputs from the hi parts: the tails need a few correct digits only.
  const double x0 = x.h, y0 = delta2.h, p0 = p.h;
  const double AF0 = (x0 + y0 + 1) * (1.0 / 3), AJ0 = (x0 + y0 + 1 + 2 * p0) * 0.2;
  const double dFx = AF0 - x0, dFy = AF0 - y0, dJx = AJ0 - x0, dJy = AJ0 - y0, dJz = AJ0 - 1;
  // delta = (p - x)(p - y)(p - z) from the double-double arguments: where p is close to x or y,
  // p.h - x.h is exact (Sterbenz) and the lo parts' difference keeps the relative accuracy that
  // e_k below inherits. The double-double delta (for the closed forms of R_C) is formed only
  // where those are needed.
  const double delta =
      (p.h - x.h + (p.l - x.l)) * (p.h - delta2.h + (p.l - delta2.l)) * (p.h - 1 + p.l);
  const double inv_tol = 1 / kKernelTolerance;
  const double qF =
      std::max(std::fabs(dFx), std::max(std::fabs(dFy), std::fabs(AF0 - 1))) * inv_tol;
  const double qJ = std::max(std::max(std::fabs(dJx), std::fabs(dJy)),
                             std::max(std::fabs(dJz), std::fabs(AJ0 - p0))) *
                    inv_tol;
  const double lambda_stop = std::max(qF - AF0, qJ - AJ0);  // step while Lambda < lambda_stop
  double Lambda = 0;
  int k = 0;
  // sum_j 2^j R_C(1, 1 + e_j) / d'_j, accumulated as U = sum_j 2^(j-k+1) (...) (halved, then
  // added to, each step; 2^(k-1) U at the end), so that no power of 2 is carried in the loop.
  DD sum = {0, 0};
  // Steps whose |e_k| >= 0.01 need the closed forms of R_C (rc_minus_1_large, a call): they are
  // deferred past the loop, since a call inside it makes the compiler keep the loop's state in
  // memory. |e_k| decreases with k (each factor (sqrt p - sqrt x_j)/(sqrt p + sqrt x_j) does), so
  // they are the first steps: none or one for most inputs, more at the corners (x = c^2 down to
  // 1e-32). The fifth and later are done in place (the Pi table and the corner sweep of
  // EllipticReference reach that path).
  constexpr int kMaxDeferred = 4;
  DD deferred_term[kMaxDeferred], deferred_e[kMaxDeferred];
  int n_deferred = 0;
  while (Lambda < lambda_stop) {
    const DD4 s = sqrt_dd(v);  // sx sy sz sp
    // lambda = sx sy + sy sz + sz sx in every lane, as a b + b c + c a with (a, b, c) the lanes
    // of s rotated (one permute level instead of a horizontal sum and a broadcast).
    const DD4 a = permute<lanes(0, 1, 2, 0)>(s), b = permute<lanes(1, 2, 0, 1)>(s),
              c = permute<lanes(2, 0, 1, 2)>(s);
    const DD4 ab = mul(a, b), bc = mul(b, c), ca = mul(c, a);
    const DD4 ab_bc = add(ab, bc);
    // d = (sp + sx)(sp + sy)(sp + sz) (lane 0).
    const DD4 w = add(s, permute<lanes(3, 3, 3, 3)>(s));
    const DD4 d4 = mul(mul(w, permute<lanes(1, 3, 3, 3)>(w)), permute<lanes(2, 3, 3, 3)>(w));
    Lambda += _mm256_cvtsd_f64(_mm256_add_pd(ab_bc.h, ca.h));
    v = add(ab_bc, add(v, ca));  // (ab + bc) + (v + ca): one addition less on the path
    const DD inv_d = recip(lane0(d4));
    const double e = delta * inv_d.h * inv_d.h;
    if (std::fabs(e) < 0.01) [[likely]] {
      // inv_d R_C = inv_d + inv_d (R_C - 1), |R_C - 1| < 0.004: the second term in double is
      // accurate to 2^-61 of the first; the pair goes unnormalised into the sum's two-sum.
      sum = add(scale(sum, 0.5), DD{inv_d.h, std::fma(inv_d.h, rc_minus_1_small(e), inv_d.l)});
    } else if (n_deferred < kMaxDeferred) {
      sum = scale(sum, 0.5);
      deferred_term[n_deferred] = scale(inv_d, pow2(k));
      deferred_e[n_deferred++] = mul(inv_d, inv_d);  // e = delta / d'^2
    } else {
      const DD rc1 = rc_minus_1_large(mul(pxyz_dd(p, x, delta2), mul(inv_d, inv_d)));
      sum = add(scale(sum, 0.5), add(inv_d, mul(inv_d, rc1)));
    }
    ++k;
  }
  const double two_k = pow2(k);
  sum = scale(sum, 0.5 * two_k);
  if (n_deferred != 0) {
    const DD delta_dd = pxyz_dd(p, x, delta2);
    for (int i = 0; i < n_deferred; ++i) {
      const DD rc1 = rc_minus_1_large(mul(delta_dd, deferred_e[i]));
      sum = add(sum, add(deferred_term[i], mul(deferred_term[i], rc1)));
    }
  }
  alignas(32) double hi[4], lo[4];
  _mm256_store_pd(hi, v.h);
  _mm256_store_pd(lo, v.l);
  const DD xyz = add(add(DD{hi[0], lo[0]}, DD{hi[1], lo[1]}), DD{hi[2], lo[2]});
  // A'^-1/2 from the double A' = A_0 + Lambda (h), corrected once with the double-double A':
  // A'^-1/2 = h (1 + e/2), e = 1 - A' h^2 (|e| ~ 1e-16, so e^2 terms are below 2^-100); then
  // A_k^-1/2 = 2^k A'^-1/2.
  const double AF = AF0 + Lambda, AJ = AJ0 + Lambda;
  const double inv_AF = 1 / AF, inv_AJ = 1 / AJ;
  const double hF = std::sqrt(AF) * inv_AF, hJ = std::sqrt(AJ) * inv_AJ;
  {
    const DD A = mul(xyz, kThird);
    const DD t = two_prod(hF, hF);
    const double e = std::fma(-A.h, t.h, 1.0) - A.h * t.l - A.l * t.h;
    // X_j = (A_k - x_j,k)/A_k = (A_0 - x_j,0)/A'_k.
    const double X = dFx * inv_AF, Y = dFy * inv_AF, Z = -(X + Y);
    const double tail = rf_series_tail9(X * Y - Z * Z, X * Y * Z);
    const double head = hF * two_k;
    rf = {head, head * (0.5 * e + tail)};
  }
  {
    const DD A = mul(add(xyz, scale(DD{hi[3], lo[3]}, 2)), kFifth);
    const DD t = two_prod(hJ, hJ);
    const double e = std::fma(-A.h, t.h, 1.0) - A.h * t.l - A.l * t.h;
    const DD h3 = mul(t, hJ);  // A'^-3/2 = h^3 (1 + 3e/2); A_k^-3/2 4^-k = 2^k A'^-3/2
    const double tail = rj_series_tail9(dJx * inv_AJ, dJy * inv_AJ, dJz * inv_AJ);
    const double head = h3.h * two_k;
    rj = add(DD{head, h3.l * two_k + head * (1.5 * e + tail)}, mul(sum, 6.0));
  }
}

DL_TARGET double pi_dd(double n, DD omn, double phi, double m, DD omm) {
  DD s, c;
  sincos_dd(phi, s, c);
  const DD s2 = mul(s, s), c2 = mul(c, c);
  // Delta^2 = 1 - m s^2 = c^2 + (1 - m) s^2 (the second form where the first cancels).
  const DD delta2 = m <= 0.5 ? add(DD{1, 0}, mul(s2, -m)) : add(c2, mul(s2, omm));
  const DD s3 = mul(s2, s);
  DD rf, rj;
  // For -1 <= n < 0 the two terms have opposite signs but cancel by a factor 2 at most (Pi >= F/2
  // there), a bit that double-double arithmetic can spare: no A&S 17.7.15 and no atan.
  if (n >= -1) {
    const DD p = n <= 0.5 ? add(DD{1, 0}, mul(s2, -n)) : add(c2, mul(s2, omn));
    const DD kj = mul(s3, mul(kThird, n));  // (n/3) s^3
    rf_rj_dd(c2, delta2, p, rf, rj);
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
  const DD arg = mul(mul(g, mul(s, c)), recip(sqrt_dd(delta2)));
  const DD term_atan = mul(mul(g, recip(mn)), atan_dd(arg));
  rf_rj_dd(c2, delta2, pN, rf, rj);
  return value(add(add(mul(rf, k1), mul(rj, kj)), term_atan));
}

}  // namespace

namespace DL_KERNEL_NS {

DL_TARGET double pi(double n, DoubleDouble one_minus_n, double phi, double m,
                    DoubleDouble one_minus_m) noexcept {
  return pi_dd(n, DD{one_minus_n.hi, one_minus_n.lo}, phi, m, DD{one_minus_m.hi, one_minus_m.lo});
}
// The complements as exact pairs (two-sums), formed only on the branches that use them.
DL_TARGET double pi(double n, double phi, double m) noexcept {
  return pi_dd(n, two_sum(1.0, -n), phi, m, two_sum(1.0, -m));
}
DL_TARGET void sincos(double phi, DoubleDouble& sin_phi, DoubleDouble& cos_phi) noexcept {
  DD s, c;
  sincos_dd(phi, s, c);
  sin_phi = {s.h, s.l};
  cos_phi = {c.h, c.l};
}
DL_TARGET DoubleDouble atan(DoubleDouble x) noexcept {
  const DD r = atan_dd(DD{x.hi, x.lo});
  return {r.h, r.l};
}
DL_TARGET DoubleDouble log(DoubleDouble x) noexcept {
  const DD r = log_dd(DD{x.hi, x.lo});
  return {r.h, r.l};
}
DL_TARGET DoubleDouble rc_minus_1(DoubleDouble e) noexcept {
  const DD r = rc_minus_1_large(DD{e.hi, e.lo});
  return {r.h, r.l};
}

}  // namespace DL_KERNEL_NS

}  // namespace disklab::math::detail

#undef DL_TARGET
#undef DL_INLINE
