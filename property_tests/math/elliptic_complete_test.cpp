// The complete integrals K(m) and Pi(n|m) at exactly pi/2, and F, Pi at any finite phi (odd and
// quasi-periodic: I(j pi + r) = 2j I(pi/2) + I(r)), in double against 50-digit references:
//  - Boost.Math's complete ellint_1(k) / ellint_3(k, n) evaluated in cpp_bin_float_50 (its own
//    Carlson code: independent of ours), with k = sqrt(m) and 1 - k^2 formed in 50 digits;
//  - for phi beyond [0, pi/2], the identity above formed in 50 digits: r = phi - j pi with a
//    50-digit pi, I(|r|) from our templates in cpp_bin_float_50 (checked against the independent
//    quadrature tables by EllipticReference.Float50TemplatesAgreeWithTablesTo1em40) and I(pi/2)
//    from Boost as above.
#include <gtest/gtest.h>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "disklab/math/elliptic.h"
#include "disklab/sequence/random.h"
#include "math/elliptic_domain.h"
#include "math/elliptic_tables.h"

namespace disklab::test {
namespace {

using Real50 = boost::multiprecision::cpp_bin_float_50;
namespace dom = elliptic_domain;

// --- Tolerances (one place for this suite) ---------------------------------------------------
// The accuracy target for F and Pi in double: 2 ulp from the correctly rounded value.
constexpr int64_t kMaxUlp = 2;
// Our templates in cpp_bin_float_50 against Boost's in cpp_bin_float_50: both converge to
// ~1e-49; the margin is that of EllipticReference's kHighPrecisionRelative (a wrong series
// coefficient shows at tol^6 ~ 1e-38).
const Real50 kHighPrecisionRelative("1e-40");
// Where the library reduces phi (below 1/eps = 2^52; beyond it returns the mean growth, which
// is within 1/(4j) relative of the exact value and so held to kMaxUlp only).
constexpr double kReducedUpTo = 0x1p52;

int64_t ulps_apart_abs(int64_t d) {
  return d < 0 ? -d : d;
}

// Boost's complete integrals in 50 digits at the double inputs (Boost takes k = sqrt(m)).
Real50 boost_k(double m) {
  return boost::math::ellint_1(sqrt(Real50(m)));
}
Real50 boost_pi(double n, double m) {
  return boost::math::ellint_3(sqrt(Real50(m)), Real50(n));
}

// m and n on a grid that reaches the corners: 1 - 2^-j with exact complements up to 1 - 2^-53.
std::vector<double> grid_m() {
  std::vector<double> v{0.0, 1e-10, 0.1, 0.5, 0.9};
  for (int j : {4, 10, 20, 30, 40, 46, 50, 52, 53})
    v.push_back(1.0 - std::ldexp(1.0, -j));
  return v;
}
std::vector<double> grid_n() {
  std::vector<double> v{-1e16, -1e8, -1e3, -1.0, -0.3, -1e-9, 1e-9, 0.3, 0.9};
  for (int j : {4, 10, 20, 30, 40, 46, 50, 52, 53})
    v.push_back(1.0 - std::ldexp(1.0, -j));
  return v;
}

TEST(EllipticComplete, KAndPiWithinTwoUlpOf50DigitBoost) {
  int64_t worst_k = 0, worst_pi = 0, worst_at_fl_half_pi = 0;
  int faithful = 0, count = 0;
  std::string worst_where;
  for (const double m : grid_m()) {
    const double mc = 1.0 - m;  // exact on the grid's corners (Sterbenz)
    const Real50 k_ref = boost_k(m);
    const double k = math::ellint_k(m, mc);
    EXPECT_EQ(k, math::ellint_k(m)) << "m=" << m;  // the complement is exact here
    const int64_t dk = ulps_apart_abs(ulp_distance(k, k_ref.convert_to<double>()));
    worst_k = std::max(worst_k, dk);
    EXPECT_LE(dk, kMaxUlp) << "K(m=" << m << ") = " << k << ", 50 digits " << k_ref.str(20);
    EXPECT_LE(abs(math::ellint_k(Real50(m)) - k_ref) / k_ref, kHighPrecisionRelative) << m;
    for (const double n : grid_n()) {
      const double nc = 1.0 - n;
      const Real50 pi_ref = boost_pi(n, m);
      const double pi = math::ellint_pi_complete(n, nc, m, mc);
      const RoundingError e = rounding_error(pi, pi_ref);
      faithful += e.faithful;
      ++count;
      const int64_t d = ulps_apart_abs(ulp_distance(pi, pi_ref.convert_to<double>()));
      char where[96];
      std::snprintf(where, sizeof where, "n=%.17g m=%.17g", n, m);
      if (d > worst_pi || worst_where.empty()) worst_where = where;
      worst_pi = std::max(worst_pi, d);
      EXPECT_LE(d, kMaxUlp) << "Pi(" << where << ") = " << pi << ", 50 digits " << pi_ref.str(20);
      EXPECT_LE(abs(math::ellint_pi_complete(Real50(n), Real50(m)) - pi_ref) / pi_ref,
                kHighPrecisionRelative)
          << where;
      // Pi at fl(pi/2) instead: what callers could ask before ellint_pi_complete.
      const double at_fl = math::ellint_pi(n, nc, dom::kHalfPi, m, mc);
      worst_at_fl_half_pi = std::max(
          worst_at_fl_half_pi, ulps_apart_abs(ulp_distance(at_fl, pi_ref.convert_to<double>())));
    }
  }
  std::printf(
      "complete integrals vs 50-digit Boost: K max %lld ulp, Pi max %lld ulp (at %s), %d of %d Pi "
      "faithful; Pi at fl(pi/2) instead: max %lld ulp\n",
      (long long)worst_k, (long long)worst_pi, worst_where.c_str(), faithful, count,
      (long long)worst_at_fl_half_pi);
  // The grid reaches the corner where fl(pi/2) (6.1e-17 below pi/2) misses the complete value:
  // otherwise this test could not tell the complete integral from Pi at fl(pi/2).
  EXPECT_GT(worst_at_fl_half_pi, kMaxUlp);
}

// The complete integrals' special cases: divergence at m = 1 or n = 1, NaN outside the domain,
// Pi(0|m) = K(m), and the two-argument forms equal to the complement forms given 1 - x.
TEST(EllipticComplete, SpecialCases) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(math::ellint_k(1.0), inf);
  EXPECT_EQ(math::ellint_pi_complete(0.5, 1.0), inf);
  EXPECT_EQ(math::ellint_pi_complete(1.0, 0.5), inf);
  EXPECT_EQ(math::ellint_pi_complete(-3.0, 1.0), inf);
  EXPECT_TRUE(std::isnan(math::ellint_k(1.5)));
  EXPECT_TRUE(std::isnan(math::ellint_pi_complete(1.5, 0.5)));
  EXPECT_TRUE(std::isnan(math::ellint_pi_complete(0.5, std::nan(""))));
  EXPECT_TRUE(std::isnan(math::ellint_k(0.5, -0.5)));
  for (const double m : {0.0, 0.3, 0.999}) {
    EXPECT_EQ(math::ellint_pi_complete(0.0, m), math::ellint_k(m)) << m;
    EXPECT_EQ(math::ellint_k(m), math::ellint_k_complete(1.0 - m)) << m;
    EXPECT_EQ(math::ellint_pi_complete(-2.0, m), math::ellint_pi_complete(-2.0, 3.0, m, 1.0 - m));
  }
  // K(0) = Pi(0|0) = pi/2.
  EXPECT_EQ(math::ellint_k(0.0), 1.5707963267948966);
}

// F and Pi at phi = +-(r + j pi) for r over the domain's phi kinds and j from 1 to 1e12
// (log-uniform), at the domain's m and n corners, against the 50-digit identity: F faithfully
// rounded, Pi within kMaxUlp. Where |phi| > 1/eps = 2^52 the library returns the mean growth
// 2 |phi| I(pi/2) / pi (as Boost does): that too is checked against the exact value, to kMaxUlp,
// up to 1e30 (the 50-digit pi still reduces it).
TEST(EllipticComplete, FAndPiAtAnyPhiWithinTwoUlpOf50Digits) {
  const Real50 pi50 = boost::math::constants::pi<Real50>();
  sequence::Pcg32 rng(2026, 13);
  constexpr int kSamples = 3000;
  int64_t worst_f = 0, worst_pi = 0;
  int f_faithful = 0;
  std::string worst_f_where, worst_pi_where;
  for (int i = 0; i < kSamples; ++i) {
    const double r0 = dom::phi(i % dom::kPhiKinds, rng.next_double());
    const double m = dom::m((i / dom::kPhiKinds) % dom::kMKinds, rng.next_double());
    const double n =
        dom::n((i / (dom::kPhiKinds * dom::kMKinds)) % dom::kNKinds, rng.next_double());
    const double u = rng.next_double();
    // j: 0 (phi just below 0) for a twentieth of the samples, else 10^(12 u) or, for a
    // twentieth, 10^(15 + 15 u) (beyond 2^52).
    const int band = i % 20;
    const double j = band == 0 ? 0.0 : std::round(std::pow(10.0, band == 1 ? 15 + 15 * u : 12 * u));
    const double sign = i % 2 == 0 ? 1.0 : -1.0;
    const double phi = sign * (r0 + j * std::numbers::pi);
    if (phi == 0) continue;
    // 50-digit reference: phi = J pi + r exactly (J, r from the double phi).
    const Real50 P(phi), J = round(P / pi50), r = P - J * pi50, ar = abs(r);
    const Real50 M(m), N(n);
    const Real50 f_ref = 2 * J * boost_k(m) + (r < 0 ? -1 : 1) * math::ellint_f(ar, M);
    const Real50 pi_ref = 2 * J * boost_pi(n, m) + (r < 0 ? -1 : 1) * math::ellint_pi(N, ar, M);
    char where[128];
    std::snprintf(where, sizeof where, "n=%.17g phi=%.17g m=%.17g", n, phi, m);
    const double f = math::ellint_f(phi, m), p = math::ellint_pi(n, phi, m);
    const int64_t df = ulps_apart_abs(ulp_distance(f, f_ref.convert_to<double>()));
    const int64_t dp = ulps_apart_abs(ulp_distance(p, pi_ref.convert_to<double>()));
    const RoundingError fe = rounding_error(f, f_ref);
    f_faithful += fe.faithful;
    // F is faithfully rounded wherever phi is reduced (below 2^52; beyond it, the mean growth).
    if (std::fabs(phi) <= kReducedUpTo) {
      EXPECT_TRUE(fe.faithful) << "F: " << where << " own=" << f << " ref=" << f_ref.str(20) << ": "
                               << fe.ulps << " ulp";
    }
    if (df > worst_f || worst_f_where.empty()) worst_f_where = where;
    if (dp > worst_pi || worst_pi_where.empty()) worst_pi_where = where;
    worst_f = std::max(worst_f, df);
    worst_pi = std::max(worst_pi, dp);
    EXPECT_LE(df, kMaxUlp) << "F: " << where << " own=" << f << " ref=" << f_ref.str(20);
    EXPECT_LE(dp, kMaxUlp) << "Pi: " << where << " own=" << p << " ref=" << pi_ref.str(20);
    // Odd in phi, bit for bit (both overloads).
    EXPECT_EQ(math::ellint_f(-phi, m), -f) << where;
    EXPECT_EQ(math::ellint_pi(n, -phi, m), -p) << where;
    EXPECT_EQ(math::ellint_f(-phi, m, 1.0 - m), -math::ellint_f(phi, m, 1.0 - m)) << where;
    EXPECT_EQ(math::ellint_pi(n, 1.0 - n, -phi, m, 1.0 - m),
              -math::ellint_pi(n, 1.0 - n, phi, m, 1.0 - m))
        << where;
  }
  std::printf(
      "any phi vs 50 digits (%d samples): F max %lld ulp (at %s), %d faithful; Pi max %lld ulp "
      "(at %s)\n",
      kSamples, (long long)worst_f, worst_f_where.c_str(), f_faithful, (long long)worst_pi,
      worst_pi_where.c_str());
}

}  // namespace
}  // namespace disklab::test
