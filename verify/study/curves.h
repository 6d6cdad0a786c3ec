#pragma once
// Error curves of a study: for every (region, method, sequence) and sample count N, per-seed sums
// over the region's shading points of squared (and relative squared) errors. RMS error, its
// slope in log-log and bootstrap standard errors follow from them. Both studies fill one:
// `convergence` with disk strategies as methods, `variance` with ellipse maps.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "study/fit.h"

namespace disklab::study {

struct CurveAxes {
  std::vector<std::string> regions, methods, sequences;
  std::vector<std::size_t> points;  // shading points per region
  std::vector<uint32_t> ns;         // increasing
  uint32_t fit_min = 64;            // slopes fit N in [fit_min, ns.back()]
  uint32_t seeds = 0;
};

class CurveTable {
 public:
  CurveAxes axes;
  // [curve][k][seed]; see sse_at.
  std::vector<double> sse, rel_sse;

  std::size_t curve_index(std::size_t region, std::size_t method, std::size_t sequence) const {
    return (region * axes.methods.size() + method) * axes.sequences.size() + sequence;
  }
  std::size_t curves() const {
    return axes.regions.size() * axes.methods.size() * axes.sequences.size();
  }
  std::size_t region_of(std::size_t curve) const {
    return curve / (axes.methods.size() * axes.sequences.size());
  }
  const std::string& method_of(std::size_t curve) const {
    return axes.methods[(curve / axes.sequences.size()) % axes.methods.size()];
  }
  const std::string& sequence_of(std::size_t curve) const {
    return axes.sequences[curve % axes.sequences.size()];
  }
  const std::vector<uint32_t>& ns() const { return axes.ns; }

  // Lookups by name; nullopt when the region, method or sequence was not part of the run.
  std::optional<std::size_t> find_curve(std::string_view region, std::string_view method,
                                        std::string_view sequence) const;
  std::optional<std::size_t> find_region(std::string_view region) const;
  std::optional<std::size_t> find_n(uint32_t n) const;
  bool has_method(std::string_view method) const;
  bool has_sequence(std::string_view sequence) const;
  // Indices of ns inside the fit range.
  std::vector<std::size_t> fit_indices() const;

  // RMS over points and seeds of (estimate - reference) at ns[k]; with replicate weights (a
  // SeedBootstrap row) when given, else every seed once. rel_rmse divides each error by its
  // reference first.
  double rmse(std::size_t curve, std::size_t k, std::span<const uint32_t> weights = {}) const;
  double rel_rmse(std::size_t curve, std::size_t k, std::span<const uint32_t> weights = {}) const;
  // Least-squares slope of log rmse vs log N over the fit range (nullopt if an RMS is 0).
  std::optional<double> slope(std::size_t curve, std::span<const uint32_t> weights = {}) const;

  double& sse_at(std::size_t curve, std::size_t k, std::size_t seed) {
    return sse[(curve * axes.ns.size() + k) * axes.seeds + seed];
  }
  double& rel_sse_at(std::size_t curve, std::size_t k, std::size_t seed) {
    return rel_sse[(curve * axes.ns.size() + k) * axes.seeds + seed];
  }
  // Sizes sse and rel_sse for the axes (zeros).
  void allocate_curves();

 private:
  double mean_square(const std::vector<double>& data, std::size_t curve, std::size_t k,
                     std::span<const uint32_t> weights) const;
};

// Checks a study's curve axes (std::invalid_argument naming the problem): every sequence in the
// registry; ns (filled with 16 .. 4096 by powers of two when empty) increasing powers of two
// >= 4, so that four-copy methods' groups stay whole; seeds >= 1; two or more N >= fit_min.
void check_curve_axes(const std::vector<std::string>& sequences, std::vector<uint32_t>& ns,
                      uint32_t seeds, uint32_t fit_min);

// One fitted curve for the outputs.
struct CurveFit {
  std::size_t curve = 0;
  std::optional<double> slope, slope_se;
};
// Every curve's slope and bootstrap standard error (threads: 0 for OpenMP's default).
std::vector<CurveFit> fit_all(const CurveTable& table, const SeedBootstrap& bootstrap,
                              int threads = 0);

}  // namespace disklab::study
