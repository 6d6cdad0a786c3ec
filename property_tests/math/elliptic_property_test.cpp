// Properties of the elliptic integrals over the domain (m in [0,1), n < 1, phi in [0, pi/2]):
// agreement with Boost.Math (both policies), identities of Carlson's and Legendre's forms,
// the cancellation-free difference forms against 50-digit evaluation, defined behaviour
// outside the domain. rapidcheck prints the seed of a failure; replay with
// RC_PARAMS="seed=<seed>" build/<preset>/bin/test_math --gtest_filter=<test>.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "disklab/math/elliptic.h"
#include "math/elliptic_domain.h"
#include "math/elliptic_pi_dd.h"  // lib/src: the Pi kernel's private hooks

namespace disklab::test {
namespace {

using Real50 = boost::multiprecision::cpp_bin_float_50;
using boost_double_policy =
    boost::math::policies::policy<boost::math::policies::promote_double<false>>;

constexpr double kEps = std::numeric_limits<double>::epsilon();
using elliptic_domain::kHalfPi;

// --- Tolerances (one place for this suite) ---------------------------------------------------
// Own vs Boost where Boost is well conditioned (k <= 0.95, -100 <= n <= 0.9; Boost forms 1 - k^2
// and 1 - n internally, so it cannot be asked about m, n -> 1): own is within 2 ulp (tables),
// Boost within a few eps there (measured max 3.5 eps double policy, 1.9 eps default, 2e5
// samples); 8 eps is their sum with margin.
constexpr double kBoostRelative = 8 * kEps;
// Identities between different evaluation paths of the same quantity: each side within ~2 ulp
// (long double loops), so 6 eps bounds their difference with margin.
constexpr double kIdentityRelative = 6 * kEps;
// Legendre's relation E K' + E' K - K K' = pi/2: the three products are each O(K K') with
// ~2 eps error, and K K' <= ~8 for m in [0.01, 0.99]; 16 eps (absolute) bounds their sum.
constexpr double kLegendreAbsolute = 16 * kEps;
// Difference forms vs (1-n) Pi - F, Pi - F evaluated in 50 digits: ~2 ulp plus the input
// rounding of 1 - n (0.5 ulp, sensitivity <= 1): 4 eps.
constexpr double kDifferenceRelative = 4 * kEps;
// (Pi(+-n) - F) / n -> D at n = 1e-9: besides the bound derived in the test (cancellation of Pi -
// F and the O(n) term), D itself comes from a separate R_D evaluation; 1e-6 relative covers the
// derivative's own O(n) curvature where 1 - m is not small.
constexpr double kNearZeroCharacteristicRel = 1e-6;
// Quasi-periodicity F(phi + pi) = F(phi) + 2K, Pi(phi - 2pi) = Pi(phi) - 4 Pi_c: each side is a
// few ulps of values up to ~5 K; 1e-14 relative to the complete integral bounds their difference.
constexpr double kQuasiPeriodRel = 1e-14;

double rel_diff(double a, double b) {
  return std::fabs(a - b) / std::fabs(b);
}

// Generators over the domain and its hard corners (the maps of elliptic_domain.h).
rc::Gen<double> gen_unit() {  // [0, 1)
  return rc::gen::map(rc::gen::inRange<int64_t>(0, int64_t(1) << 53),
                      [](int64_t i) { return std::ldexp(double(i), -53); });
}
template <class Map>
rc::Gen<double> gen_kinds(int kinds, Map map) {
  return rc::gen::apply(map, rc::gen::inRange(0, kinds), gen_unit());
}
rc::Gen<double> gen_phi() {
  return gen_kinds(elliptic_domain::kPhiKinds, elliptic_domain::phi);
}
rc::Gen<double> gen_m() {
  return gen_kinds(elliptic_domain::kMKinds, elliptic_domain::m);
}
rc::Gen<double> gen_n() {
  return gen_kinds(elliptic_domain::kNKinds, elliptic_domain::n);
}

RC_GTEST_PROP(EllipticProperty, AgreesWithBoostBothPolicies, ()) {
  const double k = 0.95 * *gen_unit();
  const double m = k * k;  // exactly what Boost squares
  const double n = -100 + 100.9 * *gen_unit();
  const double phi = kHalfPi * *gen_unit();
  const double own_pi = math::ellint_pi(n, phi, m), own_f = math::ellint_f(phi, m);
  const double b_pi_d = boost::math::ellint_3(k, n, phi, boost_double_policy());
  const double b_pi_l = boost::math::ellint_3(k, n, phi);
  const double b_f_d = boost::math::ellint_1(k, phi, boost_double_policy());
  const double b_f_l = boost::math::ellint_1(k, phi);
  RC_LOG() << "k=" << k << " m=" << m << " n=" << n << " phi=" << phi << " own Pi=" << own_pi
           << " boost(double)=" << b_pi_d << " boost(default)=" << b_pi_l << " own F=" << own_f
           << " boost F(double)=" << b_f_d << " boost F(default)=" << b_f_l;
  if (phi == 0) {
    RC_ASSERT(own_pi == 0.0 && own_f == 0.0);
    return;
  }
  RC_ASSERT(rel_diff(own_pi, b_pi_d) <= kBoostRelative);
  RC_ASSERT(rel_diff(own_pi, b_pi_l) <= kBoostRelative);
  RC_ASSERT(rel_diff(own_f, b_f_d) <= kBoostRelative);
  RC_ASSERT(rel_diff(own_f, b_f_l) <= kBoostRelative);
}

RC_GTEST_PROP(EllipticProperty, NeverNaNInsideTheDomain, ()) {
  const double n = *gen_n(), phi = *gen_phi(), m = *gen_m();
  const double f = math::ellint_f(phi, m), p = math::ellint_pi(n, phi, m);
  RC_LOG() << "n=" << n << " phi=" << phi << " m=" << m << " F=" << f << " Pi=" << p;
  RC_ASSERT(std::isfinite(f));
  RC_ASSERT(std::isfinite(p));
  RC_ASSERT(f >= 0.0);
  RC_ASSERT(p >= 0.0);
  // The integrands are ordered: 1/(1 - n s^2) >= 1 exactly when n >= 0 (up to the rounding
  // of two independently evaluated values, which matters when they are equal to ~1e-16).
  if (n > 0) RC_ASSERT(p >= f * (1 - kIdentityRelative));
  if (n < 0) RC_ASSERT(p <= f * (1 + kIdentityRelative));
}

RC_GTEST_PROP(EllipticProperty, PiAtZeroCharacteristicIsF, ()) {
  const double phi = *gen_phi(), m = *gen_m();
  RC_ASSERT(math::ellint_pi(0.0, phi, m) == math::ellint_f(phi, m));
  // Approaching n = 0 from either side through the two different Pi paths (direct formula for
  // n > 0, N-transform for n < 0): (Pi - F)/n -> D(phi|m) = int sin^2/Delta, an R_D evaluation.
  const double n = 1e-9;
  const double d = math::ellint_d(phi, m);
  if (!(d > 1e-200)) return;  // tiny phi: D ~ phi^3/3 underflows the comparison
  const double up = (math::ellint_pi(n, phi, m) - math::ellint_f(phi, m));
  const double down = (math::ellint_pi(-n, phi, m) - math::ellint_f(phi, m));
  RC_LOG() << "phi=" << phi << " m=" << m << " D=" << d << " (Pi(+n)-F)/n=" << up / n
           << " (Pi(-n)-F)/-n=" << down / -n;
  // Pi - F ~ n D is a difference of two O(F) numbers: its absolute error is ~4 eps F, and
  // the O(n^2) term is ~n D'; together these bound the check.
  const double f = math::ellint_f(phi, m);
  const double bound = 8 * kEps * f / n + n * 1e3 * d / (1 - m + 1e-300);
  RC_ASSERT(std::fabs(up / n - d) <= bound + kNearZeroCharacteristicRel * d);
  RC_ASSERT(std::fabs(down / -n - d) <= bound + kNearZeroCharacteristicRel * d);
}

RC_GTEST_PROP(EllipticProperty, LegendreRelationForCompleteIntegrals, ()) {
  // mc = 1 - m in [0.5, 0.99]: then m = 1 - mc is exact (Sterbenz), so (m, m') = (1-mc, mc)
  // is an exact complementary pair; by symmetry this covers m in [0.01, 0.99].
  const double mc = 0.5 + 0.49 * *gen_unit();
  const double m = 1.0 - mc;
  const double K = math::ellint_k_complete(mc), E = math::ellint_e_complete(mc);
  const double Kp = math::ellint_k_complete(m), Ep = math::ellint_e_complete(m);
  const double residual = E * Kp + Ep * K - K * Kp - std::numbers::pi / 2;
  RC_LOG() << "m=" << m << " K=" << K << " E=" << E << " K'=" << Kp << " E'=" << Ep
           << " E K' + E' K - K K' - pi/2 = " << residual;
  RC_ASSERT(std::fabs(residual) <= kLegendreAbsolute);
}

RC_GTEST_PROP(EllipticProperty, CarlsonSymmetryAndHomogeneity, ()) {
  // At most one zero argument (two zeros diverge): x may be 0, y, z, p are >= 1e-3.
  const double x = *gen_unit(), y = *gen_unit() + 1e-3, z = *gen_unit() + 1e-3,
               p = *gen_unit() + 1e-3;
  const double rf = math::carlson_rf(x, y, z);
  RC_LOG() << "x=" << x << " y=" << y << " z=" << z << " p=" << p << " R_F=" << rf;
  RC_ASSERT(rel_diff(math::carlson_rf(y, z, x), rf) <= kIdentityRelative);
  RC_ASSERT(rel_diff(math::carlson_rf(z, x, y), rf) <= kIdentityRelative);
  RC_ASSERT(rel_diff(math::carlson_rf(y, x, z), rf) <= kIdentityRelative);
  const double rj = math::carlson_rj(x, y, z, p);
  RC_LOG() << "R_J=" << rj;
  RC_ASSERT(rel_diff(math::carlson_rj(y, z, x, p), rj) <= kIdentityRelative);
  RC_ASSERT(rel_diff(math::carlson_rj(z, y, x, p), rj) <= kIdentityRelative);
  // Homogeneity (DLMF 19.16.1-2): R_F(lx, ly, lz) = R_F / sqrt(l), R_J(l.) = R_J / l^(3/2).
  const double l = std::exp(40 * *gen_unit() - 20);
  RC_LOG() << "lambda=" << l;
  RC_ASSERT(rel_diff(math::carlson_rf(l * x, l * y, l * z) * std::sqrt(l), rf) <=
            kIdentityRelative + 3 * kEps);  // + rounding of l*x, l*y, l*z and sqrt(l)
  RC_ASSERT(rel_diff(math::carlson_rj(l * x, l * y, l * z, l * p) * l * std::sqrt(l), rj) <=
            kIdentityRelative + 5 * kEps);
  // R_D is R_J with p = z, and R_C(x, y) = R_F(x, y, y) (DLMF 19.2.17).
  RC_ASSERT(rel_diff(math::carlson_rd(x, y, z), math::carlson_rj(x, y, z, z)) == 0.0);
  RC_ASSERT(rel_diff(math::carlson_rc(x + 1e-3, z), math::carlson_rf(x + 1e-3, z, z)) <=
            kIdentityRelative);
}

RC_GTEST_PROP(EllipticProperty, DifferenceFormsMatch50DigitEvaluation, ()) {
  const double n = *gen_n(), phi = *gen_phi(), m = *gen_m();
  const Real50 N(n), P(phi), M(m);
  const Real50 pi50 = math::ellint_pi(N, P, M), f50 = math::ellint_f(P, M);
  const double exact_bracket = static_cast<double>((1 - N) * pi50 - f50);
  const double exact_pmf = static_cast<double>(pi50 - f50);
  const double bracket = math::ellint_one_minus_n_pi_minus_f(n, phi, m);
  const double pmf = math::ellint_pi_minus_f(n, phi, m);
  RC_LOG() << "n=" << n << " phi=" << phi << " m=" << m << " (1-n)Pi-F=" << bracket
           << " (50 digits: " << exact_bracket << ") Pi-F=" << pmf << " (50 digits: " << exact_pmf
           << ")";
  if (exact_pmf == 0.0) {
    RC_ASSERT(pmf == 0.0);
  } else {
    RC_ASSERT(rel_diff(pmf, exact_pmf) <= kDifferenceRelative);
  }
  // Cancellation-free is promised for n <= 0 (the parallel map's n = -b_t^2).
  if (n < 0 && exact_bracket != 0.0)
    RC_ASSERT(rel_diff(bracket, exact_bracket) <= kDifferenceRelative);
}

// The double-double kernel of ellint_pi<double> (AVX2 + FMA machines; each copy this CPU runs)
// and the portable long-double path compute the same integral by the same formulas in different
// arithmetic: over the domain and its corners they agree to kIdentityRelative (each within
// ~2 ulp).
RC_GTEST_PROP(EllipticProperty, PiKernelAgreesWithPortablePath, ()) {
  namespace d = math::detail;
  const double n = *gen_n(), phi = *gen_phi(), m = *gen_m();
  RC_PRE(phi > 0.0);
  const double portable = d::ellint_pi_portable(n, 1.0 - n, phi, m, 1.0 - m);
  for (const d::PiKernel k : {d::PiKernel::kAvx2Fma, d::PiKernel::kAvx512}) {
    if (!d::pi_dd_kernel_supported(k)) continue;        // nothing to compare on this CPU
    const double fast = d::ellint_pi_dd(k, n, phi, m);  // as ellint_pi calls the copy in use
    RC_ASSERT(std::isfinite(fast));
    RC_ASSERT(rel_diff(fast, portable) <= kIdentityRelative);
  }
  if (d::pi_dd_kernel_available())
    RC_ASSERT(rel_diff(math::ellint_pi(n, phi, m), portable) <= kIdentityRelative);
}

TEST(EllipticProperty, DefinedOutsideTheDomain) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(math::ellint_f(0.5, 1.5)));
  EXPECT_TRUE(std::isnan(math::ellint_f(nan, 0.5)));
  EXPECT_TRUE(std::isnan(math::ellint_f(0.5, nan)));
  EXPECT_TRUE(std::isnan(math::ellint_pi(1.5, 0.5, 0.5)));
  EXPECT_TRUE(std::isnan(math::ellint_pi(nan, 0.5, 0.5)));
  EXPECT_TRUE(std::isnan(math::ellint_f(std::numeric_limits<double>::infinity(), 0.5)));
  // phi outside [0, pi/2]: odd and quasi-periodic, F(phi + pi) = F(phi) + 2K.
  const double m = 0.7, phi = 0.9;
  const double K = math::ellint_k_complete(1.0 - m);
  EXPECT_NEAR(math::ellint_f(-phi, m), -math::ellint_f(phi, m), 0.0);
  EXPECT_NEAR(math::ellint_f(phi + std::numbers::pi, m), math::ellint_f(phi, m) + 2 * K,
              kQuasiPeriodRel * K);
  const double Pc = math::ellint_pi(0.3, kHalfPi, m);
  EXPECT_NEAR(math::ellint_pi(0.3, phi - 2 * std::numbers::pi, m),
              math::ellint_pi(0.3, phi, m) - 4 * Pc, kQuasiPeriodRel * Pc);
  // m = 1: finite below pi/2 (F = atanh(sin phi)).
  EXPECT_NEAR(math::ellint_f(1.0, 1.0), std::atanh(std::sin(1.0)), 4 * kEps * 1.2);
  // Two zero Carlson arguments: divergent, +inf; negative: NaN.
  EXPECT_EQ(math::carlson_rf(0.0, 0.0, 1.0), std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(math::carlson_rj(-1.0, 1.0, 1.0, 1.0)));
}

}  // namespace
}  // namespace disklab::test
