// Which compiled copy of the double-double Pi kernel (elliptic_pi_dd_kernel.h) runs: the best
// this CPU supports, chosen once during static initialisation.
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

PiDdEntry entry_of(PiKernel kernel) {
#if DISKLAB_PI_DD
  switch (kernel) {
    case PiKernel::kAvx2Fma:
      return static_cast<PiDdEntry>(&pi_avx2::pi);
    case PiKernel::kAvx512:
      return static_cast<PiDdEntry>(&pi_avx512::pi);
    case PiKernel::kNone:
      break;
  }
#endif
  return nullptr;
}

// The best copy this CPU runs (initialised after cpu_support: same translation unit, later).
PiKernel kernel_in_use = runs(PiKernel::kAvx512)    ? PiKernel::kAvx512
                         : runs(PiKernel::kAvx2Fma) ? PiKernel::kAvx2Fma
                                                    : PiKernel::kNone;

}  // namespace

// Read by ellint_pi<double> on every call.
PiDdEntry pi_dd_entry = entry_of(kernel_in_use);

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
  return true;
}

#if DISKLAB_PI_DD

double ellint_pi_dd(double n, double one_minus_n, double one_minus_n_lo, double phi, double m,
                    double one_minus_m, double one_minus_m_lo) noexcept {
  return ellint_pi_dd(kernel_in_use, n, one_minus_n, one_minus_n_lo, phi, m, one_minus_m,
                      one_minus_m_lo);
}

double ellint_pi_dd(PiKernel kernel, double n, double one_minus_n, double one_minus_n_lo,
                    double phi, double m, double one_minus_m, double one_minus_m_lo) noexcept {
  const DoubleDouble omn = {one_minus_n, one_minus_n_lo}, omm = {one_minus_m, one_minus_m_lo};
  switch (kernel) {
    case PiKernel::kAvx512:
      if (runs(kernel)) return pi_avx512::pi(n, omn, phi, m, omm);
      break;
    case PiKernel::kAvx2Fma:
      if (runs(kernel)) return pi_avx2::pi(n, omn, phi, m, omm);
      break;
    case PiKernel::kNone:
      break;
  }
  return kNaN;
}

double ellint_pi_dd(PiKernel kernel, double n, double phi, double m) noexcept {
  const PiDdEntry entry = runs(kernel) ? entry_of(kernel) : nullptr;
  return entry != nullptr ? entry(n, phi, m) : kNaN;
}

void pi_dd_sincos(PiKernel kernel, double phi, DoubleDouble& sin_phi,
                  DoubleDouble& cos_phi) noexcept {
  if (!runs(kernel)) {
    sin_phi = cos_phi = {kNaN, 0};
    return;
  }
  (kernel == PiKernel::kAvx512 ? pi_avx512::sincos : pi_avx2::sincos)(phi, sin_phi, cos_phi);
}
DoubleDouble pi_dd_atan(PiKernel kernel, DoubleDouble x) noexcept {
  if (!runs(kernel)) return {kNaN, 0};
  return kernel == PiKernel::kAvx512 ? pi_avx512::atan(x) : pi_avx2::atan(x);
}
DoubleDouble pi_dd_log(PiKernel kernel, DoubleDouble x) noexcept {
  if (!runs(kernel)) return {kNaN, 0};
  return kernel == PiKernel::kAvx512 ? pi_avx512::log(x) : pi_avx2::log(x);
}
DoubleDouble pi_dd_rc_minus_1(PiKernel kernel, DoubleDouble e) noexcept {
  if (!runs(kernel)) return {kNaN, 0};
  return kernel == PiKernel::kAvx512 ? pi_avx512::rc_minus_1(e) : pi_avx2::rc_minus_1(e);
}

#else  // no x86-64 kernel in this build: the portable path is always used

double ellint_pi_dd(double, double, double, double, double, double, double) noexcept {
  return kNaN;
}
double ellint_pi_dd(PiKernel, double, double, double, double, double, double, double) noexcept {
  return kNaN;
}
double ellint_pi_dd(PiKernel, double, double, double) noexcept {
  return kNaN;
}
void pi_dd_sincos(PiKernel, double, DoubleDouble& sin_phi, DoubleDouble& cos_phi) noexcept {
  sin_phi = cos_phi = {kNaN, 0};
}
DoubleDouble pi_dd_atan(PiKernel, DoubleDouble) noexcept {
  return {kNaN, 0};
}
DoubleDouble pi_dd_log(PiKernel, DoubleDouble) noexcept {
  return {kNaN, 0};
}
DoubleDouble pi_dd_rc_minus_1(PiKernel, DoubleDouble) noexcept {
  return {kNaN, 0};
}

#endif

}  // namespace disklab::math::detail
