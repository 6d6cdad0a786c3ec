// Per-sample cost of the spherical-ellipse maps (issue 5, "the Newton-Raphson vs tabulated
// question"): area, gamito, parallel, radial, ld-radial, radial4, tabulated, radial-fast and
// projected (receiver normal +z, the configurations' disks all above its horizon), over
// a fixed set of configurations (near, mid, far, grazing), all in one run.
//
// Ratios, not absolute times. Every timed benchmark interleaves, batch by batch, the map under
// test with area sampling (the baseline of Guillén et al. 2017) and with a concentric and a polar
// disk sample, on the SAME square points; the times are accumulated separately and their
// quotients reported as counters (`ratio_to_area`, `ratio_to_concentric`, `ratio_to_polar`). Load
// from other processes hits all of them alike and cancels in the quotients.
//
// Inputs: a fixed array of 4096 Owen-scrambled Sobol' points (seed 1), so branch patterns
// (quadrants, Newton paths, rejections) are those of a renderer, not of a single repeated u.
//
// What an item is:
//  - sample/<map>/<config>: one direction with its pdf. radial4 returns four per root solve and
//    counts four; tabulated counts every candidate (a rejected one is a zero-weight sample of its
//    unbiased estimator; `accept` reports the acceptance rate); gamito counts accepted samples
//    (it loops until one is accepted; `tries` reports candidates per sample).
//  - setup/<map>/<config>: one `make` per shading point (counter `ratio_to_area`: against
//    AreaSampler::make).
//  - amortized/<map>/<config>/<k>: one `make` followed by k samples, per sample, against the same
//    for area sampling (k = 1, 16, 256).
// Newton maps also report `evals`: mean evaluations of the cumulative solid angle per sample.
//
// The summary after the table gives the median ratios per map and configuration and checks the
// issue's targets: exact radial <= 6x area, radial-fast <= 2x, tabulated <= 1.3x.
//
// Run: build/<preset>/bin/bench_maps --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true (add --benchmark_filter=sample/ for the per-sample part
// only).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "bench_common.h"
#include "disklab/disk/concentric.h"
#include "disklab/disk/polar.h"
#include "disklab/ellipse/area.h"
#include "disklab/ellipse/gamito.h"
#include "disklab/ellipse/ld_radial.h"
#include "disklab/ellipse/parallel.h"
#include "disklab/ellipse/projected.h"
#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/radial4.h"
#include "disklab/ellipse/radial_fast.h"
#include "disklab/ellipse/tabulated.h"
#include "disklab/sequence/random.h"
#include "disklab/sequence/sobol.h"

namespace {
using disklab::Point2;
using disklab::Vec3;
namespace ell = disklab::ellipse;
namespace disk = disklab::disk;
using Clock = std::chrono::steady_clock;

// Square points per timed batch: long enough (>= ~5 us for the cheapest map) that the two clock
// reads per batch are noise, short enough that the three timed loops alternate often.
constexpr int kBatch = 256;
constexpr int kPoints = 4096;  // the fixed point set; batches walk through it

// The targets, as ratios to area sampling in the same run.
constexpr double kTargetRadial = 6.0;
constexpr double kTargetRadialFast = 2.0;
constexpr double kTargetTabulated = 1.3;

struct Config {
  const char* name;
  Vec3 center, normal;
  double radius;
  Vec3 o;
};

// Unit disk facing the shading point at the origin (normal -z or tilted: the lit side is +normal).
const std::array<Config, 4>& configs() {
  static const Vec3 tilted = Vec3(0.3, -0.2, -1.0).normalized();
  static const std::array<Config, 4> c = {{
      // Close and off axis: alpha ~ 60 degrees, the map far from its planar limit.
      {"near", Vec3(0.3, 0.2, 0.5), Vec3(0, 0, -1), 1.0, Vec3::Zero()},
      // A few radii away, tilted: the typical area light in a room.
      {"mid", Vec3(1.0, 0.5, 3.0), tilted, 1.0, Vec3::Zero()},
      // A thousand radii away (alpha ~ 1e-3): the common case for small or distant lights.
      {"far", Vec3(300.0, 200.0, 1000.0), tilted, 1.0, Vec3::Zero()},
      // Seen almost edge-on (beta / alpha ~ 1e-2): the eccentric limit.
      {"grazing", Vec3(3.0, 0.0, 0.05), Vec3(0, 0, -1), 1.0, Vec3::Zero()},
  }};
  return c;
}

const std::vector<Point2>& points() {
  static const std::vector<Point2> pts = [] {
    const disklab::sequence::SobolOwen seq(1);
    std::vector<Point2> p(kPoints);
    for (int i = 0; i < kPoints; ++i)
      p[i] = seq.at(static_cast<uint32_t>(i));
    return p;
  }();
  return pts;
}

// ---- one adapter per map: how to build it and how to draw a batch of samples ----
// draw(m, u, n, sink) maps the n square points u[0..n) and returns the number of samples made.

template <class M>
struct Plain {  // maps with sample(Point2) -> EllipseSample
  static M make(const Config& c) {
    return M::make(ell::Disk{c.center, c.normal, c.radius, false}, c.o);
  }
  static int draw(const M& m, const Point2* u, int n, double& sink) {
    for (int i = 0; i < n; ++i) {
      const ell::EllipseSample s = m.sample(u[i]);
      sink += s.direction.x() + s.pdf;
    }
    return n;
  }
};

struct ProjectedAdapter : Plain<ell::ProjectedMap> {
  static ell::ProjectedMap make(const Config& c) {
    return ell::ProjectedMap::make(ell::Disk{c.center, c.normal, c.radius, false}, c.o,
                                   Vec3::UnitZ());
  }
};

struct Radial4Adapter {
  static ell::Radial4Map make(const Config& c) {
    return ell::Radial4Map::make(ell::Disk{c.center, c.normal, c.radius, false}, c.o);
  }
  // n / 4 root solves, four directions each: n samples, the same count as the other maps.
  static int draw(const ell::Radial4Map& m, const Point2* u, int n, double& sink) {
    for (int i = 0; i < n / 4; ++i) {
      const auto s = m.sample4(u[i]);
      for (const auto& x : s)
        sink += x.direction.x() + x.pdf;
    }
    return (n / 4) * 4;
  }
};

struct GamitoAdapter {
  static ell::GamitoSampler make(const Config& c) {
    return ell::GamitoSampler::make(ell::Disk{c.center, c.normal, c.radius, false}, c.o);
  }
  static int draw(const ell::GamitoSampler& m, const Point2* u, int n, double& sink) {
    static thread_local disklab::sequence::Pcg32 rng(7);
    for (int i = 0; i < n; ++i) {
      const ell::EllipseSample s = m.sample(u[i], rng);
      sink += s.direction.x() + s.pdf;
    }
    return n;
  }
};

using AreaA = Plain<ell::AreaSampler>;

template <Point2 (*F)(Point2)>
int draw_disk(const Point2* u, int n, double& sink) {
  for (int i = 0; i < n; ++i) {
    const Point2 p = F(u[i]);
    sink += p.x + p.y;
  }
  return n;
}

// Mean Newton evaluations per sample over the point set (untimed; maps without a root solve: 0).
template <class M>
double mean_evaluations(const M& m) {
  if constexpr (requires(Point2 u, int* it) { m.sample(u, it); } &&
                !std::is_same_v<M, ell::GamitoSampler>) {
    long total = 0;
    for (const Point2& u : points()) {
      int it = 0;
      m.sample(u, &it);
      total += it;
    }
    return double(total) / kPoints;
  } else if constexpr (std::is_same_v<M, ell::Radial4Map>) {
    long total = 0;
    for (const Point2& u : points()) {
      int it = 0;
      m.sample_quadrant(u, &it);
      total += it;
    }
    return double(total) / kPoints / 4.0;  // per direction
  } else {
    return 0.0;
  }
}

// Median of per-batch times: a batch preempted by another process is an outlier on one side and
// moves the median by at most one rank, while it would bias a sum.
double median(std::vector<double>& v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

inline double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// ---- per-sample cost, interleaved with the baselines ----
template <class A>
void BM_Sample(benchmark::State& state, const Config& c) {
  const auto m = A::make(c);
  const auto area = AreaA::make(c);
  if (!m.valid() || !area.valid()) {
    state.SkipWithError("invalid configuration");
    return;
  }
  const std::vector<Point2>& u = points();
  double sink = 0.0;
  std::vector<double> t_map, t_area, t_conc, t_polar;  // per batch
  long n_map = 0;
  int per_batch = kBatch;
  int offset = 0;
  for (auto _ : state) {
    const Point2* batch = u.data() + offset;
    offset = (offset + kBatch) % kPoints;
    const auto t0 = Clock::now();
    per_batch = A::draw(m, batch, kBatch, sink);
    const auto t1 = Clock::now();
    AreaA::draw(area, batch, kBatch, sink);
    const auto t2 = Clock::now();
    draw_disk<disk::sample_concentric>(batch, kBatch, sink);
    const auto t3 = Clock::now();
    draw_disk<disk::sample_polar>(batch, kBatch, sink);
    const auto t4 = Clock::now();
    n_map += per_batch;
    t_map.push_back(seconds(t0, t1));
    t_area.push_back(seconds(t1, t2));
    t_conc.push_back(seconds(t2, t3));
    t_polar.push_back(seconds(t3, t4));
    state.SetIterationTime(seconds(t0, t1));
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(n_map);
  const double per_map = median(t_map) / per_batch;
  const double per_area = median(t_area) / kBatch;
  const double per_conc = median(t_conc) / kBatch;
  const double per_polar = median(t_polar) / kBatch;
  state.counters["ns"] = per_map * 1e9;
  state.counters["area_ns"] = per_area * 1e9;
  state.counters["ratio_to_area"] = per_map / per_area;
  state.counters["ratio_to_concentric"] = per_map / per_conc;
  state.counters["ratio_to_polar"] = per_map / per_polar;
  const double evals = mean_evaluations(m);
  if (evals > 0.0) state.counters["evals"] = evals;
  if constexpr (std::is_same_v<A, Plain<ell::TabulatedMap>>) {
    long accepted = 0;
    for (const Point2& p : u)
      accepted += m.sample(p).valid;
    state.counters["accept"] = double(accepted) / kPoints;
  }
  if constexpr (std::is_same_v<A, GamitoAdapter>) {
    disklab::sequence::Pcg32 rng(7);
    long tries = 0;
    for (const Point2& p : u) {
      int t = 0;
      m.sample(p, rng, &t);
      tries += t;
    }
    state.counters["tries"] = double(tries) / kPoints;
  }
}

// ---- set-up cost per shading point, interleaved with AreaSampler::make ----
// The shading point is nudged per call (a fixed input could let the compiler or the branch
// predictor learn more than a renderer's stream of points would allow).
template <class A>
void BM_Setup(benchmark::State& state, const Config& c) {
  constexpr int kMakes = 32;
  double sink = 0.0;
  std::vector<double> t_map, t_area;
  long count = 0;
  const std::vector<Point2>& u = points();
  int offset = 0;
  for (auto _ : state) {
    const Point2* p = u.data() + offset;
    offset = (offset + kMakes) % kPoints;
    const auto t0 = Clock::now();
    for (int i = 0; i < kMakes; ++i) {
      Config ci = c;
      ci.o = c.o + 1e-3 * Vec3(p[i].x, p[i].y, 0.0);
      const auto m = A::make(ci);
      benchmark::DoNotOptimize(m);
    }
    const auto t1 = Clock::now();
    for (int i = 0; i < kMakes; ++i) {
      Config ci = c;
      ci.o = c.o + 1e-3 * Vec3(p[i].x, p[i].y, 0.0);
      const auto m = AreaA::make(ci);
      benchmark::DoNotOptimize(m);
    }
    const auto t2 = Clock::now();
    count += kMakes;
    t_map.push_back(seconds(t0, t1));
    t_area.push_back(seconds(t1, t2));
    state.SetIterationTime(seconds(t0, t1));
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(count);
  const double m_map = median(t_map), m_area = median(t_area);
  state.counters["ns"] = m_map / kMakes * 1e9;
  state.counters["area_ns"] = m_area / kMakes * 1e9;
  state.counters["ratio_to_area"] = m_map / m_area;
}

// ---- one make + k samples, per sample, against the same for area sampling ----
template <class A>
void BM_Amortized(benchmark::State& state, const Config& c, int k) {
  const int reps = std::max(1, 256 / k);  // shading points per timed batch
  double sink = 0.0;
  std::vector<double> t_map, t_area;
  long samples = 0;
  int per_batch = reps * k;
  const std::vector<Point2>& u = points();
  int offset = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    int off = offset;
    per_batch = 0;
    for (int r = 0; r < reps; ++r) {
      Config ci = c;
      ci.o = c.o + 1e-3 * Vec3(u[off].x, u[off].y, 0.0);
      const auto m = A::make(ci);
      per_batch += A::draw(m, u.data() + off, k, sink);
      off = (off + k) % kPoints;
    }
    const auto t1 = Clock::now();
    off = offset;
    for (int r = 0; r < reps; ++r) {
      Config ci = c;
      ci.o = c.o + 1e-3 * Vec3(u[off].x, u[off].y, 0.0);
      const auto m = AreaA::make(ci);
      AreaA::draw(m, u.data() + off, k, sink);
      off = (off + k) % kPoints;
    }
    const auto t2 = Clock::now();
    offset = off;
    samples += per_batch;
    t_map.push_back(seconds(t0, t1));
    t_area.push_back(seconds(t1, t2));
    state.SetIterationTime(seconds(t0, t1));
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(samples);
  // radial4 draws k/4 solves of four (it is not registered for k < 4): count what was drawn.
  const double per_map = median(t_map) / std::max(1, per_batch);
  const double per_area = median(t_area) / (reps * k);
  state.counters["ns"] = per_map * 1e9;
  state.counters["ratio_to_area"] = per_map / per_area;
}

template <class A>
void register_map(const std::string& name) {
  for (const Config& c : configs()) {
    benchmark::RegisterBenchmark(("sample/" + name + "/" + c.name).c_str(),
                                 [&c](benchmark::State& s) { BM_Sample<A>(s, c); })
        ->UseManualTime();
  }
  for (const Config& c : configs()) {
    benchmark::RegisterBenchmark(("setup/" + name + "/" + c.name).c_str(),
                                 [&c](benchmark::State& s) { BM_Setup<A>(s, c); })
        ->UseManualTime();
  }
  for (const Config& c : configs()) {
    for (int k : {1, 16, 256}) {
      if (std::is_same_v<A, Radial4Adapter> && k < 4) continue;  // one solve makes four
      benchmark::RegisterBenchmark(
          ("amortized/" + name + "/" + c.name + "/" + std::to_string(k)).c_str(),
          [&c, k](benchmark::State& s) { BM_Amortized<A>(s, c, k); })
          ->UseManualTime();
    }
  }
}

// Worst ratio to area over the configurations of sample/<map>/*, against its target.
void check_target(const disklab::bench::Results& values, const std::string& map, double target) {
  double worst = -1.0;
  std::string where;
  for (const auto& [name, v] : values) {
    if (name.rfind("sample/" + map + "/", 0) != 0) continue;
    const double ratio = disklab::bench::counter(v, "ratio_to_area");
    if (ratio > worst) {
      worst = ratio;
      where = name;
    }
  }
  if (worst < 0) {
    std::printf("  %-12s not run\n", map.c_str());
    return;
  }
  std::printf("  %-12s worst %.2fx (%s), target <= %.1fx: %s\n", map.c_str(), worst, where.c_str(),
              target, worst <= target ? "met" : "MISSED");
}

// After the console table: the median (or only) ratios per map and configuration, and the
// issue's targets.
void print_summary(const disklab::bench::Results& values) {
  std::printf(
      "\nMedian ratios (same run). sample: per direction; setup: per make;\n"
      "amortized/k: (make + k samples) / k, both against area sampling.\n");
  std::printf("%-34s %9s %9s %9s %9s %7s\n", "benchmark", "ns", "x area", "x concen", "x polar",
              "evals");
  for (const auto& [name, v] : values) {
    const auto get = [&v](const char* k) { return disklab::bench::counter(v, k); };
    std::printf("%-34s %9.1f %9.2f", name.c_str(), get("ns"), get("ratio_to_area"));
    if (get("ratio_to_concentric") >= 0)
      std::printf(" %9.1f %9.1f", get("ratio_to_concentric"), get("ratio_to_polar"));
    else
      std::printf(" %9s %9s", "", "");
    if (get("evals") >= 0) std::printf(" %7.2f", get("evals"));
    std::printf("\n");
  }
  std::printf("\nTargets (worst configuration of sample/<map>/*, ratio to area):\n");
  check_target(values, "radial", kTargetRadial);
  check_target(values, "radial-fast", kTargetRadialFast);
  check_target(values, "tabulated", kTargetTabulated);
  // projected against the exact radial map (both as ratios to area in this run).
  for (const char* kind : {"sample", "amortized"}) {
    double worst = -1.0;
    std::string where;
    for (const auto& [name, v] : values) {
      const std::string prefix = std::string(kind) + "/projected/";
      if (name.rfind(prefix, 0) != 0) continue;
      const std::string radial = std::string(kind) + "/radial/" + name.substr(prefix.size());
      const auto it = values.find(radial);
      if (it == values.end()) continue;
      const double ratio = disklab::bench::counter(v, "ratio_to_area") /
                           disklab::bench::counter(it->second, "ratio_to_area");
      if (ratio > worst) {
        worst = ratio;
        where = name;
      }
    }
    if (worst >= 0)
      std::printf("  projected / radial (%s): worst %.2fx (%s), target <= 3x: %s\n", kind, worst,
                  where.c_str(), worst <= 3.0 ? "met" : "MISSED");
  }
  std::printf(
      "Anchor (issue 5): the authors' Newton sample costs ~40-220x a polar disk sample;\n"
      "compare the 'x polar' column of sample/radial, sample/parallel.\n");
}

}  // namespace

int main(int argc, char** argv) {
  // Built before any timing: the shared table behind tabulated and radial-fast, and the points.
  (void)ell::RadialTable::shared();
  (void)points();
  register_map<AreaA>("area");
  register_map<GamitoAdapter>("gamito");
  register_map<Plain<ell::ParallelMap>>("parallel");
  register_map<Plain<ell::RadialMap>>("radial");
  register_map<Plain<ell::LdRadialMap>>("ld-radial");
  register_map<Radial4Adapter>("radial4");
  register_map<Plain<ell::TabulatedMap>>("tabulated");
  register_map<Plain<ell::RadialFastMap>>("radial-fast");
  register_map<ProjectedAdapter>("projected");
  return disklab::bench::run_benchmarks(argc, argv, print_summary);
}
