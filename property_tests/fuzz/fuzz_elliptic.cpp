// libFuzzer: the elliptic integrals (math/elliptic.h) on any doubles. Contracts: in the domain
// (finite phi, finite m <= 1, n <= 1) F and Pi are not NaN and keep F's oddness exactly; outside it
// they are NaN; where F runs its double-double kernel (0 < |phi| <= pi/2, m in [0, 1]; its three
// paths) it is within one ulp of the portable long-double path, both being faithfully rounded;
// Carlson's R_F, R_D, R_J of non-negative finite arguments are >= 0 or +inf, never NaN (0 where
// they underflow); no crash, no undefined behaviour (UBSan), no out-of-bounds access (ASan).
#include <cmath>

#include "disklab/math/elliptic.h"
#include "fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  disklab::fuzz::Bytes in(data, size);
  const double n = in.any_double(), phi = in.any_double(), m = in.any_double();
  const double x = std::abs(in.any_double()), y = std::abs(in.any_double());
  const double z = std::abs(in.any_double()), p = std::abs(in.any_double());
  namespace math = disklab::math;
  const double f = math::ellint_f(phi, m);
  const double pi = math::ellint_pi(n, phi, m);
  const bool domain_f = std::isfinite(phi) && std::isfinite(m) && m <= 1.0;
  const bool domain_pi = domain_f && n <= 1.0 && std::isfinite(n);
  if (domain_f) {
    FUZZ_CHECK(!std::isnan(f));
    FUZZ_CHECK(math::ellint_f(-phi, m) == -f);  // odd, exactly
    if (phi >= 0.0) FUZZ_CHECK(f >= 0.0);
    const double a = std::fabs(phi);
    if (a > 0.0 && a <= 1.5707963267948966 && m >= 0.0) {
      // Two faithfully rounded values of one number are equal or adjacent doubles.
      const double portable = math::detail::ellint_f_core(a, m, 1.0 - m);
      FUZZ_CHECK(std::fabs(std::fabs(f) - portable) <=
                 std::nextafter(portable, INFINITY) - portable);
    }
  } else if (std::isnan(phi) || std::isnan(m) || m > 1.0) {
    FUZZ_CHECK(std::isnan(f));
  }
  if (domain_pi && n < 1.0 && m < 1.0) FUZZ_CHECK(!std::isnan(pi));
  if (std::isfinite(x) && std::isfinite(y) && std::isfinite(z) && std::isfinite(p)) {
    // At most one of x, y, z zero for R_F (two zeros diverge): then positive or +inf.
    const int zeros = (x == 0.0) + (y == 0.0) + (z == 0.0);
    if (zeros <= 1) FUZZ_CHECK(math::carlson_rf(x, y, z) >= 0.0);
    if (zeros <= 1 && z > 0.0) FUZZ_CHECK(math::carlson_rd(x, y, z) >= 0.0);
    if (zeros <= 1 && p > 0.0) FUZZ_CHECK(math::carlson_rj(x, y, z, p) >= 0.0);
  }
  return 0;
}
