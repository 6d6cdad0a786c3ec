#include "study/convergence.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>

#include "disklab/sequence/sequence.h"
#include "study/estimator.h"

namespace disklab::study {

Scene memo_scene() {
  Scene s;
  s.light.center = Vec3(0.0, 0.0, 2.0);
  s.light.normal = Vec3(0.0, 0.0, -1.0);
  s.light.radius = 1.0;
  s.light.two_sided = false;
  s.light.radiance = 1.0;
  s.light.axis_x = Vec3::UnitX();
  s.light.axis_y = Vec3::UnitY();
  s.occluders.push_back({Vec3(1.5, 0.0, 1.0), 0.5});
  return s;
}

std::vector<StudyRegion> memo_regions() {
  return {{{"lit-axis", -0.6, -0.3, -0.6, -0.3, 4, 4}, true},
          {{"lit-off", -1.6, -1.3, -1.6, -1.3, 4, 4}, true},
          {{"penumbra", 1.9, 2.2, 0.5, 0.8, 4, 4}, false}};
}

void finalize(ConvergenceConfig& c) {
  if (c.strategies.empty())
    c.strategies.assign(std::begin(disk::kAllStrategies), std::end(disk::kAllStrategies));
  if (c.sequences.empty()) c.sequences = sequence::sequence_names();
  check_curve_axes(c.sequences, c.ns, c.seeds, c.fit_min);
  if (c.regions.empty()) throw std::invalid_argument("no regions");
}

std::vector<RegionReferences> compute_references(const ConvergenceConfig& config) {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  std::vector<RegionReferences> out;
  const DiskLight& light = config.scene.light;
  for (const StudyRegion& region : config.regions) {
    RegionReferences refs{region.grid.name, region.fully_lit ? "closed-form" : "quadrature", {}};
    for (const ShadingPoint& p : region.grid.points()) {
      ReferenceValue v;
      if (region.fully_lit) {
        // Receiver parallel to the disk: height along the normal, offset from the axis.
        const Vec3 rel = p.position - light.center;
        const double h = std::fabs(rel.dot(light.normal));
        const double d = (rel - rel.dot(light.normal) * light.normal).norm();
        v.value = disk_irradiance_parallel(light.radiance, light.radius, h, d);
        // A dozen roundings and two square roots: 16 eps relative bounds them.
        v.error_estimate = 16.0 * kEps * v.value;
      } else {
        v = irradiance_quadrature(config.scene, p);
      }
      refs.points.push_back({p, v});
    }
    out.push_back(std::move(refs));
  }
  return out;
}

void ConvergenceResult::allocate() {
  axes.regions.clear();
  axes.points.clear();
  for (std::size_t r = 0; r < config.regions.size(); ++r) {
    axes.regions.push_back(config.regions[r].grid.name);
    axes.points.push_back(r < references.size() ? references[r].points.size()
                                                : config.regions[r].grid.points().size());
  }
  axes.methods.clear();
  for (disk::Strategy st : config.strategies)
    axes.methods.emplace_back(disk::strategy_name(st));
  axes.sequences = config.sequences;
  axes.ns = config.ns;
  axes.fit_min = config.fit_min;
  axes.seeds = config.seeds;
  allocate_curves();
}

ConvergenceResult run_convergence(ConvergenceConfig config) {
  finalize(config);
  ConvergenceResult result;
  result.config = config;
  result.references = compute_references(config);
  result.allocate();

  const uint32_t n_max = config.ns.back();
  uint32_t capacity = 0;
  for (disk::Strategy st : config.strategies)
    capacity = std::max(capacity, square_points_needed(st, n_max));

  const std::size_t nseq = config.sequences.size(), nk = config.ns.size();
  const auto jobs = static_cast<int64_t>(nseq * config.seeds);
  std::atomic<uint64_t> done{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const int threads = config.threads > 0 ? config.threads : omp_get_max_threads();

#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int64_t job = 0; job < jobs; ++job) {
    try {
      const std::size_t q = static_cast<std::size_t>(job) / config.seeds;
      const std::size_t s = static_cast<std::size_t>(job) % config.seeds;
      const auto seq =
          sequence::make_sequence(config.sequences[q], config.first_seed + s, capacity);
      std::vector<double> est(nk);
      for (std::size_t st = 0; st < config.strategies.size(); ++st) {
        const std::vector<AreaSample> samples = disk_samples(config.strategies[st], *seq, n_max);
        for (std::size_t r = 0; r < config.regions.size(); ++r) {
          const std::size_t curve = result.curve_index(r, st, q);
          for (const PointReference& p : result.references[r].points) {
            progressive_irradiance(config.scene, p.point, samples, config.ns, est);
            const double ref = p.reference.value;
            for (std::size_t k = 0; k < nk; ++k) {
              const double e = est[k] - ref;
              result.sse_at(curve, k, s) += e * e;
              result.rel_sse_at(curve, k, s) += ref != 0.0 ? (e / ref) * (e / ref) : 0.0;
            }
          }
        }
      }
    } catch (...) {
      std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
    }
    const uint64_t now = ++done;
    if (config.progress) config.progress(now, static_cast<uint64_t>(jobs));
  }
  if (failure) std::rethrow_exception(failure);
  return result;
}

SeedBootstrap make_bootstrap(const ConvergenceConfig& config) {
  // The resampling draws depend on the run's first seed only, so a run is reproducible.
  return SeedBootstrap(config.seeds, config.bootstrap_replicates,
                       0x9e3779b97f4a7c15ULL ^ config.first_seed);
}

}  // namespace disklab::study
