// Own F and Pi against the committed 50-digit tables (reference/elliptic_*.csv, made by
// tanh-sinh quadrature, independent of Carlson): in double to within kMaxUlp of the correctly
// rounded value (F also faithfully rounded, there and at Boost.Math's own ellint_1 test inputs),
// and the same templates in cpp_bin_float_50 to kHighPrecisionRelative.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "disklab/math/elliptic.h"
#include "disklab/sequence/random.h"
#include "math/elliptic_domain.h"
#include "math/elliptic_pi_dd.h"  // lib/src: the Pi kernel's private hooks
#include "math/elliptic_tables.h"

namespace disklab::test {
namespace {

using Real50 = boost::multiprecision::cpp_bin_float_50;

// The accuracy target: at most 2 ulp from the correctly rounded reference anywhere on
// the domain (m in [0,1), n < 1, phi in [0, pi/2]).
constexpr int64_t kMaxUlp = 2;
// The tables hold 45 digits and agree with mpmath to ~1e-43 (reference/README.md); Carlson in
// 50 digits measures ~7e-44 against them. 1e-40 leaves that margin and still catches a wrong
// series coefficient, whose terms are of size tol^6 ~ 1e-38 at 50 digits.
const Real50 kHighPrecisionRelative("1e-40");

struct UlpStats {
  int64_t max = 0;
  double sum2 = 0;
  std::size_t count = 0;
  std::string worst;
  void add(int64_t d, const std::string& where) {
    d = d < 0 ? -d : d;
    sum2 += double(d) * double(d);
    ++count;
    if (d > max || worst.empty()) {
      if (d > max) max = d;
      worst = where;
    }
  }
  double rms() const { return std::sqrt(sum2 / double(count)); }
};

std::string describe(const std::vector<double>& in, double own, const EllipticRow& row) {
  char buf[256];
  if (in.size() == 2)
    std::snprintf(buf, sizeof buf, "phi=%.17g m=%.17g own=%.17g ref=%s", in[0], in[1], own,
                  row.value.c_str());
  else
    std::snprintf(buf, sizeof buf, "n=%.17g phi=%.17g m=%.17g own=%.17g ref=%s", in[0], in[1],
                  in[2], own, row.value.c_str());
  return buf;
}

TEST(EllipticReference, FWithinTwoUlpOfTable) {
  const auto rows = read_elliptic_table("elliptic_f.csv", 2);
  UlpStats plain, complement;
  for (const EllipticRow& row : rows) {
    const double phi = row.inputs[0], m = row.inputs[1];
    const double own = math::ellint_f(phi, m);
    const double own_c = math::ellint_f(phi, m, 1.0 - m);
    plain.add(ulp_distance(own, row.value_rounded), describe(row.inputs, own, row));
    complement.add(ulp_distance(own_c, row.value_rounded), describe(row.inputs, own_c, row));
    EXPECT_LE(std::llabs(ulp_distance(own, row.value_rounded)), kMaxUlp)
        << describe(row.inputs, own, row);
    EXPECT_LE(std::llabs(ulp_distance(own_c, row.value_rounded)), kMaxUlp)
        << "complement overload: " << describe(row.inputs, own_c, row);
  }
  std::printf("F: %zu rows, max %lld ulp, RMS %.3f ulp, worst %s\n", plain.count,
              (long long)plain.max, plain.rms(), plain.worst.c_str());
}

// F in double is faithfully rounded (below one ulp of the exact value) on both F tables: ours
// (reference/elliptic_f.csv) and the inputs of Boost.Math's own ellint_1 test table
// (reference/elliptic_f_boost_inputs.csv, 500 of 610 rows with phi beyond pi/2, up to 1185, so
// the reduction of phi is held to it too). The error in fractional ulps is printed.
TEST(EllipticReference, FFaithfullyRoundedOnBothTables) {
  for (const char* name : {"elliptic_f.csv", "elliptic_f_boost_inputs.csv"}) {
    double worst = 0, sum2 = 0;
    std::string worst_row;
    const auto rows = read_elliptic_table(name, 2);
    for (const EllipticRow& row : rows) {
      const double own = math::ellint_f(row.inputs[0], row.inputs[1]);
      const RoundingError e = rounding_error(own, Real50(row.value));
      sum2 += e.ulps * e.ulps;
      if (e.ulps >= worst) {
        worst = e.ulps;
        worst_row = describe(row.inputs, own, row);
      }
      EXPECT_TRUE(e.faithful) << name << ": " << e.ulps << " ulp, "
                              << describe(row.inputs, own, row);
    }
    std::printf("F faithful on %s: %zu rows, max %.3f ulp of the exact value, RMS %.3f, worst %s\n",
                name, rows.size(), worst, std::sqrt(sum2 / double(rows.size())), worst_row.c_str());
  }
}

// F's sin and cos in x87 long double (sincos_wide, elliptic_legendre.h) against 50 digits, on
// [0, pi/2] and its ends. Bound: Taylor truncation below 2^-68, plus about a dozen long-double
// roundings of 2^-64 on terms no larger than the value: 2^-60.
TEST(EllipticReference, WideSinCosWithin2em60Of50Digits) {
  if constexpr (std::numeric_limits<long double>::digits != 64) {
    GTEST_SKIP() << "long double is not x87 extended here: sincos_wide uses libm";
  } else {
    namespace dom = elliptic_domain;
    const Real50 kBound = Real50(std::ldexp(1.0, -60));
    sequence::Pcg32 rng(2026, 12);
    Real50 worst_s = 0, worst_c = 0;
    for (int i = 0; i < 30000; ++i) {
      const double phi = i < 2 ? (i == 0 ? dom::kHalfPi : std::ldexp(1.0, -1074))
                               : dom::phi(i % dom::kPhiKinds, rng.next_double());
      if (phi == 0) continue;
      long double s, c;
      math::detail::sincos_wide(static_cast<long double>(phi), s, c);
      const Real50 P(phi), es = abs((Real50(s) - sin(P)) / sin(P)),
                           ec = abs((Real50(c) - cos(P)) / cos(P));
      worst_s = std::max(worst_s, es);
      worst_c = std::max(worst_c, ec);
      EXPECT_LE(es, kBound) << "sin phi=" << phi;
      EXPECT_LE(ec, kBound) << "cos phi=" << phi;
    }
    std::printf("sincos_wide: max relative error sin %.2g, cos %.2g (bound 2^-60 = %.2g)\n",
                double(worst_s), double(worst_c), std::ldexp(1.0, -60));
  }
}

TEST(EllipticReference, PiWithinTwoUlpOfTable) {
  const auto rows = read_elliptic_table("elliptic_pi.csv", 3);
  UlpStats plain;
  for (const EllipticRow& row : rows) {
    const double n = row.inputs[0], phi = row.inputs[1], m = row.inputs[2];
    const double own = math::ellint_pi(n, phi, m);
    const double own_c = math::ellint_pi(n, 1.0 - n, phi, m, 1.0 - m);
    plain.add(ulp_distance(own, row.value_rounded), describe(row.inputs, own, row));
    EXPECT_LE(std::llabs(ulp_distance(own, row.value_rounded)), kMaxUlp)
        << describe(row.inputs, own, row);
    EXPECT_LE(std::llabs(ulp_distance(own_c, row.value_rounded)), kMaxUlp)
        << "complement overload: " << describe(row.inputs, own_c, row);
  }
  std::printf("Pi: %zu rows, max %lld ulp, RMS %.3f ulp, worst %s\n", plain.count,
              (long long)plain.max, plain.rms(), plain.worst.c_str());
}

// ellint_pi<double> runs the double-double kernel where the CPU has AVX2 and FMA
// (elliptic_legendre.h, FAST PATH; its AVX-512VL copy where the CPU has that too), else the
// long-double path; the test above checks whichever this machine runs. These check each path by
// name, so every copy this CPU runs is held to the target (and the portable path everywhere).
constexpr math::detail::PiKernel kKernelCopies[] = {math::detail::PiKernel::kAvx2Fma,
                                                    math::detail::PiKernel::kAvx512};

// The copies of the kernel this CPU runs (none: the tests that need one skip).
std::vector<math::detail::PiKernel> supported_kernels() {
  std::vector<math::detail::PiKernel> out;
  for (const math::detail::PiKernel k : kKernelCopies)
    if (math::detail::pi_dd_kernel_supported(k)) out.push_back(k);
  return out;
}

// Pi by the given copy of the kernel, with the complements exact (hi + lo), as the
// three-argument ellint_pi passes them.
double kernel_pi(math::detail::PiKernel kernel, double n, double phi, double m) {
  const double omn = 1.0 - n, omm = 1.0 - m;
  return math::detail::ellint_pi_dd(kernel, n, omn, math::detail::complement_error(n, omn), phi, m,
                                    omm, math::detail::complement_error(m, omm));
}

// The Pi table's inputs (n, phi, m) in the kernel's domain (phi in (0, pi/2], m in [0, 1], n < 1):
// the kernel and the portable path are both within 1 ulp there but round differently on some
// rows, which is how the dispatch tests below tell them apart (on random inputs they now agree
// on all but ~0.2%).
std::vector<std::array<double, 3>> pi_table_kernel_inputs() {
  std::vector<std::array<double, 3>> out;
  for (const EllipticRow& row : read_elliptic_table("elliptic_pi.csv", 3)) {
    const double n = row.inputs[0], phi = row.inputs[1], m = row.inputs[2];
    if (phi > 0 && phi <= elliptic_domain::kHalfPi && m >= 0 && m <= 1 && n < 1)
      out.push_back({n, phi, m});
  }
  return out;
}

template <class Eval>
UlpStats check_pi_path(const char* label, Eval eval) {
  const auto rows = read_elliptic_table("elliptic_pi.csv", 3);
  UlpStats stats;
  for (const EllipticRow& row : rows) {
    const std::optional<double> answer = eval(row.inputs[0], row.inputs[1], row.inputs[2]);
    if (!answer) continue;
    const double own = *answer;
    stats.add(ulp_distance(own, row.value_rounded), describe(row.inputs, own, row));
    EXPECT_LE(std::llabs(ulp_distance(own, row.value_rounded)), kMaxUlp)
        << label << ": " << describe(row.inputs, own, row);
  }
  std::printf("Pi (%s): %zu rows, max %lld ulp, RMS %.3f ulp, worst %s\n", label, stats.count,
              (long long)stats.max, stats.rms(), stats.worst.c_str());
  return stats;
}

TEST(EllipticReference, PiPortablePathWithinTwoUlpOfTable) {
  const UlpStats stats = check_pi_path(
      "portable long-double path", [](double n, double phi, double m) -> std::optional<double> {
        return math::detail::ellint_pi_portable(n, 1.0 - n, phi, m, 1.0 - m);
      });
  EXPECT_EQ(stats.count, read_elliptic_table("elliptic_pi.csv", 3).size());
}

TEST(EllipticReference, PiDoubleDoubleKernelWithinTwoUlpOfTable) {
  const auto kernels = supported_kernels();
  if (kernels.empty())
    GTEST_SKIP() << "this CPU lacks AVX2/FMA: ellint_pi runs the portable path (tested above)";
  for (const math::detail::PiKernel kernel : kernels) {
    const std::string label =
        std::string("double-double kernel, ") + math::detail::pi_dd_kernel_name(kernel);
    const UlpStats stats = check_pi_path(label.c_str(), [kernel](double n, double phi, double m) {
      // The kernel's domain (phi = 0 and m < 0 are answered before it).
      return phi > 0 && m >= 0 ? std::optional<double>(kernel_pi(kernel, n, phi, m)) : std::nullopt;
    });
    // The kernel's domain covers most of the table.
    EXPECT_GT(stats.count, read_elliptic_table("elliptic_pi.csv", 3).size() / 2) << label;
  }
}

// The copy this CPU should run, from its features read directly (not through the library's
// predicate): the copies are compiled for AVX2 + FMA and for AVX2 + FMA + AVX-512F/VL
// (elliptic_pi_dd_avx2.cpp, elliptic_pi_dd_avx512.cpp), on x86-64 with GCC or Clang only.
math::detail::PiKernel expected_best_kernel() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  __builtin_cpu_init();
  const bool avx2_fma = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  const bool avx512vl = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
  if (avx2_fma && avx512vl) return math::detail::PiKernel::kAvx512;
  if (avx2_fma) return math::detail::PiKernel::kAvx2Fma;
#endif
  return math::detail::PiKernel::kNone;
}

// ellint_pi<double> runs the best copy this CPU supports, and only supported copies answer.
TEST(EllipticReference, PiRunsTheBestSupportedKernel) {
  namespace d = math::detail;
  const d::PiKernel best = expected_best_kernel();
  EXPECT_EQ(d::pi_dd_kernel(), best) << "runs " << d::pi_dd_kernel_name(d::pi_dd_kernel())
                                     << ", the CPU's features say " << d::pi_dd_kernel_name(best);
  EXPECT_EQ(d::pi_dd_kernel_available(), best != d::PiKernel::kNone);
  EXPECT_FALSE(d::pi_dd_kernel_supported(d::PiKernel::kNone));
  // The AVX2 + FMA copy runs wherever the AVX-512VL one does (its instruction sets are a subset).
  EXPECT_EQ(d::pi_dd_kernel_supported(d::PiKernel::kAvx2Fma), best != d::PiKernel::kNone);
  EXPECT_EQ(d::pi_dd_kernel_supported(d::PiKernel::kAvx512), best == d::PiKernel::kAvx512);
  std::printf("Pi kernel in use: %s\n", d::pi_dd_kernel_name(best));
  // ellint_pi's result is the kernel's, bit for bit. The portable path's differs in the last bit
  // on some of the table's inputs (counted), so this shows that the kernel runs; which copy runs is
  // pi_dd_kernel()'s answer above (the copies rarely differ: the corner sweep below counts it).
  sequence::Pcg32 rng(2026, 6);
  int portable_differs = 0;
  for (int i = 0; i < 200; ++i) {
    const double n = 2 * rng.next_double() - 1, phi = 1.5 * rng.next_double() + 0.05;
    const double m = rng.next_double();
    for (const d::PiKernel k : kKernelCopies) {
      // The three-argument entry forms the same exact complements as kernel_pi passes.
      const double got = kernel_pi(k, n, phi, m), got3 = d::ellint_pi_dd(k, n, phi, m);
      if (d::pi_dd_kernel_supported(k)) {
        EXPECT_TRUE(std::isfinite(got)) << d::pi_dd_kernel_name(k);
        EXPECT_EQ(std::bit_cast<uint64_t>(got), std::bit_cast<uint64_t>(got3))
            << d::pi_dd_kernel_name(k) << " n=" << n << " phi=" << phi << " m=" << m;
      } else {
        EXPECT_TRUE(std::isnan(got) && std::isnan(got3))
            << d::pi_dd_kernel_name(k) << " is not supported here";
      }
    }
    if (best != d::PiKernel::kNone) {
      const double own = math::ellint_pi(n, phi, m);
      EXPECT_EQ(std::bit_cast<uint64_t>(own), std::bit_cast<uint64_t>(kernel_pi(best, n, phi, m)))
          << "n=" << n << " phi=" << phi << " m=" << m;
      portable_differs += own != d::ellint_pi_portable(n, 1.0 - n, phi, m, 1.0 - m);
    }
  }
  const auto table = pi_table_kernel_inputs();
  if (best != d::PiKernel::kNone) {
    for (const auto& [n, phi, m] : table) {
      const double own = math::ellint_pi(n, phi, m);
      EXPECT_EQ(std::bit_cast<uint64_t>(own), std::bit_cast<uint64_t>(kernel_pi(best, n, phi, m)))
          << "n=" << n << " phi=" << phi << " m=" << m;
      portable_differs += own != d::ellint_pi_portable(n, 1.0 - n, phi, m, 1.0 - m);
    }
    EXPECT_GT(portable_differs, 0);
  }
  std::printf("the portable path differs from the kernel on %d of %zu inputs\n", portable_differs,
              200 + table.size());
}

// use_pi_dd_kernel, the benchmark's way to time a copy that is not the best: ellint_pi then runs
// the chosen copy or, for kNone, the portable path (which differs from the kernel in the last bit
// on some of the table's inputs, so the bitwise checks tell them apart); unsupported copies are
// refused.
TEST(EllipticReference, PiKernelCanBeChosen) {
  namespace d = math::detail;
  const d::PiKernel before = d::pi_dd_kernel();
  struct Restore {
    d::PiKernel kernel;
    ~Restore() { d::use_pi_dd_kernel(kernel); }
  } restore{before};
  auto same_bits = [](double a, double b) {
    return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
  };
  sequence::Pcg32 rng(2026, 7);
  std::vector<std::array<double, 3>> inputs(300);
  for (auto& in : inputs)
    in = {2 * rng.next_double() - 1, 1.5 * rng.next_double() + 0.05, rng.next_double()};
  const auto table = pi_table_kernel_inputs();
  inputs.insert(inputs.end(), table.begin(), table.end());
  for (const d::PiKernel k : kKernelCopies) {
    if (!d::pi_dd_kernel_supported(k)) {
      EXPECT_FALSE(d::use_pi_dd_kernel(k)) << d::pi_dd_kernel_name(k);
      EXPECT_EQ(d::pi_dd_kernel(), before);
      continue;
    }
    ASSERT_TRUE(d::use_pi_dd_kernel(k)) << d::pi_dd_kernel_name(k);
    EXPECT_EQ(d::pi_dd_kernel(), k);
    for (const auto& [n, phi, m] : inputs)
      EXPECT_TRUE(same_bits(math::ellint_pi(n, phi, m), kernel_pi(k, n, phi, m)))
          << d::pi_dd_kernel_name(k) << " n=" << n << " phi=" << phi << " m=" << m;
  }
  ASSERT_TRUE(d::use_pi_dd_kernel(d::PiKernel::kNone));
  EXPECT_FALSE(d::pi_dd_kernel_available());
  const auto kernels = supported_kernels();
  int kernel_differs = 0;
  for (const auto& [n, phi, m] : inputs) {
    const double portable = d::ellint_pi_portable(n, 1.0 - n, phi, m, 1.0 - m);
    EXPECT_TRUE(same_bits(math::ellint_pi(n, phi, m), portable))
        << "kNone: n=" << n << " phi=" << phi << " m=" << m;
    if (!kernels.empty()) kernel_differs += !same_bits(portable, kernel_pi(kernels[0], n, phi, m));
  }
  if (!kernels.empty()) {
    EXPECT_GT(kernel_differs, 0) << "these inputs cannot tell the paths apart";
  }
}

// The 2-ulp target away from the table's rows: a fixed pseudo-random sweep over the domain's
// corners (elliptic_domain.h: phi -> pi/2 and -> 0, m -> 1, n -> 1 and n down to -1e16), every
// Pi path and F against the same integrals evaluated by our templates in cpp_bin_float_50
// (Carlson, checked against the independent tables by the test below). The corners are where
// rounding s, c, R_C or the atan term to double once costs 3-4 ulp; the table's 2130 rows
// happened to miss them.
TEST(EllipticReference, PiAndFWithinTwoUlpOf50DigitsAtCorners) {
  namespace dom = elliptic_domain;
  constexpr int kSamples = 9000;  // 500 per (phi, m, n) corner combination
  sequence::Pcg32 rng(2026, 4);
  const bool kernel = math::detail::pi_dd_kernel_available();
  const auto kernels = supported_kernels();
  UlpStats pi_stats, portable_stats, f_stats;
  std::vector<UlpStats> copy_stats(kernels.size());
  // Where two copies run, their results differ by rounding only: each is a double-double value
  // within ~2^-58 relative of Pi rounded once, so they can round to neighbouring doubles (1 ulp
  // apart), never further.
  int copies_differ = 0;
  auto check = [](UlpStats& stats, const char* label, double own, double ref,
                  const std::string& where) {
    const int64_t d = ulp_distance(own, ref);
    stats.add(d, where);
    EXPECT_LE(std::llabs(d), kMaxUlp) << label << ": " << where << " own=" << own;
  };
  for (int i = 0; i < kSamples; ++i) {
    const int kinds = i % (dom::kPhiKinds * dom::kMKinds * dom::kNKinds);
    const double phi = dom::phi(kinds % dom::kPhiKinds, rng.next_double());
    const double m = dom::m(kinds / dom::kPhiKinds % dom::kMKinds, rng.next_double());
    const double n = dom::n(kinds / (dom::kPhiKinds * dom::kMKinds), rng.next_double());
    char where[128];
    std::snprintf(where, sizeof where, "n=%.17g phi=%.17g m=%.17g", n, phi, m);
    const double pi_ref = static_cast<double>(math::ellint_pi(Real50(n), Real50(phi), Real50(m)));
    check(pi_stats, kernel ? "Pi (double-double kernel)" : "Pi", math::ellint_pi(n, phi, m), pi_ref,
          where);
    check(portable_stats, "Pi (portable)",
          math::detail::ellint_pi_portable(n, 1.0 - n, phi, m, 1.0 - m), pi_ref, where);
    double first_copy = 0;
    for (std::size_t j = 0; j < kernels.size(); ++j) {
      const double v = kernel_pi(kernels[j], n, phi, m);
      check(copy_stats[j], math::detail::pi_dd_kernel_name(kernels[j]), v, pi_ref, where);
      if (j == 0) first_copy = v;
      const int64_t apart = std::llabs(ulp_distance(v, first_copy));
      copies_differ += apart != 0;
      EXPECT_LE(apart, 1) << "copies of the kernel disagree: " << where;
    }
    if (kinds / (dom::kPhiKinds * dom::kMKinds) == 0)  // F once per (phi, m) sample
      check(f_stats, "F", math::ellint_f(phi, m),
            static_cast<double>(math::ellint_f(Real50(phi), Real50(m))), where);
  }
  std::printf(
      "Corner sweep vs 50 digits: Pi (%s) max %lld ulp RMS %.3f; Pi (portable) max %lld "
      "ulp RMS %.3f; F max %lld ulp RMS %.3f (%zu/%zu/%zu samples)\n",
      kernel ? "kernel" : "portable", (long long)pi_stats.max, pi_stats.rms(),
      (long long)portable_stats.max, portable_stats.rms(), (long long)f_stats.max, f_stats.rms(),
      pi_stats.count, portable_stats.count, f_stats.count);
  for (std::size_t j = 0; j < kernels.size(); ++j)
    std::printf("Corner sweep, kernel copy %s: max %lld ulp RMS %.3f\n",
                math::detail::pi_dd_kernel_name(kernels[j]), (long long)copy_stats[j].max,
                copy_stats[j].rms());
  if (kernels.size() > 1)
    std::printf("Kernel copies differ (by 1 ulp) on %d of %d samples\n", copies_differ, kSamples);
}

// The kernel's double-double elementary functions (elliptic_pi_dd_kernel.inc), in every copy this
// CPU runs, against cpp_bin_float_50.
// Their error enters Pi once, scaled by at most ~1 (no cancellation between Pi's terms), so each
// must stay well under a correctly rounded double's 2^-53. Bounds from their error analysis (the
// measured maxima are printed): atan, log and R_C carry only first-order corrections and series
// tails below 2^-58, so 2^-55; sin and cos come from a table of double-doubles and Taylor
// terms through t^7 at |t| <= pi/256 (omitted terms below 2^-66), rounding in double only what is
// below 7.5e-5 of the value: 2^-64, checked at 2^-62 (a factor 4 for the roundings not counted),
// at random phi and at the table's nodes j pi/128 and midpoints, where |t| is largest.
TEST(EllipticReference, KernelElementaryFunctionsWithin2em55Of50Digits) {
  const auto kernels = supported_kernels();
  if (kernels.empty())
    GTEST_SKIP() << "this CPU lacks AVX2/FMA: the kernel and its functions are not used";
  namespace dom = elliptic_domain;
  namespace d = math::detail;
  using DDv = d::DoubleDouble;
  const Real50 kBound = Real50(std::ldexp(1.0, -55)), kSinCosBound = Real50(std::ldexp(1.0, -62));
  auto value = [](DDv x) { return Real50(x.hi) + Real50(x.lo); };
  auto rel = [](const Real50& got, const Real50& ref) { return Real50(abs((got - ref) / ref)); };
  sequence::Pcg32 rng(2026, 5);
  Real50 worst_sc = 0, worst_atan = 0, worst_log = 0, worst_rc = 0;
  for (int i = 0; i < 3000; ++i) {
    // sin, cos of phi in [0, pi/2] (phi > 0: the kernel's domain), corners included.
    const double phi = dom::phi(i % dom::kPhiKinds, rng.next_double());
    // atan of x = 10^(-8..8) carrying a lo part.
    const double xh = std::pow(10.0, 16 * rng.next_double() - 8);
    const DDv x = {xh, xh * 0x1p-54 * (2 * rng.next_double() - 1)};
    // log of x in [1 + 2^-40, 1e9] (the kernel's (1 + r)/(1 - r), r in [0.1, 1)).
    const double yh = 1 + std::pow(10.0, 21 * rng.next_double() - 12);
    const DDv y = {yh, yh * 0x1p-54 * (2 * rng.next_double() - 1)};
    // R_C(1, 1 + e) - 1 for e in +-[0.01, 1) and e -> -1, error relative to R_C.
    const double u = rng.next_double();
    const double e = i % 3 == 0   ? 0.01 + 0.99 * u
                     : i % 3 == 1 ? -0.01 - 0.99 * u
                                  : -(1 - std::pow(10.0, -8 * u));
    const Real50 E(e), r = sqrt(abs(E));
    const Real50 rc = e > 0 ? Real50(atan(r) / r) : Real50(atanh(r) / r);
    const Real50 atan_ref = atan(value(x)), log_ref = log(value(y));
    for (const d::PiKernel k : kernels) {
      const char* name = d::pi_dd_kernel_name(k);
      if (phi > 0) {
        DDv s, c;
        d::pi_dd_sincos(k, phi, s, c);
        const Real50 es = rel(value(s), sin(Real50(phi))), ec = rel(value(c), cos(Real50(phi)));
        worst_sc = std::max(worst_sc, std::max(es, ec));
        EXPECT_LE(std::max(es, ec), kSinCosBound) << name << " sincos phi=" << phi;
      }
      const Real50 ea = rel(value(d::pi_dd_atan(k, x)), atan_ref);
      worst_atan = std::max(worst_atan, ea);
      EXPECT_LE(ea, kBound) << name << " atan x=" << xh;
      const Real50 el = rel(value(d::pi_dd_log(k, y)), log_ref);
      worst_log = std::max(worst_log, el);
      EXPECT_LE(el, kBound) << name << " log x=" << yh;
      const Real50 er = abs((value(d::pi_dd_rc_minus_1(k, {e, 0})) + 1 - rc) / rc);
      worst_rc = std::max(worst_rc, er);
      EXPECT_LE(er, kBound) << name << " R_C e=" << e;
    }
  }
  for (int j = 0; j <= 128; ++j) {  // nodes (even j) and midpoints (odd j) of the sincos table
    const double phi = std::max(1e-300, j * (std::numbers::pi / 256));
    for (const d::PiKernel k : kernels) {
      DDv s, c;
      d::pi_dd_sincos(k, phi, s, c);
      const Real50 es = rel(value(s), sin(Real50(phi))), ec = rel(value(c), cos(Real50(phi)));
      worst_sc = std::max(worst_sc, std::max(es, ec));
      EXPECT_LE(std::max(es, ec), kSinCosBound) << d::pi_dd_kernel_name(k) << " sincos phi=" << phi;
    }
  }
  std::printf(
      "kernel functions (%zu copies), max relative error: sincos %.2g, atan %.2g, log %.2g, "
      "R_C %.2g (bounds 2^-62, 2^-55 = %.2g)\n",
      kernels.size(), double(worst_sc), double(worst_atan), double(worst_log), double(worst_rc),
      std::ldexp(1.0, -55));
}

// The same templates in cpp_bin_float_50: proves they run at high precision and checks
// Carlson's algorithms (series coefficients included) against the independent quadrature.
TEST(EllipticReference, Float50TemplatesAgreeWithTablesTo1em40) {
  Real50 worst = 0;
  for (const auto& [name, inputs] : {std::pair{"elliptic_f.csv", 2}, {"elliptic_pi.csv", 3}}) {
    for (const EllipticRow& row : read_elliptic_table(name, inputs)) {
      const Real50 ref(row.value);
      Real50 value;
      if (inputs == 2)
        value = math::ellint_f(Real50(row.inputs[0]), Real50(row.inputs[1]));
      else
        value =
            math::ellint_pi(Real50(row.inputs[0]), Real50(row.inputs[1]), Real50(row.inputs[2]));
      const Real50 rel = abs(value - ref) / abs(ref);
      if (rel > worst) worst = rel;
      EXPECT_LE(rel, kHighPrecisionRelative)
          << name << ": " << describe(row.inputs, value.convert_to<double>(), row)
          << " value50=" << value.str(50) << " rel=" << rel.str(5);
    }
  }
  std::printf("cpp_bin_float_50 vs tables: worst relative %s\n", worst.str(4).c_str());
}

// The kernel's degree-9 series tails (lib/src/math/elliptic_pi_dd.h) against 50-digit R_F and
// R_J, at A = 1 with relative deviations of size delta in random directions. Their error is the
// truncation, O(delta^10): halving delta divides its sum over the samples by 2^10 = 1024. A missing
// degree-9 term leaves O(delta^9), a ratio near 512 (zeroing R_F's E3^3 term: 550); so the test
// asks for more than 2^9.5 = 724. A coefficient off by a few percent can pass (R_J's E4 E5 term
// off by 3.5%: 893): the Pi tables then bound its effect. The degree-7 tails, O(delta^8), must show
// a ratio near 256 (below 362 = 2^8.5): the test tells the orders apart. delta = 0.02 and 0.01 keep
// the errors (1e-17 to 1e-21) far above cpp_bin_float_50's rounding.
TEST(EllipticReference, SeriesTailsOfDegree9) {
  sequence::Pcg32 rng(2026, 9);
  Real50 err_f9[2] = {0, 0}, err_j9[2] = {0, 0}, err_f7[2] = {0, 0}, err_j7[2] = {0, 0};
  for (int i = 0; i < 400; ++i) {
    const double u = 2 * rng.next_double() - 1, v = 2 * rng.next_double() - 1,
                 w = 2 * rng.next_double() - 1;
    for (int h = 0; h < 2; ++h) {
      const Real50 delta = h == 0 ? Real50(0.02) : Real50(0.01);
      // R_F(1 - X, 1 - Y, 1 - Z) with X + Y + Z = 0: A = 1, R_F = 1 + tail.
      const Real50 X = delta * u, Y = delta * v, Z = -(X + Y);
      const Real50 tail_f = math::carlson_rf(1 - X, 1 - Y, 1 - Z) - 1;
      err_f9[h] += abs(math::detail::rf_series_tail9(X * Y - Z * Z, X * Y * Z) - tail_f);
      err_f7[h] += abs(math::detail::rf_series_tail(X * Y - Z * Z, X * Y * Z) - tail_f);
      // R_J(1 - X, 1 - Y, 1 - Z, 1 - P) with P = -(X + Y + Z)/2: A = 1, R_J = 1 + tail.
      const Real50 Xj = delta * u, Yj = delta * v, Zj = delta * w, P = -(Xj + Yj + Zj) / 2;
      const Real50 tail_j = math::carlson_rj(1 - Xj, 1 - Yj, 1 - Zj, 1 - P) - 1;
      err_j9[h] += abs(math::detail::rj_series_tail9(Xj, Yj, Zj) - tail_j);
      err_j7[h] += abs(math::detail::rj_series_tail(Xj, Yj, Zj) - tail_j);
    }
  }
  const double rf9 = double(err_f9[0] / err_f9[1]), rj9 = double(err_j9[0] / err_j9[1]);
  const double rf7 = double(err_f7[0] / err_f7[1]), rj7 = double(err_j7[0] / err_j7[1]);
  std::printf(
      "series tails, error ratio for delta 0.02 / 0.01: degree 9 R_F %.0f R_J %.0f, degree 7 "
      "R_F %.0f R_J %.0f (mean error at 0.02: %.2g %.2g)\n",
      rf9, rj9, rf7, rj7, double(err_f9[0] / 400), double(err_j9[0] / 400));
  EXPECT_GT(rf9, 724);
  EXPECT_GT(rj9, 724);
  EXPECT_LT(rf7, 362);
  EXPECT_LT(rj7, 362);
}

// F's kernel (lib/src/math/elliptic_pi_dd_kernel.inc) in every copy this CPU runs, and F's
// portable path, each faithfully rounded on both F tables (the copies' arguments: phi in
// (0, pi/2], m in [0, 1]; ellint_f<double> runs one of them, tested above).
TEST(EllipticReference, FKernelCopiesAndPortablePathFaithfulOnBothTables) {
  namespace d = math::detail;
  const auto kernels = supported_kernels();
  for (const char* name : {"elliptic_f.csv", "elliptic_f_boost_inputs.csv"}) {
    std::size_t rows_in_domain = 0;
    for (const EllipticRow& row : read_elliptic_table(name, 2)) {
      const double phi = row.inputs[0], m = row.inputs[1];
      if (!(phi > 0 && phi <= elliptic_domain::kHalfPi && m >= 0 && m <= 1)) continue;
      ++rows_in_domain;
      const Real50 exact(row.value);
      const double portable = d::ellint_f_core(phi, m, 1.0 - m);
      EXPECT_TRUE(rounding_error(portable, exact).faithful)
          << name << " portable: " << describe(row.inputs, portable, row);
      for (const d::PiKernel k : kernels) {
        const double own = d::ellint_f_dd(k, phi, m);
        EXPECT_TRUE(rounding_error(own, exact).faithful)
            << name << " " << d::pi_dd_kernel_name(k) << ": " << describe(row.inputs, own, row);
        // With the caller's complement (exact here for m >= 0.5, Sterbenz): the same bits.
        if (m >= 0.5) {
          EXPECT_EQ(d::ellint_f_dd(k, phi, m, 1.0 - m, 0.0), own) << name;
        }
      }
    }
    EXPECT_GT(rows_in_domain, 100u) << name;
  }
}

// The series of F's kernel: R_F(r_1^2, r_2^2, r_3^2) = (1 + G(e2, e3)) / mu for roots
// r_j = mu (1 + d_j), sum d_j = 0, against 50-digit R_F at mu = 1 and |d_j| up to the kernel's
// tolerance (0.2). Bound: the kernel's error budget for the series, truncation beyond degree 17
// below 2^-62.8 and the double evaluation of |G| < 0.0027 below 2^-58. A wrong coefficient of
// degree up to 14 exceeds it at |d| = 0.2 (its term is 1e-10 to 1e-17 there).
TEST(EllipticReference, FKernelSeriesAgainst50Digits) {
  namespace d = math::detail;
  const auto kernels = supported_kernels();
  if (kernels.empty()) GTEST_SKIP() << "this CPU lacks AVX2/FMA: F's kernel is not used";
  const double kBound = std::ldexp(1.0, -58) + std::exp2(-62.8);
  const double tol = d::kFKernelSeriesRange;
  sequence::Pcg32 rng(2026, 16);
  double worst = 0;
  for (int i = 0; i < 2000; ++i) {
    // d on the boundary of |d_j| <= tol for half of the samples (the largest terms).
    const double scale = i % 2 == 0 ? tol : tol * rng.next_double();
    const double d0 = scale * (2 * rng.next_double() - 1), d1 = scale * (2 * rng.next_double() - 1);
    if (std::fabs(d0 + d1) > tol) continue;  // |d_2| within the tolerance too
    const Real50 D0(d0), D1(d1), D2 = -(D0 + D1);
    const Real50 g_exact =
        math::carlson_rf((1 + D0) * (1 + D0), (1 + D1) * (1 + D1), (1 + D2) * (1 + D2)) - 1;
    const double p01 = d0 * d1, s01 = d0 + d1;
    const double e2 = p01 - s01 * s01, e3 = -p01 * s01;
    for (const d::PiKernel k : kernels) {
      // The reference at the double e2, e3 actually passed: G is a polynomial in them, and the
      // exact e2, e3 of d0, d1 differ by their rounding, which moves G by below 2^-60.
      const double err = std::fabs(double(Real50(d::f_dd_series(k, e2, e3)) - g_exact));
      worst = std::max(worst, err);
      EXPECT_LE(err, kBound) << d::pi_dd_kernel_name(k) << " d0=" << d0 << " d1=" << d1;
    }
  }
  std::printf("F kernel series vs 50 digits at |d| <= %.2g: max error %.2g (bound %.2g)\n", tol,
              worst, kBound);
}

// F's kernel takes its series after 0, 1, 2 or more duplication steps, as the roots' spread
// allows (f_converged in the kernel). The series' error is largest where the spread only just
// passes, with |d_j| near the tolerance: faithful there, on both sides of every change of the
// step count, against 50-digit F. The changes are found by bisection on phi of the kernel's
// spread test evaluated in double, for m from 0 to 1 - 1e-12 (the test's roots differ from the
// kernel's by roundings, so each change is probed a few ulps to either side).
TEST(EllipticReference, FKernelFaithfulWhereItsStepCountChanges) {
  namespace d = math::detail;
  const auto kernels = supported_kernels();
  if (kernels.empty()) GTEST_SKIP() << "this CPU lacks AVX2/FMA: F's kernel is not used";
  const double tol = d::kFKernelSpread;
  auto steps = [tol](double phi, double m) {
    const double s = std::sin(phi), c = std::cos(phi);
    double r0 = c, r1 = std::sqrt(c * c + (1 - m) * s * s), r2 = 1.0;
    int k = 0;
    while (3 * (r2 - r0) > tol * (r0 + r1 + r2)) {
      const double a = std::sqrt((r0 + r1) * (r0 + r2)), b = std::sqrt((r1 + r0) * (r1 + r2));
      r2 = std::sqrt((r2 + r0) * (r2 + r1));
      r0 = a;
      r1 = b;
      ++k;
    }
    return k;
  };
  std::array<int, 4> probed{};  // probes by step count: 0, 1, 2, 3 or more
  for (const double m :
       {0.0, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1 - 1e-3, 1 - 1e-6, 1 - 1e-9, 1 - 1e-12, 1.0}) {
    for (int k = 1; k <= 4 && steps(elliptic_domain::kHalfPi, m) >= k; ++k) {
      double lo = 0x1p-20, hi = elliptic_domain::kHalfPi;  // steps(lo, m) = 0 < k <= steps(hi, m)
      for (int it = 0; it < 80 && std::nextafter(lo, hi) < hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        (steps(mid, m) < k ? lo : hi) = mid;
      }
      double phi = lo;
      for (int j = 0; j < 3; ++j)
        phi = std::nextafter(phi, 0.0);
      for (int j = 0; j < 8 && phi <= elliptic_domain::kHalfPi;
           ++j, phi = std::nextafter(phi, 4.0)) {
        ++probed[std::min(steps(phi, m), 3)];
        const Real50 exact = math::ellint_f(Real50(phi), Real50(m));
        for (const d::PiKernel kernel : kernels) {
          const double own = d::ellint_f_dd(kernel, phi, m);
          const RoundingError e = rounding_error(own, exact);
          EXPECT_TRUE(e.faithful) << d::pi_dd_kernel_name(kernel) << " phi=" << phi << " m=" << m
                                  << " own=" << own << " exact=" << exact;
        }
      }
    }
  }
  std::printf(
      "F kernel at its step-count changes: %d / %d / %d / %d probes after 0 / 1 / 2 / 3+ "
      "steps\n",
      probed[0], probed[1], probed[2], probed[3]);
  for (int k = 0; k < 4; ++k)
    EXPECT_GT(probed[k], 0) << "no probe after " << k << " steps";
}

// F's kernel at small amplitudes (phi <= kFSmallPhi) returns phi (1 + eps) with eps in plain
// double (f_small_eps in the kernel): the absolute error of eps, F's relative error before the
// one rounding, stays below the kernel's derived bound kFSmallEpsBound (3 * 2^-56) against
// 50-digit F, in every copy, on phi uniform up to the threshold, at it, near 0 and in the
// subnormal range, with m uniform, at 0 and 1 and near both; and the rounded F is faithful.
TEST(EllipticReference, FSmallAmplitudeEpsWithinItsBound) {
  namespace d = math::detail;
  const auto kernels = supported_kernels();
  if (kernels.empty()) GTEST_SKIP() << "this CPU lacks AVX2/FMA: F's kernel is not used";
  // The series needs the roots' deviations within kFKernelSeriesRange: at most 2v/(3 - 2v)
  // with v = 1 - cos phi (the derivation at f_small_eps).
  const double v_max = 1 - std::cos(d::kFSmallPhi);
  EXPECT_LE(2 * v_max / (3 - 2 * v_max), d::kFKernelSeriesRange);
  sequence::Pcg32 rng(2026, 1206);
  const Real50 bound(d::kFSmallEpsBound);
  Real50 worst = 0;
  std::string worst_at;
  for (int i = 0; i < 4000; ++i) {
    const double u = rng.next_double();
    const int phi_kind = i % 4;
    double phi = phi_kind == 0   ? d::kFSmallPhi * (1 - u)                        // (0, 0.72]
                 : phi_kind == 1 ? d::kFSmallPhi * (1 - std::pow(10.0, -12 * u))  // below it
                 : phi_kind == 2 ? d::kFSmallPhi * std::pow(10.0, -8 * u)         // phi -> 0
                                 : std::ldexp(1.0 + u, -1070 + int(1000 * rng.next_double()));
    if (i == 0) phi = d::kFSmallPhi;
    if (!(phi > 0)) continue;
    const double w = rng.next_double();
    const int m_kind = (i / 4) % 5;
    const double m = m_kind == 0   ? w
                     : m_kind == 1 ? elliptic_domain::near_one(w)
                     : m_kind == 2 ? std::pow(10.0, -17 * w)
                     : m_kind == 3 ? (i % 8 < 4 ? 0.0 : 1.0)
                                   : 0.5 + 0.5 * w;
    const Real50 exact = math::ellint_f(Real50(phi), Real50(m));
    for (const d::PiKernel kernel : kernels) {
      const double eps = d::f_dd_small_eps(kernel, phi, m);
      const Real50 err = abs(Real50(phi) * (1 + Real50(eps)) - exact) / exact;
      if (err > worst) {
        worst = err;
        worst_at = "phi=" + std::to_string(phi) + " m=" + std::to_string(m);
      }
      EXPECT_LE(err, bound) << d::pi_dd_kernel_name(kernel) << " phi=" << phi << " m=" << m
                            << " eps=" << eps << " exact=" << exact;
      const double own = d::ellint_f_dd(kernel, phi, m);
      EXPECT_TRUE(rounding_error(own, exact).faithful)
          << d::pi_dd_kernel_name(kernel) << " phi=" << phi << " m=" << m << " own=" << own;
    }
  }
  std::printf(
      "F at small amplitudes: eps within %.3f u of exact (bound %.3f u, u = 2^-53), at %s\n",
      double(worst * Real50(std::ldexp(1.0, 53))), std::ldexp(d::kFSmallEpsBound, 53),
      worst_at.c_str());
}

// K(m) from the kernel's piecewise polynomials (lib/src/math/elliptic_k_table.inc), which the
// complement path below subtracts from: within kKCompleteBound (0.05 u) of Boost's ellint_1 in 50
// digits, on m uniform over the table's range [0, 15/16], at both sides of every piece boundary
// (x = 1 - m = 2^E (1 + p/4)) and at its ends.
TEST(EllipticReference, FComplementKWithinItsBound) {
  namespace d = math::detail;
  const auto kernels = supported_kernels();
  if (kernels.empty()) GTEST_SKIP() << "this CPU lacks AVX2/FMA: F's kernel is not used";
  std::vector<double> ms = {0.0, 15.0 / 16};
  for (int E = -4; E <= -1; ++E)
    for (int p = 0; p <= 4; ++p) {
      const double x = std::ldexp(1.0 + p / 4.0, E);
      for (const double xx : {std::nextafter(x, 0.0), x, std::nextafter(x, 2.0)})
        if (xx >= 1.0 / 16 && xx <= 1.0) ms.push_back(1.0 - xx);  // 1 - xx is exact here
    }
  sequence::Pcg32 rng(2026, 1207);
  for (int i = 0; i < 3000; ++i)
    ms.push_back(15.0 / 16 * rng.next_double());
  const Real50 bound(d::kKCompleteBound);
  Real50 worst = 0;
  for (const double m : ms) {
    const Real50 exact = boost::math::ellint_1(sqrt(Real50(m)));
    for (const d::PiKernel kernel : kernels) {
      const d::DoubleDouble k = d::k_dd_complete(kernel, m);
      const Real50 err = abs(Real50(k.hi) + Real50(k.lo) - exact) / exact;
      worst = std::max(worst, err);
      EXPECT_LE(err, bound) << d::pi_dd_kernel_name(kernel) << " m=" << m;
    }
  }
  std::printf("K(m) of the complement path: within %.4f u of 50 digits (bound %.2f u)\n",
              double(worst * Real50(std::ldexp(1.0, 53))), std::ldexp(d::kKCompleteBound, 53));
}

// F's kernel near phi = pi/2 takes F(phi|m) = K(m) - F(psi|m) (f_complement in the kernel) where
// chi = pi/2 - phi has chi^2 <= kFComplementRegion (1 - m), m <= 15/16: its value before the one
// rounding within kFComplementBound (0.44 u) of 50-digit F, in every copy, over that region, on
// its edge and at phi = fl(pi/2) (chi = 0 in double), with m uniform, 0 and 15/16; the eps of
// F(chi|m') it takes (m' = -m/(1 - m) < 0) within kFSmallEpsBound; and ellint_f faithful there.
TEST(EllipticReference, FComplementWithinItsBound) {
  namespace d = math::detail;
  const auto kernels = supported_kernels();
  if (kernels.empty()) GTEST_SKIP() << "this CPU lacks AVX2/FMA: F's kernel is not used";
  sequence::Pcg32 rng(2026, 1208);
  const Real50 bound(d::kFComplementBound), eps_bound(d::kFSmallEpsBound);
  const Real50 half_pi = boost::math::constants::half_pi<Real50>();
  Real50 worst = 0, worst_eps = 0;
  std::string worst_at;
  int in_region = 0;
  for (int i = 0; i < 3000; ++i) {
    const int m_kind = i % 4;
    const double m = m_kind == 0 ? 0.0 : m_kind == 1 ? 15.0 / 16 : 15.0 / 16 * rng.next_double();
    const double x = 1.0 - m;  // exact for m >= 1/2, and what the kernel's region test reads
    const double chi_max = std::sqrt(d::kFComplementRegion * x);
    const int chi_kind = (i / 4) % 3;
    const double u = rng.next_double();
    double phi = chi_kind == 0   ? elliptic_domain::kHalfPi - chi_max * u
                 : chi_kind == 1 ? elliptic_domain::kHalfPi - chi_max * (1 - 1e-9 * u)  // edge
                                 : elliptic_domain::kHalfPi;
    const double chi = elliptic_domain::kHalfPi - phi;
    if (!(chi * chi <= d::kFComplementRegion * x)) phi = std::nextafter(phi, 2.0);
    if (!((elliptic_domain::kHalfPi - phi) * (elliptic_domain::kHalfPi - phi) <=
          d::kFComplementRegion * x))
      continue;
    ++in_region;
    const Real50 exact = math::ellint_f(Real50(phi), Real50(m));
    // F(chi|m') exactly, for eps: chi = pi/2 - phi in 50 digits, m' = -m/(1 - m).
    const Real50 chi50 = half_pi - Real50(phi), mt50 = -Real50(m) / (1 - Real50(m));
    const double mt = static_cast<double>(mt50);
    for (const d::PiKernel kernel : kernels) {
      const d::DoubleDouble f = d::f_dd_complement(kernel, phi, m);
      const Real50 err = abs(Real50(f.hi) + Real50(f.lo) - exact) / exact;
      if (err > worst) {
        worst = err;
        worst_at = "phi=" + std::to_string(phi) + " m=" + std::to_string(m);
      }
      EXPECT_LE(err, bound) << d::pi_dd_kernel_name(kernel) << " phi=" << phi << " m=" << m;
      const double own = d::ellint_f_dd(kernel, phi, m);
      EXPECT_TRUE(rounding_error(own, exact).faithful)
          << d::pi_dd_kernel_name(kernel) << " phi=" << phi << " m=" << m << " own=" << own;
      // eps at a double chi and m' (the kernel's are pairs): F(chi|m')/chi - 1 in 50 digits.
      const double chi_d = static_cast<double>(chi50);
      if (chi_d > 0) {
        const double eps = d::f_dd_small_eps(kernel, chi_d, mt);
        const Real50 f_chi = math::ellint_f(Real50(chi_d), Real50(mt));
        const Real50 e = abs(Real50(chi_d) * (1 + Real50(eps)) - f_chi) / f_chi;
        worst_eps = std::max(worst_eps, e);
        EXPECT_LE(e, eps_bound) << "eps at chi=" << chi_d << " m'=" << mt;
      }
    }
  }
  EXPECT_GT(in_region, 2500);
  std::printf(
      "F by the complement: within %.3f u of 50 digits before rounding (bound %.2f u), at %s; "
      "its eps within %.3f u (bound %.3f u)\n",
      double(worst * Real50(std::ldexp(1.0, 53))), std::ldexp(d::kFComplementBound, 53),
      worst_at.c_str(), double(worst_eps * Real50(std::ldexp(1.0, 53))),
      std::ldexp(d::kFSmallEpsBound, 53));
}

TEST(EllipticReference, MissingTableFailsLoudly) {
  EXPECT_THROW(read_elliptic_table("no_such_table.csv", 2), std::runtime_error);
}

}  // namespace
}  // namespace disklab::test
