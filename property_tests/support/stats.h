#pragma once
// Statistical helpers shared by the property suites.
#include <cstddef>
#include <string>
#include <vector>

namespace disklab::test {

// Per-test significance so that `tests` independent tests together reject a correct
// implementation with probability `family_alpha` (Sidak correction).
double sidak_alpha(double family_alpha, std::size_t tests);

struct ChiSquareResult {
  double statistic = 0.0;
  std::size_t dof = 0;     // degrees of freedom after pooling
  double p_value = 1.0;    // P(X >= statistic) under the null hypothesis
  std::size_t pooled = 0;  // bins merged because their expected count was small
  std::string summary() const;
};

// Pearson chi-square goodness of fit, Mitsuba-style: bins whose expected count is below
// `min_expected` are pooled into one (then dropped if even the pool stays below it), so the
// chi-square approximation holds. `expected` must sum to the number of samples.
ChiSquareResult chi_square(const std::vector<double>& observed, const std::vector<double>& expected,
                           double min_expected = 5.0);

// Mean and the standard error of the mean of a sample.
struct MeanEstimate {
  double mean = 0.0;
  double std_error = 0.0;
  std::size_t n = 0;
};
MeanEstimate mean_estimate(const std::vector<double>& values);

// Two-sided normal quantile z with P(|Z| > z) = alpha.
double normal_two_sided_quantile(double alpha);

// Least-squares slope of log(y) against log(x): the convergence order of an error curve.
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace disklab::test
