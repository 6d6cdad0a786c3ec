#include "study/curves.h"

#include <omp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "disklab/sequence/sequence.h"

namespace disklab::study {

namespace {
std::optional<std::size_t> index_of(const std::vector<std::string>& names, std::string_view name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return std::nullopt;
  return static_cast<std::size_t>(it - names.begin());
}
}  // namespace

std::optional<std::size_t> CurveTable::find_curve(std::string_view region, std::string_view method,
                                                  std::string_view sequence) const {
  const auto r = index_of(axes.regions, region), m = index_of(axes.methods, method),
             q = index_of(axes.sequences, sequence);
  if (!r || !m || !q) return std::nullopt;
  return curve_index(*r, *m, *q);
}

std::optional<std::size_t> CurveTable::find_region(std::string_view region) const {
  return index_of(axes.regions, region);
}

bool CurveTable::has_method(std::string_view method) const {
  return index_of(axes.methods, method).has_value();
}

bool CurveTable::has_sequence(std::string_view sequence) const {
  return index_of(axes.sequences, sequence).has_value();
}

std::optional<std::size_t> CurveTable::find_n(uint32_t n) const {
  for (std::size_t k = 0; k < axes.ns.size(); ++k)
    if (axes.ns[k] == n) return k;
  return std::nullopt;
}

std::vector<std::size_t> CurveTable::fit_indices() const {
  std::vector<std::size_t> ks;
  for (std::size_t k = 0; k < axes.ns.size(); ++k)
    if (axes.ns[k] >= axes.fit_min) ks.push_back(k);
  return ks;
}

void CurveTable::allocate_curves() {
  const std::size_t size = curves() * axes.ns.size() * axes.seeds;
  sse.assign(size, 0.0);
  rel_sse.assign(size, 0.0);
}

double CurveTable::mean_square(const std::vector<double>& data, std::size_t curve, std::size_t k,
                               std::span<const uint32_t> weights) const {
  const double* row = &data[(curve * axes.ns.size() + k) * axes.seeds];
  double sum = 0.0, count = 0.0;
  for (std::size_t s = 0; s < axes.seeds; ++s) {
    const double w = weights.empty() ? 1.0 : weights[s];
    sum += w * row[s];
    count += w;
  }
  return sum / (count * static_cast<double>(axes.points[region_of(curve)]));
}

double CurveTable::rmse(std::size_t curve, std::size_t k, std::span<const uint32_t> weights) const {
  return std::sqrt(mean_square(sse, curve, k, weights));
}

double CurveTable::rel_rmse(std::size_t curve, std::size_t k,
                            std::span<const uint32_t> weights) const {
  return std::sqrt(mean_square(rel_sse, curve, k, weights));
}

std::optional<double> CurveTable::slope(std::size_t curve,
                                        std::span<const uint32_t> weights) const {
  std::vector<double> x, y;
  for (std::size_t k : fit_indices()) {
    const double e = rmse(curve, k, weights);
    if (!(e > 0.0)) return std::nullopt;  // an exact estimate has no slope
    x.push_back(axes.ns[k]);
    y.push_back(e);
  }
  if (x.size() < 2) return std::nullopt;
  return fit_log_log(x, y).slope;
}

void check_curve_axes(const std::vector<std::string>& sequences, std::vector<uint32_t>& ns,
                      uint32_t seeds, uint32_t fit_min) {
  const std::vector<std::string> all = sequence::sequence_names();
  for (const std::string& name : sequences)
    if (std::find(all.begin(), all.end(), name) == all.end())
      throw std::invalid_argument("unknown sequence '" + name + "'");
  if (ns.empty())
    for (uint32_t n = 16; n <= 4096; n *= 2)
      ns.push_back(n);
  for (std::size_t k = 0; k < ns.size(); ++k) {
    if (!std::has_single_bit(ns[k]) || ns[k] < 4)
      throw std::invalid_argument("N = " + std::to_string(ns[k]) + " is not a power of two >= 4");
    if (k > 0 && ns[k] <= ns[k - 1]) throw std::invalid_argument("the sample counts must increase");
  }
  if (seeds == 0) throw std::invalid_argument("seeds must be at least 1");
  std::size_t in_fit = 0;
  for (uint32_t n : ns)
    in_fit += n >= fit_min;
  if (in_fit < 2)
    throw std::invalid_argument("fewer than two sample counts in the fit range N >= " +
                                std::to_string(fit_min));
}

std::vector<CurveFit> fit_all(const CurveTable& table, const SeedBootstrap& bootstrap,
                              int threads) {
  std::vector<CurveFit> fits(table.curves());
  const auto n = static_cast<int64_t>(fits.size());
#pragma omp parallel for schedule(dynamic, 4) \
    num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (int64_t c = 0; c < n; ++c) {
    const auto curve = static_cast<std::size_t>(c);
    fits[curve].curve = curve;
    fits[curve].slope = table.slope(curve);
    fits[curve].slope_se = bootstrap.standard_error(
        [&](std::span<const uint32_t> w) { return table.slope(curve, w); });
  }
  return fits;
}

}  // namespace disklab::study
