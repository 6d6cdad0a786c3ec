#include "study/fit.h"

#include <cmath>
#include <stdexcept>

#include "disklab/sequence/random.h"

namespace disklab::study {

LineFit fit_log_log(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size() || x.size() < 2)
    throw std::invalid_argument("fit_log_log: needs two or more (x, y) pairs of equal count");
  double sx = 0.0, sy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] > 0.0) || !(y[i] > 0.0))
      throw std::invalid_argument("fit_log_log: values must be positive");
    sx += std::log(x[i]);
    sy += std::log(y[i]);
  }
  const double n = static_cast<double>(x.size()), mx = sx / n, my = sy / n;
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double dx = std::log(x[i]) - mx;
    sxx += dx * dx;
    sxy += dx * (std::log(y[i]) - my);
  }
  if (!(sxx > 0.0)) throw std::invalid_argument("fit_log_log: all x are equal");
  const double slope = sxy / sxx;
  return {slope, my - slope * mx};
}

SeedBootstrap::SeedBootstrap(uint32_t seeds, int replicates, uint64_t rng_seed) : seeds_(seeds) {
  if (seeds == 0 || replicates < 0) throw std::invalid_argument("SeedBootstrap: no seeds");
  sequence::Pcg32 rng(rng_seed);
  weights_.assign(replicates, std::vector<uint32_t>(seeds, 0));
  // Index by the high half of a 32 x 32-bit product (Lemire): bias below seeds / 2^32.
  for (auto& w : weights_)
    for (uint32_t i = 0; i < seeds; ++i)
      ++w[(uint64_t{rng.next_u32()} * seeds) >> 32u];
}

std::optional<double> SeedBootstrap::standard_error(
    const std::function<std::optional<double>(std::span<const uint32_t>)>& statistic) const {
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  for (const auto& w : weights_) {
    const std::optional<double> v = statistic(w);
    if (!v || !std::isfinite(*v)) continue;
    sum += *v;
    sum2 += *v * *v;
    ++n;
  }
  if (n < 2) return std::nullopt;
  const double mean = sum / n;
  return std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / (n - 1)));
}

}  // namespace disklab::study
