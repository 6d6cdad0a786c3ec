// Which compiled copy of the double-double Pi and F kernels (elliptic_pi_dd_kernel.inc) runs: the
// best this CPU supports, chosen once during static initialisation.
#include <limits>

#include "elliptic_pi_dd_entry.h"

namespace disklab::math::detail {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// What this CPU runs, probed once (all false until then: a call from another static
// initialiser takes the portable path).
struct CpuSupport {
  bool avx2_fma = false, avx512vl = false;
};
const CpuSupport cpu_support = [] {
  CpuSupport s;
#if DISKLAB_PI_DD
  __builtin_cpu_init();  // static initialisers may run before libgcc's own CPU probe
  s.avx2_fma = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  s.avx512vl = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
#endif
  return s;
}();

bool runs(PiKernel kernel) {
  switch (kernel) {
    case PiKernel::kAvx2Fma:
      return cpu_support.avx2_fma;
    case PiKernel::kAvx512:
      return cpu_support.avx2_fma && cpu_support.avx512vl;
    case PiKernel::kNone:
      break;
  }
  return false;
}

// One copy's entry points (elliptic_pi_dd_entry.h).
struct Copy {
  double (*pi_pairs)(double, DoubleDouble, double, double, DoubleDouble) noexcept;
  PiDdEntry pi;
  void (*sincos)(double, DoubleDouble&, DoubleDouble&) noexcept;
  DoubleDouble (*atan)(DoubleDouble) noexcept;
  DoubleDouble (*log)(DoubleDouble) noexcept;
  DoubleDouble (*rc_minus_1)(DoubleDouble) noexcept;
  double (*f_pairs)(double, double, DoubleDouble) noexcept;
  FDdEntry f;
  double (*f_series)(double, double) noexcept;
  double (*f_small_eps)(double, double) noexcept;
  DoubleDouble (*f_complement)(double, double) noexcept;
  DoubleDouble (*k_complete)(double) noexcept;
};
#if DISKLAB_PI_DD
#define DL_COPY(ns)                                                                      \
  Copy {                                                                                 \
    &ns::pi, &ns::pi, &ns::sincos, &ns::atan, &ns::log, &ns::rc_minus_1, &ns::f, &ns::f, \
        &ns::f_series, &ns::f_small_eps, &ns::f_complement, &ns::k_complete              \
  }
constexpr Copy kAvx2Copy = DL_COPY(pi_avx2), kAvx512Copy = DL_COPY(pi_avx512);
#undef DL_COPY
#endif

// The given copy's entry points, or nullptr where this CPU (or build) does not run it.
const Copy* copy_of(PiKernel kernel) {
  if (!runs(kernel)) return nullptr;
#if DISKLAB_PI_DD
  return kernel == PiKernel::kAvx512 ? &kAvx512Copy : &kAvx2Copy;
#else
  return nullptr;
#endif
}

PiDdEntry entry_of(PiKernel kernel) {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->pi : nullptr;
}
FDdEntry f_entry_of(PiKernel kernel) {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->f : nullptr;
}

// The best copy this CPU runs (initialised after cpu_support: same translation unit, later).
PiKernel kernel_in_use = runs(PiKernel::kAvx512)    ? PiKernel::kAvx512
                         : runs(PiKernel::kAvx2Fma) ? PiKernel::kAvx2Fma
                                                    : PiKernel::kNone;

}  // namespace

// Read by ellint_pi<double> and ellint_f<double> on every call.
PiDdEntry pi_dd_entry = entry_of(kernel_in_use);
FDdEntry f_dd_entry = f_entry_of(kernel_in_use);

PiKernel pi_dd_kernel() noexcept {
  return kernel_in_use;
}
bool pi_dd_kernel_available() noexcept {
  return pi_dd_entry != nullptr;
}
bool pi_dd_kernel_supported(PiKernel kernel) noexcept {
  return runs(kernel);
}
const char* pi_dd_kernel_name(PiKernel kernel) noexcept {
  switch (kernel) {
    case PiKernel::kAvx2Fma:
      return "AVX2+FMA";
    case PiKernel::kAvx512:
      return "AVX2+FMA+AVX-512VL";
    case PiKernel::kNone:
      break;
  }
  return "none";
}
bool use_pi_dd_kernel(PiKernel kernel) noexcept {
  if (kernel != PiKernel::kNone && !runs(kernel)) return false;
  kernel_in_use = kernel;
  pi_dd_entry = entry_of(kernel);
  f_dd_entry = f_entry_of(kernel);
  return true;
}

double ellint_pi_dd(double n, double one_minus_n, double one_minus_n_lo, double phi, double m,
                    double one_minus_m, double one_minus_m_lo) noexcept {
  return ellint_pi_dd(kernel_in_use, n, one_minus_n, one_minus_n_lo, phi, m, one_minus_m,
                      one_minus_m_lo);
}
double ellint_pi_dd(PiKernel kernel, double n, double one_minus_n, double one_minus_n_lo,
                    double phi, double m, double one_minus_m, double one_minus_m_lo) noexcept {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->pi_pairs(n, {one_minus_n, one_minus_n_lo}, phi, m,
                                          {one_minus_m, one_minus_m_lo})
                         : kNaN;
}
double ellint_pi_dd(PiKernel kernel, double n, double phi, double m) noexcept {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->pi(n, phi, m) : kNaN;
}

double ellint_f_dd(double phi, double m, double one_minus_m) noexcept {
  return ellint_f_dd(kernel_in_use, phi, m, one_minus_m, 0.0);
}
double ellint_f_dd(PiKernel kernel, double phi, double m, double one_minus_m,
                   double one_minus_m_lo) noexcept {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->f_pairs(phi, m, {one_minus_m, one_minus_m_lo}) : kNaN;
}
double ellint_f_dd(PiKernel kernel, double phi, double m) noexcept {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->f(phi, m) : kNaN;
}
double f_dd_series(PiKernel kernel, double e2, double e3) noexcept {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->f_series(e2, e3) : kNaN;
}
double f_dd_small_eps(PiKernel kernel, double phi, double m) noexcept {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->f_small_eps(phi, m) : kNaN;
}
DoubleDouble f_dd_complement(PiKernel kernel, double phi, double m) noexcept {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->f_complement(phi, m) : DoubleDouble{kNaN, 0};
}
DoubleDouble k_dd_complete(PiKernel kernel, double m) noexcept {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->k_complete(m) : DoubleDouble{kNaN, 0};
}

void pi_dd_sincos(PiKernel kernel, double phi, DoubleDouble& sin_phi,
                  DoubleDouble& cos_phi) noexcept {
  if (const Copy* copy = copy_of(kernel))
    copy->sincos(phi, sin_phi, cos_phi);
  else
    sin_phi = cos_phi = {kNaN, 0};
}
DoubleDouble pi_dd_atan(PiKernel kernel, DoubleDouble x) noexcept {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->atan(x) : DoubleDouble{kNaN, 0};
}
DoubleDouble pi_dd_log(PiKernel kernel, DoubleDouble x) noexcept {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->log(x) : DoubleDouble{kNaN, 0};
}
DoubleDouble pi_dd_rc_minus_1(PiKernel kernel, DoubleDouble e) noexcept {
  const Copy* copy = copy_of(kernel);
  return copy != nullptr ? copy->rc_minus_1(e) : DoubleDouble{kNaN, 0};
}

}  // namespace disklab::math::detail
