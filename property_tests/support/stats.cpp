#include "support/stats.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>

namespace disklab::test {

double sidak_alpha(double family_alpha, std::size_t tests) {
  return -std::expm1(std::log1p(-family_alpha) / static_cast<double>(tests));
}

std::string ChiSquareResult::summary() const {
  std::ostringstream s;
  s << "chi2=" << statistic << " dof=" << dof << " p=" << p_value << " pooled_bins=" << pooled;
  return s.str();
}

ChiSquareResult chi_square(const std::vector<double>& observed, const std::vector<double>& expected,
                           double min_expected) {
  if (observed.size() != expected.size()) throw std::invalid_argument("chi_square: size mismatch");
  ChiSquareResult r;
  double pool_obs = 0.0, pool_exp = 0.0;
  std::size_t bins = 0;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < min_expected) {
      pool_obs += observed[i];
      pool_exp += expected[i];
      ++r.pooled;
      continue;
    }
    const double d = observed[i] - expected[i];
    r.statistic += d * d / expected[i];
    ++bins;
  }
  if (pool_exp >= min_expected) {
    const double d = pool_obs - pool_exp;
    r.statistic += d * d / pool_exp;
    ++bins;
  } else if (pool_obs > 10.0 * std::max(pool_exp, 1.0)) {
    // Samples where the model says there is (almost) nothing: a clear failure.
    r.statistic = INFINITY;
  }
  if (bins < 2) throw std::invalid_argument("chi_square: fewer than two usable bins");
  r.dof = bins - 1;
  if (std::isinf(r.statistic)) {
    r.p_value = 0.0;
  } else {
    boost::math::chi_squared dist(static_cast<double>(r.dof));
    r.p_value = boost::math::cdf(boost::math::complement(dist, r.statistic));
  }
  return r;
}

MeanEstimate mean_estimate(const std::vector<double>& values) {
  MeanEstimate m;
  m.n = values.size();
  if (m.n < 2) throw std::invalid_argument("mean_estimate: need at least two values");
  // Two-pass for accuracy.
  double sum = 0.0;
  for (double v : values)
    sum += v;
  m.mean = sum / static_cast<double>(m.n);
  double ss = 0.0;
  for (double v : values)
    ss += (v - m.mean) * (v - m.mean);
  m.std_error = std::sqrt(ss / static_cast<double>(m.n - 1) / static_cast<double>(m.n));
  return m;
}

double normal_two_sided_quantile(double alpha) {
  return boost::math::quantile(boost::math::complement(boost::math::normal(), alpha / 2.0));
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size() || x.size() < 2) throw std::invalid_argument("log_log_slope: sizes");
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace disklab::test
