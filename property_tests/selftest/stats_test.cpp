// The statistical helpers must be able to fail: a chi-square that passes everything would
// make every uniformity test in the project vacuous.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/stats.h"

namespace disklab::test {
namespace {

// Family significance of this file's tests; each assertion below is a single test.
constexpr double kAlpha = 1e-4;
// Closed-form checks of a few roundings (pow, sqrt, a sum of four): 1e-15 absolute on O(1)
// values; the normal quantile and the log-log fit go through a series and a dozen logarithms.
constexpr double kFewRoundings = 1e-15;
constexpr double kSeriesRoundings = 1e-12;

TEST(Stats, SidakMatchesDefinition) {
  const double a = sidak_alpha(0.01, 10);
  EXPECT_NEAR(1.0 - std::pow(1.0 - a, 10), 0.01, kFewRoundings);
  EXPECT_LT(a, 0.01 / 10 * 1.01);  // slightly above Bonferroni, never far from it
  EXPECT_GT(a, 0.01 / 10);
}

TEST(Stats, ChiSquareAcceptsFairDieAndRejectsLoadedOne) {
  std::mt19937_64 rng(12345);
  const int bins = 20, n = 200000;
  std::vector<double> fair(bins, 0.0), loaded(bins, 0.0), expected(bins, double(n) / bins);
  std::uniform_int_distribution<int> die(0, bins - 1);
  for (int i = 0; i < n; ++i) {
    fair[die(rng)] += 1.0;
    // A fifth of bin 1's samples move to bin 0: 2000 counts against a Poisson spread of
    // ~100 per bin, about 20 sigma, so the test must reject it.
    const int k = die(rng);
    loaded[(k == 1 && (i % 5 == 0)) ? 0 : k] += 1.0;
  }
  EXPECT_GT(chi_square(fair, expected).p_value, kAlpha);
  EXPECT_LT(chi_square(loaded, expected).p_value, kAlpha);
}

TEST(Stats, ChiSquarePoolsSmallBinsAndFlagsMassWhereNoneIsExpected) {
  std::vector<double> expected{50, 50, 1e-3, 1e-3}, observed{50, 50, 0, 0};
  const auto ok = chi_square(observed, expected);
  EXPECT_EQ(ok.pooled, 2u);
  EXPECT_GT(ok.p_value, 0.5);
  std::vector<double> bad{40, 40, 10, 10};
  EXPECT_EQ(chi_square(bad, expected).p_value, 0.0);
}

TEST(Stats, LogLogSlopeRecoversPowerLaw) {
  std::vector<double> x, y;
  for (int k = 4; k <= 12; ++k) {
    x.push_back(std::ldexp(1.0, k));
    y.push_back(3.0 * std::pow(x.back(), -1.5));
  }
  EXPECT_NEAR(log_log_slope(x, y), -1.5, kSeriesRoundings);
}

TEST(Stats, MeanEstimateStandardError) {
  const auto m = mean_estimate({1.0, 2.0, 3.0, 4.0});
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_NEAR(m.std_error, std::sqrt(5.0 / 3.0 / 4.0), kFewRoundings);
  EXPECT_NEAR(normal_two_sided_quantile(0.05), 1.959963984540054, kSeriesRoundings);
}

}  // namespace
}  // namespace disklab::test
