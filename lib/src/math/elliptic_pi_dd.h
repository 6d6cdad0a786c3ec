#pragma once
// The double-double Pi kernel's dispatch and its hooks for tests and benchmarks: which compiled
// copy runs (AVX2 + FMA, or AVX2 + FMA + AVX-512VL), a way to choose another, each copy's entry
// points and elementary functions, and the degree-9 series tails only the kernel uses. PRIVATE
// to the project (lib/src is not installed): the library's own sources, the tests, the
// benchmarks and the CLI include it; ellint_pi<double> needs only what elliptic_legendre.h
// declares. The kernel itself is elliptic_pi_dd_kernel.inc, the dispatch elliptic_pi_dd.cpp.
#include "disklab/math/elliptic_legendre.h"

namespace disklab::math::detail {

// The kernel is compiled twice: for AVX2 + FMA, and for AVX2 + FMA + AVX-512VL (whose reciprocal
// estimate spares a division per duplication step). The best copy the CPU runs is chosen once,
// at start-up: pi_dd_kernel() (kNone: none, the portable path only).
enum class PiKernel { kNone, kAvx2Fma, kAvx512 };
PiKernel pi_dd_kernel() noexcept;
bool pi_dd_kernel_supported(PiKernel kernel) noexcept;    // compiled in, and this CPU runs it
const char* pi_dd_kernel_name(PiKernel kernel) noexcept;  // "AVX2+FMA", ...
bool pi_dd_kernel_available() noexcept;                   // pi_dd_kernel() != kNone
// For tests and benchmarks: makes ellint_pi<double> and ellint_f<double> run the given copy from
// now on (kNone: the portable paths). Not thread-safe (no evaluation may run meanwhile); false, and
// no change, where the copy is not supported.
bool use_pi_dd_kernel(PiKernel kernel) noexcept;
// ellint_pi_dd (elliptic_legendre.h) in the given copy, with the complements as hi + lo pairs,
// or formed exactly from n and m (the copy's pi_dd_entry). NaN where the copy is not supported.
double ellint_pi_dd(PiKernel kernel, double n, double one_minus_n, double one_minus_n_lo,
                    double phi, double m, double one_minus_m, double one_minus_m_lo) noexcept;
double ellint_pi_dd(PiKernel kernel, double n, double phi, double m) noexcept;
// F's kernel (ellint_f_dd in elliptic_legendre.h) in the given copy: phi in (0, pi/2], m in
// [0, 1], with 1 - m as a hi + lo pair or formed exactly from m; and its series G(e2, e3) (see
// the kernel). NaN where the copy is not supported.
double ellint_f_dd(PiKernel kernel, double phi, double m, double one_minus_m,
                   double one_minus_m_lo) noexcept;
double ellint_f_dd(PiKernel kernel, double phi, double m) noexcept;
double f_dd_series(PiKernel kernel, double e2, double e3) noexcept;
// F's kernel takes its series once the spread of the roots, (max - min) / mean, is at most
// kFKernelSpread; their deviations d_j from the mean (sum 0) are then at most 2/3 of it, the
// series' range kFKernelSeriesRange.
inline constexpr double kFKernelSpread = 0.3;
inline constexpr double kFKernelSeriesRange = 2 * kFKernelSpread / 3;
// A double-double, value hi + lo, as the hooks below return it.
struct DoubleDouble {
  double hi, lo;
};
// At phi <= kFSmallPhi F's kernel takes no sin, cos or duplication step: F = phi (1 + eps), with
// eps in plain double from Taylor series in phi^2 and the same series in the roots (their
// deviations stay within kFKernelSeriesRange up to phi = acos(0.75) = 0.7227). f_dd_small_eps
// returns that eps (m in [0, 1]), and kFSmallEpsBound bounds its absolute error, which is F's
// relative error before the one rounding (the derivation is at f_small_eps in the kernel).
inline constexpr double kFSmallPhi = 0.72;
inline constexpr double kFSmallEpsBound = 0.375 * 0x1p-53;
double f_dd_small_eps(PiKernel kernel, double phi, double m) noexcept;
// Near phi = pi/2 F's kernel takes the complement, F(phi|m) = K(m) - F(psi|m), with F(psi|m)
// from f_small_eps at chi = pi/2 - phi and m' = -m/(1 - m), where chi^2 <= kFComplementRegion
// (1 - m) and 1 - m >= 1/16; K(m) by piecewise polynomials (lib/src/math/elliptic_k_table.inc).
// f_dd_complement returns that path's value before its one rounding, as a pair (for any phi in
// (pi/4, pi/2] and m in [0, 15/16]; outside the region it is not F), within kFComplementBound
// relative of F in the region; k_dd_complete returns K(m), m in [0, 15/16], within
// kKCompleteBound relative. Derivations at f_complement in the kernel.
inline constexpr double kFComplementRegion = 0.54;
inline constexpr double kFComplementBound = 0.44 * 0x1p-53;
inline constexpr double kKCompleteBound = 0.05 * 0x1p-53;
DoubleDouble f_dd_complement(PiKernel kernel, double phi, double m) noexcept;
DoubleDouble k_dd_complete(PiKernel kernel, double m) noexcept;
// The kernel's double-double elementary functions in the given copy, exported for their
// accuracy tests (results as {hi, lo} pairs; NaN where the copy is not supported): sin and cos
// of phi in [0, pi/2], atan of x >= 0, log of x >= 1, and R_C(1, 1 + e) - 1 for
// 0.01 <= |e| < 1.
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

// The series tails of R_F and R_J (rf_series_tail, rj_series_tail in elliptic_carlson.h) through
// degree 9, for the kernel, which stops its duplication at tolerance 0.03 instead of 0.01. The
// degree-N term of Carlson's expansion is (a)_N/(b)_N times the degree-N part of
// (1 + E2 - E3 + E4 - E5)^-1/2: 1/(2N+1) for R_F (a = 1/2, b = 3/2) and 3/(2N+3) for R_J
// (a = 3/2, b = 5/2); through degree 7 this reproduces the coefficients of the degree-7 tails
// (repeated here: written as the degree-7 tails plus the degree-8 and -9 terms, the kernel
// measured slower in bench_elliptic Pi/mixed). EllipticReference.SeriesTailsOfDegree9 checks
// them against 50-digit R_F and R_J.
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

}  // namespace disklab::math::detail
