// The entry points of the two compiled copies of the double-double Pi and F kernels
// (elliptic_pi_dd_kernel.inc): pi_avx2 (AVX2 + FMA) and pi_avx512 (the same plus AVX-512VL).
// Private to lib/src/math; elliptic_pi_dd.cpp dispatches to them.
#pragma once

#include "elliptic_pi_dd.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define DISKLAB_PI_DD 1
#else
#define DISKLAB_PI_DD 0
#endif

#define DISKLAB_PI_DD_ENTRY_POINTS                                                \
  double pi(double n, DoubleDouble one_minus_n, double phi, double m,             \
            DoubleDouble one_minus_m) noexcept;                                   \
  double pi(double n, double phi, double m) noexcept;                             \
  void sincos(double phi, DoubleDouble& sin_phi, DoubleDouble& cos_phi) noexcept; \
  DoubleDouble atan(DoubleDouble x) noexcept;                                     \
  DoubleDouble log(DoubleDouble x) noexcept;                                      \
  DoubleDouble rc_minus_1(DoubleDouble e) noexcept;                               \
  double f(double phi, double m, DoubleDouble one_minus_m) noexcept;              \
  double f(double phi, double m) noexcept;                                        \
  double f_series(double e2, double e3) noexcept;                                 \
  double f_small_eps(double phi, double m) noexcept;                              \
  DoubleDouble f_complement(double phi, double m) noexcept;                       \
  DoubleDouble k_complete(double m) noexcept;

namespace disklab::math::detail {
namespace pi_avx2 {
DISKLAB_PI_DD_ENTRY_POINTS
}  // namespace pi_avx2
namespace pi_avx512 {
DISKLAB_PI_DD_ENTRY_POINTS
}  // namespace pi_avx512
}  // namespace disklab::math::detail

#undef DISKLAB_PI_DD_ENTRY_POINTS
