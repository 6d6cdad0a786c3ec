#include "study/variance.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "disklab/ellipse/area_lean.h"
#include "disklab/sequence/random.h"
#include "disklab/sequence/scramble.h"
#include "disklab/sequence/sequence.h"
#include "study/estimator.h"

namespace disklab::study {

namespace {
constexpr int kNewtonBins = 33;  // 0 .. 31 iterations, and 32 or more
// A shadowed pixel's quadrature target, and the error estimate the reference must meet.
constexpr double kQuadratureTol = 1e-12;
constexpr double kRequiredRelError = 1e-10;

int threads_of(int threads) {
  return threads > 0 ? threads : omp_get_max_threads();
}

// Runs body(job) for job in [0, jobs) on `threads` threads; the first exception is rethrown.
template <class Body>
void parallel_jobs(int64_t jobs, int threads, const std::function<void()>& tick, Body&& body) {
  std::exception_ptr failure;
  std::mutex failure_mutex;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int64_t job = 0; job < jobs; ++job) {
    try {
      body(job);
    } catch (...) {
      std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
    }
    if (tick) tick();
  }
  if (failure) std::rethrow_exception(failure);
}
}  // namespace

Scene variance_scene() {
  Scene s;
  s.light.center = Vec3(0.0, 0.0, 0.6);
  s.light.normal = Vec3(1.0, 0.0, 0.0);
  s.light.radius = 0.5;
  s.light.two_sided = true;
  s.light.radiance = 1.0;
  // In-plane axes with axis_x x axis_y = normal.
  s.light.axis_x = Vec3::UnitY();
  s.light.axis_y = Vec3::UnitZ();
  s.occluders.push_back({Vec3(-0.8, 0.5, 0.3), 0.25});
  return s;
}

std::vector<StudyRegion> variance_regions() {
  return {{{"near", 0.05, 0.2, -0.15, 0.15, 4, 4}, true},
          {{"mid", 0.6, 0.9, -0.15, 0.15, 4, 4}, true},
          {{"far", 1.7, 2.0, 1.7, 2.0, 4, 4}, true}};
}

ShadingPoint ImageGrid::pixel(int row, int col) const {
  const double step = (hi - lo) / size;
  return {Vec3(lo + (col + 0.5) * step, hi - (row + 0.5) * step, 0.0), Vec3::UnitZ()};
}

bool may_be_shadowed(const Scene& scene, const ShadingPoint& sp) {
  const DiskLight& l = scene.light;
  const Vec3 a = l.center - sp.position;
  const double da = a.norm();
  if (!(da > l.radius)) return !scene.occluders.empty();
  const double alpha = std::asin(l.radius / da);
  const double side = (sp.position - l.center).dot(l.normal);
  for (const Sphere& s : scene.occluders) {
    // Wholly beyond the light's plane, seen from sp: never between sp and the disk.
    const double beyond = (side > 0.0 ? -1.0 : 1.0) * (s.center - l.center).dot(l.normal);
    if (beyond > s.radius) continue;
    const Vec3 v = s.center - sp.position;
    const double dv = v.norm();
    if (!(dv > s.radius)) return true;
    const double angle = std::atan2(a.cross(v).norm(), a.dot(v));
    // A margin far above the rounding of the angles keeps the test conservative.
    if (angle <= alpha + std::asin(s.radius / dv) + 1e-9) return true;
  }
  return false;
}

ReferenceValue irradiance_reference(const Scene& scene, const ShadingPoint& sp, bool* quadrature) {
  const bool shadowed = may_be_shadowed(scene, sp);
  if (quadrature) *quadrature = shadowed;
  const ReferenceValue v =
      shadowed ? irradiance_quadrature(scene, sp, kQuadratureTol) : irradiance_rim(scene.light, sp);
  if (!(v.error_estimate <= kRequiredRelError * std::fabs(v.value)) && v.value != 0.0)
    throw std::runtime_error("irradiance reference: error estimate above 1e-10 relative");
  return v;
}

ImageReference compute_image_reference(const Scene& scene, const ImageGrid& grid, int threads,
                                       const std::function<void()>& row_done) {
  ImageReference ref;
  ref.grid = grid;
  const std::size_t n = static_cast<std::size_t>(grid.size) * grid.size;
  ref.value.assign(n, 0.0);
  ref.error.assign(n, 0.0);
  std::vector<uint8_t> quad(n, 0);
  parallel_jobs(grid.size, threads_of(threads), row_done, [&](int64_t row) {
    for (int col = 0; col < grid.size; ++col) {
      const std::size_t i = static_cast<std::size_t>(row) * grid.size + col;
      bool q = false;
      const ReferenceValue v =
          irradiance_reference(scene, grid.pixel(static_cast<int>(row), col), &q);
      ref.value[i] = v.value;
      ref.error[i] = v.error_estimate;
      quad[i] = q ? 1 : 0;
    }
  });
  for (uint8_t q : quad)
    ref.quadrature_pixels += q;
  ref.shadowed = std::move(quad);
  return ref;
}

void finalize(VarianceConfig& c) {
  if (c.maps.empty())
    for (const std::string& name : ellipse::map_names())
      c.maps.push_back(*ellipse::parse_map(name));
  if (c.sequences.empty()) c.sequences = {"random", "sobol-owen", "pmj02"};
  check_curve_axes(c.sequences, c.ns, c.seeds, c.fit_min);
  if (c.image_randomizations == 0)
    throw std::invalid_argument("image randomizations must be at least 1");
  if (c.spp < 4 || c.spp % 4 != 0)
    throw std::invalid_argument("samples per pixel must be a positive multiple of 4");
  if (c.image.size < 1) throw std::invalid_argument("the image needs at least one pixel");
  if (c.timing_repetitions < 1) throw std::invalid_argument("timing repetitions must be >= 1");
  if (c.regions.empty()) throw std::invalid_argument("no regions");
}

SeedBootstrap make_curve_bootstrap(const VarianceConfig& c) {
  return SeedBootstrap(c.seeds, c.bootstrap_replicates, 0x9e3779b97f4a7c15ULL ^ c.first_seed);
}
SeedBootstrap make_image_bootstrap(const VarianceConfig& c) {
  return SeedBootstrap(c.image_randomizations, c.bootstrap_replicates,
                       0xc2b2ae3d27d4eb4fULL ^ c.first_seed);
}

namespace {

void merge_newton(std::vector<NewtonStats>& into, const std::vector<std::vector<uint64_t>>& add,
                  std::mutex& mutex) {
  std::lock_guard lock(mutex);
  for (std::size_t m = 0; m < add.size(); ++m)
    for (std::size_t b = 0; b < add[m].size(); ++b)
      into[m].histogram[b] += add[m][b];
}

// The regions' curves: jobs are (sequence, seed) pairs.
void run_curves(const VarianceConfig& c, VarianceResult& r, const std::function<void()>& tick) {
  const uint32_t n_max = c.ns.back();
  const std::size_t nk = c.ns.size();
  parallel_jobs(static_cast<int64_t>(c.sequences.size() * c.seeds), threads_of(c.threads), tick,
                [&](int64_t job) {
                  const std::size_t q = static_cast<std::size_t>(job) / c.seeds;
                  const std::size_t s = static_cast<std::size_t>(job) % c.seeds;
                  const auto seq = sequence::make_sequence(c.sequences[q], c.first_seed + s, n_max);
                  std::vector<Point2> u(n_max);
                  for (uint32_t i = 0; i < n_max; ++i)
                    u[i] = seq->at(i);
                  std::vector<double> est(nk);
                  for (std::size_t reg = 0; reg < c.regions.size(); ++reg)
                    for (const PointReference& p : r.references[reg].points)
                      for (std::size_t m = 0; m < c.maps.size(); ++m) {
                        const ellipse::AnyMap map = light_map(c.maps[m], c.scene, p.point);
                        progressive_irradiance(c.scene, p.point, map, u, c.ns, est);
                        const std::size_t curve = r.curves.curve_index(reg, m, q);
                        const double ref = p.reference.value;
                        for (std::size_t k = 0; k < nk; ++k) {
                          const double e = est[k] - ref;
                          r.curves.sse_at(curve, k, s) += e * e;
                          r.curves.rel_sse_at(curve, k, s) += (e / ref) * (e / ref);
                        }
                      }
                });
}

// The images: jobs are (randomization, row) pairs; each pixel has its own sequence instances.
void run_images(const VarianceConfig& c, VarianceResult& r, const std::function<void()>& tick) {
  const int size = c.image.size;
  const std::size_t nm = c.maps.size(), nq = c.sequences.size(), curves = nm * nq;
  const bool has_shadow = r.image.axes.regions.size() > 1;
  const auto jobs = static_cast<int64_t>(c.image_randomizations) * size;
  // Per-job sums, added in job order afterwards so the totals do not depend on the threads.
  // Slots [job][region][map][sequence], region 1 the shadowed pixels.
  const std::size_t per_job = 2 * curves;
  std::vector<double> job_sse(static_cast<std::size_t>(jobs) * per_job, 0.0);
  std::vector<double> job_rel(job_sse.size(), 0.0);
  std::mutex newton_mutex;
  const std::vector<uint32_t> ns{c.spp};
  parallel_jobs(jobs, threads_of(c.threads), tick, [&](int64_t job) {
    const auto rand = static_cast<uint32_t>(job / size);
    const auto row = static_cast<int>(job % size);
    std::vector<std::vector<uint64_t>> newton(nm, std::vector<uint64_t>(kNewtonBins, 0));
    std::vector<Point2> u(c.spp);
    double est = 0.0;
    for (int col = 0; col < size; ++col) {
      const ShadingPoint sp = c.image.pixel(row, col);
      const std::size_t pixel = static_cast<std::size_t>(row) * size + col;
      const double ref = r.image_reference.value[pixel];
      for (std::size_t q = 0; q < nq; ++q) {
        const uint64_t seed = sequence::derive_seed(
            c.first_seed, (uint64_t{rand} << 32u) ^ (uint64_t{pixel} << 4u) ^ q);
        const auto seq = sequence::make_sequence(c.sequences[q], seed, c.spp);
        for (uint32_t i = 0; i < c.spp; ++i)
          u[i] = seq->at(i);
        for (std::size_t m = 0; m < nm; ++m) {
          const ellipse::AnyMap map = light_map(c.maps[m], c.scene, sp);
          progressive_irradiance(c.scene, sp, map, u, ns, {&est, 1}, newton[m]);
          const double e = est - ref, rel = ref != 0.0 ? (e / ref) * (e / ref) : 0.0;
          const std::size_t slot = static_cast<std::size_t>(job) * per_job + m * nq + q;
          job_sse[slot] += e * e;
          job_rel[slot] += rel;
          if (r.image_reference.shadowed[pixel]) {
            job_sse[slot + curves] += e * e;
            job_rel[slot + curves] += rel;
          }
          if (rand == 0) r.images[m * nq + q][pixel] = est;
        }
      }
    }
    merge_newton(r.newton, newton, newton_mutex);
  });
  for (int64_t job = 0; job < jobs; ++job) {
    const auto rand = static_cast<std::size_t>(job / size);
    for (std::size_t reg = 0; reg < (has_shadow ? 2u : 1u); ++reg)
      for (std::size_t m = 0; m < nm; ++m)
        for (std::size_t q = 0; q < nq; ++q) {
          const std::size_t slot =
              static_cast<std::size_t>(job) * per_job + reg * curves + m * nq + q;
          const std::size_t curve = r.image.curve_index(reg, m, q);
          r.image.sse_at(curve, 0, rand) += job_sse[slot];
          r.image.rel_sse_at(curve, 0, rand) += job_rel[slot];
        }
  }
  for (std::size_t m = 0; m < nm; ++m) {
    NewtonStats& s = r.newton[m];
    double sum = 0.0;
    for (int b = 0; b < kNewtonBins; ++b) {
      s.solves += s.histogram[b];
      sum += static_cast<double>(b) * static_cast<double>(s.histogram[b]);
      if (s.histogram[b] > 0) s.max = b;
    }
    s.mean = s.solves > 0 ? sum / static_cast<double>(s.solves) : 0.0;
    s.per_sample = s.mean / ellipse::map_copies(c.maps[m]);
  }
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size();
  return m % 2 ? v[m / 2] : 0.5 * (v[m / 2 - 1] + v[m / 2]);
}

// Everything a renderer reads from a light sample, the maps and the baseline alike (the rule
// bench_maps follows): the direction, the point on the light, the pdf and the validity.
template <class S>
inline double consume(const S& s) {
  return s.direction.x() + s.direction.y() + s.direction.z() + s.point.x() + s.point.y() +
         s.point.z() + s.pdf + (s.valid ? 1.0 : 0.0);
}

// n samples of one concrete map from u[0..): the same draws as AnyMap::sample_copies (radial4:
// four copies per u, gamito and tabulated one candidate), without its per-sample dispatch.
template <class M>
double draw_samples(const M& m, const Point2* u, uint32_t n) {
  double sink = 0.0;
  if constexpr (std::is_same_v<M, ellipse::Radial4Map>) {
    for (uint32_t j = 0; j < n; j += 4)
      for (const ellipse::EllipseSample& x : m.sample4(u[j / 4]))
        sink += consume(x);
  } else if constexpr (std::is_same_v<M, ellipse::GamitoSampler>) {
    for (uint32_t j = 0; j < n; ++j)
      sink += consume(m.propose(u[j]));
  } else {
    for (uint32_t j = 0; j < n; ++j)
      sink += consume(m.sample(u[j]));
  }
  return sink;
}

// Set-up and sampling cost over every pixel of the image on the calling thread, by the rules of
// bench_maps: every sample consumed whole, the methods alternated (rotated within each
// repetition, so drifts of the clock rate hit all alike), the baseline the area sample a
// renderer writes (ellipse::LeanAreaSampler, its light prepared once as a renderer stores it),
// ratios taken within a repetition and their median reported.
void run_timing(const VarianceConfig& c, VarianceResult& r, const std::function<void()>& tick) {
  using Clock = std::chrono::steady_clock;
  const int size = c.image.size;
  const std::size_t pixels = static_cast<std::size_t>(size) * size, nm = c.maps.size();
  std::vector<ShadingPoint> points(pixels);
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col)
      points[static_cast<std::size_t>(row) * size + col] = c.image.pixel(row, col);
  // radial4's copies: spp / 4 points per pixel serve its spp samples.
  std::vector<Point2> u(pixels * c.spp);
  sequence::Pcg32 rng(sequence::derive_seed(c.first_seed, 0x7157));
  for (Point2& p : u)
    p = {rng.next_double(), rng.next_double()};
  const DiskLight& l = c.scene.light;
  const ellipse::LeanDiskLight lean =
      ellipse::LeanDiskLight::make(ellipse::Disk{l.center, l.normal, l.radius, l.two_sided});
  const std::size_t baseline = nm;  // the methods: the maps, then the baseline
  std::vector<std::vector<double>> setup(nm + 1), total(nm + 1), ratio(nm + 1);
  double sink = 0.0;
  for (int rep = 0; rep < c.timing_repetitions; ++rep) {
    std::vector<double> rep_total(nm + 1);
    for (std::size_t i = 0; i <= nm; ++i) {
      const std::size_t m = (i + static_cast<std::size_t>(rep)) % (nm + 1);
      const auto t0 = Clock::now();
      if (m == baseline) {
        for (const ShadingPoint& sp : points)
          sink += ellipse::LeanAreaSampler::make(lean, sp.position).valid() ? 1.0 : 0.0;
      } else {
        for (const ShadingPoint& sp : points)
          sink += light_map(c.maps[m], c.scene, sp).omega();
      }
      const auto t1 = Clock::now();
      for (std::size_t p = 0; p < pixels; ++p) {
        const Point2* up = &u[p * c.spp];
        if (m == baseline) {
          sink += draw_samples(ellipse::LeanAreaSampler::make(lean, points[p].position), up, c.spp);
        } else {
          const ellipse::AnyMap map = light_map(c.maps[m], c.scene, points[p]);
          sink +=
              std::visit([&](const auto& x) { return draw_samples(x, up, c.spp); }, map.variant());
        }
      }
      const auto t2 = Clock::now();
      const double ns_setup = std::chrono::duration<double, std::nano>(t1 - t0).count();
      const double ns_total = std::chrono::duration<double, std::nano>(t2 - t1).count();
      setup[m].push_back(ns_setup / static_cast<double>(pixels));
      total[m].push_back(ns_total / static_cast<double>(pixels));
      rep_total[m] = ns_total;
    }
    for (std::size_t m = 0; m <= nm; ++m)
      ratio[m].push_back(rep_total[m] / rep_total[baseline]);
    if (tick) tick();
  }
  if (sink == 12345.678) std::fputs("", stderr);  // keeps the timed work observable
  auto cost_of = [&](std::size_t m) {
    MapCost cost;
    cost.setup_ns = median(setup[m]);
    const double per_point = median(total[m]);
    cost.ns_per_sample = per_point / c.spp;
    cost.sample_ns = std::max(0.0, (per_point - cost.setup_ns) / c.spp);
    cost.ratio_to_baseline = median(ratio[m]);
    return cost;
  };
  r.cost.clear();
  for (std::size_t m = 0; m < nm; ++m)
    r.cost.push_back(cost_of(m));
  r.baseline_cost = cost_of(baseline);
}

}  // namespace

uint64_t work_units(const VarianceConfig& c) {
  return static_cast<uint64_t>(c.image.size) + static_cast<uint64_t>(c.sequences.size()) * c.seeds +
         static_cast<uint64_t>(c.image_randomizations) * c.image.size +
         static_cast<uint64_t>(c.timing_repetitions);
}

VarianceResult run_variance(VarianceConfig config) {
  finalize(config);
  VarianceResult r;
  r.config = config;
  const VarianceConfig& c = r.config;
  for (ellipse::MapKind k : c.maps)
    r.map_names.emplace_back(ellipse::map_name(k));

  const uint64_t total = work_units(c);
  std::atomic<uint64_t> done{0};
  const std::function<void()> tick = [&] {
    const uint64_t now = ++done;
    if (c.progress) c.progress(now, total);
  };

  for (const StudyRegion& region : c.regions) {
    RegionReferences refs{region.grid.name, "rim integral", {}};
    for (const ShadingPoint& p : region.grid.points()) {
      if (may_be_shadowed(c.scene, p))
        throw std::invalid_argument("region " + region.grid.name + " is not wholly unoccluded");
      refs.points.push_back({p, irradiance_rim(c.scene.light, p)});
    }
    r.references.push_back(std::move(refs));
  }
  r.image_reference = compute_image_reference(c.scene, c.image, c.threads, tick);

  CurveAxes& a = r.curves.axes;
  for (std::size_t i = 0; i < c.regions.size(); ++i) {
    a.regions.push_back(c.regions[i].grid.name);
    a.points.push_back(r.references[i].points.size());
  }
  a.methods = r.map_names;
  a.sequences = c.sequences;
  a.ns = c.ns;
  a.fit_min = c.fit_min;
  a.seeds = c.seeds;
  r.curves.allocate_curves();

  CurveAxes& ia = r.image.axes;
  ia.regions = {"image"};
  ia.points = {static_cast<std::size_t>(c.image.size) * c.image.size};
  if (r.image_reference.quadrature_pixels > 0) {
    ia.regions.push_back("shadowed");
    ia.points.push_back(r.image_reference.quadrature_pixels);
  }
  ia.methods = r.map_names;
  ia.sequences = c.sequences;
  ia.ns = {c.spp};
  ia.fit_min = c.spp;
  ia.seeds = c.image_randomizations;
  r.image.allocate_curves();
  r.images.assign(c.maps.size() * c.sequences.size(), std::vector<double>(ia.points[0], 0.0));
  r.newton.assign(c.maps.size(),
                  NewtonStats{std::vector<uint64_t>(kNewtonBins, 0), 0, 0.0, 0.0, 0});

  run_curves(c, r, tick);
  run_images(c, r, tick);
  run_timing(c, r, tick);
  return r;
}

}  // namespace disklab::study
