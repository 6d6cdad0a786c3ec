#pragma once
// Convergence slopes and their uncertainty.
//  - fit_log_log: least-squares line through (log N, log y); its slope is the convergence order.
//  - SeedBootstrap: resampling of the randomizations (seeds) with replacement, the unit the
//    study repeats independently. A statistic computed from per-seed data with replicate
//    weights (how often each seed was drawn) gives its bootstrap standard error.
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace disklab::study {

struct LineFit {
  double slope = 0.0;
  double intercept = 0.0;  // of log(y) at log(x) = 0
};

// Throws std::invalid_argument for fewer than two points, unequal lengths or a non-positive
// value (the logarithm would be undefined).
LineFit fit_log_log(std::span<const double> x, std::span<const double> y);

class SeedBootstrap {
 public:
  // `replicates` resamples of `seeds` seeds, drawn deterministically from `rng_seed`.
  SeedBootstrap(uint32_t seeds, int replicates, uint64_t rng_seed);

  uint32_t seeds() const { return seeds_; }
  int replicates() const { return static_cast<int>(weights_.size()); }
  // How often each seed appears in replicate r (sums to seeds()).
  std::span<const uint32_t> weights(int r) const { return weights_[r]; }

  // Standard deviation over the replicates of a statistic of the weights (replicates where it
  // is undefined are skipped; nullopt when fewer than two are defined).
  std::optional<double> standard_error(
      const std::function<std::optional<double>(std::span<const uint32_t>)>& statistic) const;

 private:
  uint32_t seeds_;
  std::vector<std::vector<uint32_t>> weights_;
};

}  // namespace disklab::study
