// Cost of the spherical-ellipse maps per shading point (issues 5 and 16): area, gamito, parallel,
// radial, ld-radial, radial4, tabulated, radial-fast and projected (receiver normal +z, the
// configurations' disks all above its horizon), and the published radial method re-implemented
// from the paper (published.h: Boost ellint_3 with its default and its double policy, and the
// tabulated variant), over a fixed set of configurations (near, mid, far, grazing, very-far),
// all in one run.
//
// Ratios, not absolute times. Every timed benchmark interleaves, batch by batch, the map under
// test with the LEAN AREA BASELINE (area_lean.h: area sampling as a renderer writes it, a
// two-region concentric point in world space and d^2 / (A cos)), and with a concentric and a
// polar disk sample, on the SAME square points, the map and the baseline taking turns at going
// first; every adapter sums the whole sample (direction, point, pdf, validity). The times are
// accumulated separately and their quotients
// reported as counters (`ratio_to_lean`, `ratio_to_concentric`, `ratio_to_polar`). Load from other
// processes hits all of them alike and cancels in the quotients. `area` is disklab's precise
// ellipse-frame area sampler (area.h), measured like any other map.
//
// Inputs: a fixed array of 4096 Owen-scrambled Sobol' points (seed 1), so branch patterns
// (quadrants, Newton paths, rejections) are those of a renderer, not of a single repeated u.
//
// What an item is:
//  - sample/<map>/<config>: one direction with its pdf. radial4 returns four per root solve and
//    counts four; tabulated (both) counts every candidate (a rejected one is a zero-weight sample;
//    `accept` reports the acceptance rate); gamito counts accepted samples (it loops until one is
//    accepted; `tries` reports candidates per sample).
//  - setup/<map>/<config>: one `make` per shading point, against the lean baseline's make.
//  - amortized/<map>/<config>/<k>: one `make` followed by k samples, per sample, against the same
//    for the lean baseline (k = 1, 16, 256): k = 1 is one light sample per shading point.
//  - plain/<map>/<config> and plain/<map>/<config>/<k> (k = 1, 256): the same per sample and per
//    make + k samples, timed as the renderer's own loop: inlined into the benchmark, the map a
//    local of its frame, no out-of-line wrapper and no stack offsets.
// Newton maps also report `evals`: mean evaluations of the cumulative solid angle per sample.
// Maps that reproduce the exact radial map (radial, radial-fast, published-*) report `q_err`:
// the largest error of their samples' quadrant fraction, |4 eps1(w) - 4 u.x| with eps1(w) the
// exact radial map's inverse of the returned direction (accepted samples only).
//
// The summary after the table gives the median ratios, bytes per shading point, and checks the
// targets listed in bench/targets.txt (scripts/bench --processes K aggregates them over K runs).
//
// Run: build/<preset>/bin/bench_maps --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true --benchmark_min_time=0.1 (the longest of the programs;
// add --benchmark_filter='/(radial|published-radial-double)/' for a part).
#include <alloca.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "bench_common.h"
#include "disklab/disk/concentric.h"
#include "disklab/disk/polar.h"
#include "disklab/ellipse/area.h"
#include "disklab/ellipse/area_lean.h"
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
#include "published.h"

namespace {
using disklab::Point2;
using disklab::Vec3;
namespace ell = disklab::ellipse;
namespace disk = disklab::disk;
namespace pub = disklab::bench;
using Clock = std::chrono::steady_clock;

// Square points per timed batch: long enough (>= ~5 us for the cheapest map) that the two clock
// reads per batch are noise, short enough that the timed loops alternate often.
constexpr int kBatch = 256;
constexpr int kPoints = 4096;  // the fixed point set; batches walk through it

struct Config {
  const char* name;
  Vec3 center, normal;
  double radius;
  Vec3 o;
  ell::Disk disk() const { return ell::Disk{center, normal, radius, false}; }
};

// Unit disk facing the shading point at the origin (normal -z or tilted: the lit side is +normal).
const std::array<Config, 5>& configs() {
  static const Vec3 tilted = Vec3(0.3, -0.2, -1.0).normalized();
  static const std::array<Config, 5> c = {{
      // Close and off axis: alpha ~ 60 degrees, the map far from its planar limit.
      {"near", Vec3(0.3, 0.2, 0.5), Vec3(0, 0, -1), 1.0, Vec3::Zero()},
      // A few radii away, tilted: the typical area light in a room.
      {"mid", Vec3(1.0, 0.5, 3.0), tilted, 1.0, Vec3::Zero()},
      // A thousand radii away (alpha ~ 1e-3): the common case for small or distant lights.
      {"far", Vec3(300.0, 200.0, 1000.0), tilted, 1.0, Vec3::Zero()},
      // Seen almost edge-on (beta / alpha ~ 1e-2): the eccentric limit.
      {"grazing", Vec3(3.0, 0.0, 0.05), Vec3(0, 0, -1), 1.0, Vec3::Zero()},
      // Ten thousand radii away (alpha ~ 1e-4), issue 16's one-sample scene.
      {"very-far", Vec3(3000.0, 2000.0, 9500.0), tilted, 1.0, Vec3::Zero()},
  }};
  return c;
}

// The lean baseline's per-light part, built once per configuration (a renderer builds it once
// per light, not per shading point).
const ell::LeanDiskLight& lean_light(const Config& c) {
  static const std::array<ell::LeanDiskLight, 5> lights = [] {
    std::array<ell::LeanDiskLight, 5> l;
    for (std::size_t i = 0; i < l.size(); ++i)
      l[i] = ell::LeanDiskLight::make(configs()[i].disk());
    return l;
  }();
  return lights[static_cast<std::size_t>(&c - configs().data())];
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

// A configuration with its shading point nudged (per make in the set-up and amortized loops: a
// fixed input could let the branch predictor learn more than a renderer's stream allows).
Config nudged(const Config& c, Point2 p) {
  Config ci = c;
  ci.o = c.o + 1e-3 * Vec3(p.x, p.y, 0.0);
  return ci;
}

// ---- one adapter per map: how to build it and how to draw a batch of samples ----
// draw(m, u, n, sink) maps the n square points u[0..n) and returns the number of samples made.
// make(c, light) gets the configuration and its lean light (only the lean baseline uses it).

// Everything a renderer reads from a light sample, maps and baselines alike: the direction, the
// point on the light, the pdf and the validity. Summing all of them keeps the optimizer from
// dropping any part of either side's work.
template <class S>
inline double consume(const S& s) {
  return s.direction.x() + s.direction.y() + s.direction.z() + s.point.x() + s.point.y() +
         s.point.z() + s.pdf + (s.valid ? 1.0 : 0.0);
}

template <class M>
struct Plain {  // maps with make(Disk, o) and sample(Point2) -> EllipseSample
  static M make(const Config& c, const ell::LeanDiskLight&) { return M::make(c.disk(), c.o); }
  static int draw(const M& m, const Point2* u, int n, double& sink) {
    for (int i = 0; i < n; ++i) {
      sink += consume(m.sample(u[i]));
    }
    return n;
  }
};

struct LeanA : Plain<ell::LeanAreaSampler> {
  static ell::LeanAreaSampler make(const Config& c, const ell::LeanDiskLight& light) {
    return ell::LeanAreaSampler::make(light, c.o);
  }
};

struct ProjectedAdapter : Plain<ell::ProjectedMap> {
  static ell::ProjectedMap make(const Config& c, const ell::LeanDiskLight&) {
    return ell::ProjectedMap::make(c.disk(), c.o, Vec3::UnitZ());
  }
};

struct Radial4Adapter {
  static ell::Radial4Map make(const Config& c, const ell::LeanDiskLight&) {
    return ell::Radial4Map::make(c.disk(), c.o);
  }
  // n / 4 root solves, four directions each: n samples, the same count as the other maps.
  static int draw(const ell::Radial4Map& m, const Point2* u, int n, double& sink) {
    for (int i = 0; i < n / 4; ++i) {
      const auto s = m.sample4(u[i]);
      for (const auto& x : s)
        sink += consume(x);
    }
    return (n / 4) * 4;
  }
};

struct GamitoAdapter {
  static ell::GamitoSampler make(const Config& c, const ell::LeanDiskLight&) {
    return ell::GamitoSampler::make(c.disk(), c.o);
  }
  static int draw(const ell::GamitoSampler& m, const Point2* u, int n, double& sink) {
    static thread_local disklab::sequence::Pcg32 rng(7);
    for (int i = 0; i < n; ++i) {
      sink += consume(m.sample(u[i], rng));
    }
    return n;
  }
};

using PublishedDouble = Plain<pub::PublishedRadial<pub::DoublePolicy>>;
using PublishedDefault = Plain<pub::PublishedRadial<pub::DefaultPolicy>>;
using PublishedTab = Plain<pub::PublishedTabulated>;

template <Point2 (*F)(Point2)>
int draw_disk(const Point2* u, int n, double& sink) {
  for (int i = 0; i < n; ++i) {
    const Point2 p = F(u[i]);
    sink += p.x + p.y;
  }
  return n;
}

// ---- untimed diagnostics ----

// Mean Newton evaluations per sample over the point set (maps without a root solve: 0).
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

// Maps whose samples should be the exact radial map's (up to their own error).
template <class A>
constexpr bool kReproducesRadial =
    std::is_same_v<A, Plain<ell::RadialMap>> || std::is_same_v<A, Plain<ell::RadialFastMap>> ||
    std::is_same_v<A, PublishedDouble> || std::is_same_v<A, PublishedDefault> ||
    std::is_same_v<A, PublishedTab>;

// Largest |4 eps1(w) - 4 u.x| over the point set (see the header), or -1.
template <class A, class M>
double quadrant_error(const M& m, const Config& c) {
  if constexpr (!kReproducesRadial<A>) {
    return -1.0;
  } else {
    const ell::RadialMap exact = ell::RadialMap::make(c.disk(), c.o);
    double worst = 0.0;
    for (const Point2& u : points()) {
      const auto s = m.sample(u);
      if (!s.valid) continue;
      const Point2 back = exact.invert(s.direction);
      // eps1 is periodic: a direction on the +x_e seam may come back as 0 or 1.
      double d = std::abs(back.x - u.x);
      d = std::min(d, 1.0 - d);
      worst = std::max(worst, 4.0 * d);
    }
    return worst;
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

// Times f and g back to back, f first on even batches and g first on odd ones, so that what the
// first leaves behind (caches, branch history, clock frequency) favours neither side; returns
// {seconds of f, seconds of g}.
template <class F, class G>
std::pair<double, double> timed_pair(long batch, F&& f, G&& g) {
  const bool f_first = batch % 2 == 0;
  const auto t0 = Clock::now();
  if (f_first)
    f();
  else
    g();
  const auto t1 = Clock::now();
  if (f_first)
    g();
  else
    f();
  const auto t2 = Clock::now();
  return f_first ? std::pair{seconds(t0, t1), seconds(t1, t2)}
                 : std::pair{seconds(t1, t2), seconds(t0, t1)};
}

// ---- stack positions ----
// Each timed batch runs at one of kStackOffsets stack positions, kStackStride bytes apart (more
// than 4 KiB in all). A core that compares only the low 12 bits of addresses to decide whether a
// load waits for an earlier store ("4K aliasing") slows a map by up to 40% when one of its stack
// stores (spills, the returned sample) shares those bits with a constant or an input it loads on
// every sample; which pairs do depends on where the caller's stack happens to be. At a single
// position a map's ratio moved by that much between builds, and with the size of the
// environment; over the positions it is the expected cost over a renderer's call sites. Times
// are the median per position (robust to preempted batches), averaged over positions.
constexpr int kStackOffsets = 16;
constexpr std::size_t kStackStride = 272;  // 16-byte aligned; 16 * 272 = 4352 bytes

// f() with the stack moved down by k * kStackStride bytes: f must call out of line (the frames
// of what it calls lie below the pad, its own inlined locals do not).
template <class F>
[[gnu::noinline]] int at_stack_offset(int k, F&& f) {
  auto* pad = static_cast<volatile char*>(alloca(16 + static_cast<std::size_t>(k) * kStackStride));
  pad[0] = 0;
  return f();
}

// A map's draw, out of line so that at_stack_offset moves its frame, on a copy of the map in that
// frame (the map's position counts as much as its spills'), summing into a local (a sink in the
// caller's frame, stored on every sample because it may alias the inputs, made a slow mode of
// its own).
template <class A, class M>
[[gnu::noinline]] int draw_out_of_line(const M& m, const Point2* u, int n, double& sink) {
  const M here = m;  // NOLINT(performance-unnecessary-copy-initialization): the copy is the point
  double here_sink = 0.0;
  const int drawn = A::draw(here, u, n, here_sink);
  sink += here_sink;
  return drawn;
}
template <Point2 (*F)(Point2)>
[[gnu::noinline]] int draw_disk_out_of_line(const Point2* u, int n, double& sink) {
  return draw_disk<F>(u, n, sink);
}

// `count` makes per shading point p[i] (the set-up benchmark), out of line.
template <class A>
[[gnu::noinline]] int make_out_of_line(const Config& c, const Point2* p, int count,
                                       const ell::LeanDiskLight& light) {
  for (int i = 0; i < count; ++i) {
    const auto m = A::make(nudged(c, p[i]), light);
    benchmark::DoNotOptimize(m);
  }
  return count;
}
// `reps` shading points of one make and k samples each, from u[offset] on; samples drawn.
template <class A>
[[gnu::noinline]] int make_and_draw_out_of_line(const Config& c, const ell::LeanDiskLight& light,
                                                const std::vector<Point2>& u, int offset, int reps,
                                                int k, double& sink) {
  int drawn = 0;
  double here_sink = 0.0;
  for (int r = 0; r < reps; ++r) {
    const auto m = A::make(nudged(c, u[offset]), light);
    drawn += A::draw(m, u.data() + offset, k, here_sink);
    offset = (offset + k) % kPoints;
  }
  sink += here_sink;
  return drawn;
}

// Per-batch times, kept per stack position.
struct PositionTimes {
  std::array<std::vector<double>, kStackOffsets> t;
  void add(int k, double seconds) { t[static_cast<std::size_t>(k)].push_back(seconds); }
  // Mean over the positions of the median batch time at each (positions never run are skipped).
  double typical() {
    double sum = 0.0;
    int n = 0;
    for (auto& v : t) {
      if (v.empty()) continue;
      sum += median(v);
      ++n;
    }
    return n > 0 ? sum / n : 0.0;
  }
};

// ---- per-sample cost, interleaved with the baselines ----
template <class A>
void BM_Sample(benchmark::State& state, const Config& c) {
  const ell::LeanDiskLight& light = lean_light(c);
  const auto m = A::make(c, light);
  const auto lean = LeanA::make(c, light);
  if (!m.valid() || !lean.valid()) {
    state.SkipWithError("invalid configuration");
    return;
  }
  const std::vector<Point2>& u = points();
  double sink = 0.0;
  PositionTimes t_map, t_lean, t_conc, t_polar;  // per batch
  long n_map = 0;
  int per_batch = kBatch;
  int offset = 0, position = 0;
  long batches = 0;
  for (auto _ : state) {
    const Point2* batch = u.data() + offset;
    offset = (offset + kBatch) % kPoints;
    const int k = position;
    position = (position + 1) % kStackOffsets;
    const auto [s_map, s_lean] = timed_pair(
        batches++,
        [&] {
          per_batch =
              at_stack_offset(k, [&] { return draw_out_of_line<A>(m, batch, kBatch, sink); });
        },
        [&] {
          at_stack_offset(k, [&] { return draw_out_of_line<LeanA>(lean, batch, kBatch, sink); });
        });
    const auto t2 = Clock::now();
    at_stack_offset(
        k, [&] { return draw_disk_out_of_line<disk::sample_concentric>(batch, kBatch, sink); });
    const auto t3 = Clock::now();
    at_stack_offset(k,
                    [&] { return draw_disk_out_of_line<disk::sample_polar>(batch, kBatch, sink); });
    const auto t4 = Clock::now();
    n_map += per_batch;
    t_map.add(k, s_map);
    t_lean.add(k, s_lean);
    t_conc.add(k, seconds(t2, t3));
    t_polar.add(k, seconds(t3, t4));
    state.SetIterationTime(s_map);
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(n_map);
  const double per_map = t_map.typical() / per_batch;
  const double per_lean = t_lean.typical() / kBatch;
  state.counters["ns"] = per_map * 1e9;
  state.counters["lean_ns"] = per_lean * 1e9;
  state.counters["ratio_to_lean"] = per_map / per_lean;
  state.counters["ratio_to_concentric"] = per_map / (t_conc.typical() / kBatch);
  state.counters["ratio_to_polar"] = per_map / (t_polar.typical() / kBatch);
  state.counters["bytes"] = sizeof(m);
  const double evals = mean_evaluations(m);
  if (evals > 0.0) state.counters["evals"] = evals;
  const double q_err = quadrant_error<A>(m, c);
  if (q_err >= 0.0) state.counters["q_err"] = q_err;
  if constexpr (std::is_same_v<A, Plain<ell::TabulatedMap>> || std::is_same_v<A, PublishedTab>) {
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

// ---- set-up cost per shading point, interleaved with the lean baseline's make ----
template <class A>
void BM_Setup(benchmark::State& state, const Config& c) {
  constexpr int kMakes = 32;
  const ell::LeanDiskLight& light = lean_light(c);
  PositionTimes t_map, t_lean;
  long count = 0;
  const std::vector<Point2>& u = points();
  int offset = 0, position = 0;
  long batches = 0;
  for (auto _ : state) {
    const Point2* p = u.data() + offset;
    offset = (offset + kMakes) % kPoints;
    const int k = position;
    position = (position + 1) % kStackOffsets;
    const auto [s_map, s_lean] = timed_pair(
        batches++,
        [&] { at_stack_offset(k, [&] { return make_out_of_line<A>(c, p, kMakes, light); }); },
        [&] { at_stack_offset(k, [&] { return make_out_of_line<LeanA>(c, p, kMakes, light); }); });
    count += kMakes;
    t_map.add(k, s_map);
    t_lean.add(k, s_lean);
    state.SetIterationTime(s_map);
  }
  state.SetItemsProcessed(count);
  const double m_map = t_map.typical(), m_lean = t_lean.typical();
  state.counters["ns"] = m_map / kMakes * 1e9;
  state.counters["lean_ns"] = m_lean / kMakes * 1e9;
  state.counters["ratio_to_lean"] = m_map / m_lean;
}

// ---- one make + k samples, per sample, against the same for the lean baseline ----
template <class A>
void BM_Amortized(benchmark::State& state, const Config& c, int k) {
  const int reps = std::max(1, 256 / k);  // shading points per timed batch
  const ell::LeanDiskLight& light = lean_light(c);
  double sink = 0.0;
  PositionTimes t_map, t_lean;
  long samples = 0;
  int per_batch = reps * k;
  const std::vector<Point2>& u = points();
  int offset = 0, position = 0;
  long batches = 0;
  for (auto _ : state) {
    const int at = position;
    position = (position + 1) % kStackOffsets;
    const auto [s_map, s_lean] = timed_pair(
        batches++,
        [&] {
          per_batch = at_stack_offset(
              at, [&] { return make_and_draw_out_of_line<A>(c, light, u, offset, reps, k, sink); });
        },
        [&] {
          at_stack_offset(at, [&] {
            return make_and_draw_out_of_line<LeanA>(c, light, u, offset, reps, k, sink);
          });
        });
    offset = (offset + reps * k) % kPoints;
    samples += per_batch;
    t_map.add(at, s_map);
    t_lean.add(at, s_lean);
    state.SetIterationTime(s_map);
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(samples);
  // radial4 draws k/4 solves of four (it is not registered for k < 4): count what was drawn.
  const double per_map = t_map.typical() / std::max(1, per_batch);
  const double per_lean = t_lean.typical() / (reps * k);
  state.counters["ns"] = per_map * 1e9;
  state.counters["ratio_to_lean"] = per_map / per_lean;
}

// ---- plain mode: the loop a renderer writes ----
// plain/<map>/<config>: per sample, each batch of kBatch points mapped by a loop inlined into
// this function, with the map a local of its frame, no out-of-line wrapper and no stack offsets;
// plain/<map>/<config>/<k>: the same for one make at a nudged shading point followed by k
// samples. The lean baseline's identical loop alternates with the map's, batch by batch; times
// are the medians of the batch times.
template <class A>
void BM_Plain(benchmark::State& state, const Config& c, int k) {
  const ell::LeanDiskLight& light = lean_light(c);
  const std::vector<Point2>& u = points();
  const int reps = k > 0 ? std::max(1, kBatch / k) : 1;  // shading points per batch
  const int per_point = k > 0 ? k : kBatch;              // samples per shading point
  // One shading point: make (when k > 0: per point, at a nudged o) and draw per_point samples.
  const auto run = [&](auto adapter, const auto& fixed, int offset, double& sink) {
    using Ad = decltype(adapter);
    int drawn = 0;
    for (int r = 0; r < reps; ++r) {
      const int at = (offset + r * per_point) % kPoints;
      if (k > 0) {
        const auto m = Ad::make(nudged(c, u[static_cast<std::size_t>(at)]), light);
        drawn += Ad::draw(m, u.data() + at, per_point, sink);
      } else {
        drawn += Ad::draw(fixed, u.data() + at, per_point, sink);
      }
    }
    return drawn;
  };
  const auto m = A::make(c, light);
  const auto lean = LeanA::make(c, light);
  if (!m.valid() || !lean.valid()) {
    state.SkipWithError("invalid configuration");
    return;
  }
  std::vector<double> t_map, t_lean;
  double sink = 0.0;
  long samples = 0;
  int drawn = 0, offset = 0;
  long batches = 0;
  for (auto _ : state) {
    double s_map = 0.0, s_lean = 0.0;
    const auto [dt_map, dt_lean] = timed_pair(
        batches++, [&] { drawn = run(A{}, m, offset, s_map); },
        [&] { run(LeanA{}, lean, offset, s_lean); });
    // Stays a multiple of per_point, which divides kPoints: no batch runs past the points.
    offset = (offset + reps * per_point) % kPoints;
    samples += drawn;
    t_map.push_back(dt_map);
    t_lean.push_back(dt_lean);
    sink += s_map + s_lean;
    state.SetIterationTime(dt_map);
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(samples);
  const double per_map = median(t_map) / std::max(1, drawn);
  const double per_lean = median(t_lean) / (reps * per_point);
  state.counters["ns"] = per_map * 1e9;
  state.counters["lean_ns"] = per_lean * 1e9;
  state.counters["ratio_to_lean"] = per_map / per_lean;
}

std::map<std::string, double>& state_bytes() {  // map name -> sizeof its per-shading-point state
  static std::map<std::string, double> b;
  return b;
}

template <class A>
void register_map(const std::string& name) {
  using M = decltype(A::make(configs()[0], lean_light(configs()[0])));
  state_bytes()[name] = sizeof(M);
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
  for (const Config& c : configs()) {
    benchmark::RegisterBenchmark(("plain/" + name + "/" + c.name).c_str(),
                                 [&c](benchmark::State& s) { BM_Plain<A>(s, c, 0); })
        ->UseManualTime();
    for (int k : {1, 256}) {
      if (std::is_same_v<A, Radial4Adapter> && k < 4) continue;
      benchmark::RegisterBenchmark(
          ("plain/" + name + "/" + c.name + "/" + std::to_string(k)).c_str(),
          [&c, k](benchmark::State& s) { BM_Plain<A>(s, c, k); })
          ->UseManualTime();
    }
  }
}

// ---- the summary ----
using disklab::bench::Results;

double ratio(const Results& values, const std::string& name, const char* key = "ratio_to_lean") {
  const auto it = values.find(name);
  return it == values.end() ? -1.0 : disklab::bench::counter(it->second, key);
}

// One line of bench/targets.txt (its header has the format).
struct Target {
  std::string id, what;
  double limit = 0.0;
  std::string p, q;                  // benchmark patterns with {cfg}; q empty for a plain ratio
  std::vector<std::string> configs;  // empty: every configuration
};

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::vector<Target> load_targets(const char* path, std::string& error) {
  std::vector<Target> out;
  std::ifstream in(path);
  if (!in) {
    error = std::string("cannot open ") + path;
    return out;
  }
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string part; std::getline(ss, part, '|');)
      f.push_back(trim(part));
    std::stringstream form(f.size() == 4 ? f[3] : "");
    std::string kind, word;
    form >> kind;
    Target t;
    if (f.size() == 4) {
      t.id = f[0];
      t.what = f[2];
      char* end = nullptr;
      t.limit = std::strtod(f[1].c_str(), &end);
      if (end == f[1].c_str() || *end != '\0' || !(t.limit > 0.0)) kind.clear();
    }
    if (kind == "ratio" || kind == "quotient") {
      form >> t.p;
      if (kind == "quotient") form >> t.q;
      while (form >> word) {
        if (word.rfind("configs=", 0) != 0) kind.clear();
        std::stringstream cs(word.substr(8));
        for (std::string c; std::getline(cs, c, ',');) {
          const auto known = [&c](const Config& x) { return c == x.name; };
          if (std::none_of(configs().begin(), configs().end(), known)) kind.clear();
          t.configs.push_back(c);
        }
      }
    }
    if ((kind != "ratio" && kind != "quotient") || t.p.empty() ||
        (kind == "quotient" && t.q.empty())) {
      error = std::string(path) + ":" + std::to_string(number) + ": not 'id | limit | what | form'";
      return {};
    }
    out.push_back(t);
  }
  return out;
}

// A pattern's value at one configuration: {cfg} replaced, `:counter` read (default: the ratio to
// the lean baseline); -1 when that benchmark was not run.
double value_of(const Results& values, const std::string& pattern, const std::string& cfg) {
  std::string name = pattern, key = "ratio_to_lean";
  if (const auto colon = name.find(':'); colon != std::string::npos) {
    key = name.substr(colon + 1);
    name.resize(colon);
  }
  if (const auto at = name.find("{cfg}"); at != std::string::npos) name.replace(at, 5, cfg);
  return ratio(values, name, key.c_str());
}

// Worst over the target's configurations of value(config) (configurations that were not run are
// skipped), printed against the limit on one line that scripts/bench --processes reads:
//   [id] what  worst X.XXx (config), target <= Lx: met|MISSED
template <class F>
void check(const Target& t, F value) {
  double worst = -1.0;
  std::string where;
  for (const Config& c : configs()) {
    if (!t.configs.empty() &&
        std::find(t.configs.begin(), t.configs.end(), c.name) == t.configs.end())
      continue;
    const double v = value(std::string(c.name));
    if (v < 0.0) continue;
    if (v > worst) {
      worst = v;
      where = c.name;
    }
  }
  const std::string label = "[" + t.id + "] " + t.what;
  if (worst < 0.0) {
    std::printf("  %-78s not run\n", label.c_str());
    return;
  }
  std::printf("  %-78s worst %6.2fx (%s), target <= %.2gx: %s\n", label.c_str(), worst,
              where.c_str(), t.limit, worst <= t.limit ? "met" : "MISSED");
}

void print_summary(const Results& values) {
  std::printf(
      "\nMedian ratios (same run) to the lean area baseline (area_lean.h). sample: per direction;\n"
      "setup: per make; amortized/k: (make + k samples) / k, against the same for the baseline.\n");
  std::printf("%-44s %9s %8s %9s %9s %7s %9s\n", "benchmark", "ns", "x lean", "x concen", "x polar",
              "evals", "q_err");
  for (const auto& [name, v] : values) {
    const auto get = [&c = v](const char* k) { return disklab::bench::counter(c, k); };
    std::printf("%-44s %9.1f %8.2f", name.c_str(), get("ns"), get("ratio_to_lean"));
    if (get("ratio_to_concentric") >= 0)
      std::printf(" %9.1f %9.1f", get("ratio_to_concentric"), get("ratio_to_polar"));
    else
      std::printf(" %9s %9s", "", "");
    if (get("evals") >= 0)
      std::printf(" %7.2f", get("evals"));
    else
      std::printf(" %7s", "");
    if (get("q_err") >= 0) std::printf(" %9.1e", get("q_err"));
    std::printf("\n");
  }

  std::printf("\nBytes per shading point (sizeof the state `make` returns; none allocates):\n");
  for (const auto& [name, bytes] : state_bytes())
    std::printf("  %-28s %6.0f\n", name.c_str(), bytes);
  std::printf(
      "Shared tables (built once per process): tabulated %zu bytes, "
      "published-tabulated %zu bytes\n",
      ell::RadialTable::shared().phi.size() * sizeof(double),
      pub::PublishedTable::shared().bytes());

  std::printf("\nTargets (same-run ratios; worst configuration; %s):\n", DISKLAB_BENCH_TARGETS);
  std::string error;
  const std::vector<Target> targets = load_targets(DISKLAB_BENCH_TARGETS, error);
  if (!error.empty()) std::printf("  cannot read the targets: %s\n", error.c_str());
  for (const Target& t : targets)
    check(t, [&](const std::string& cfg) {
      const double a = value_of(values, t.p, cfg);
      if (t.q.empty()) return a;
      const double b = value_of(values, t.q, cfg);
      return a > 0.0 && b > 0.0 ? a / b : -1.0;
    });
  std::printf(
      "Anchor (issue 5): the authors' Newton sample costs ~40-220x a polar disk sample;\n"
      "compare the 'x polar' column of sample/published-radial-*, sample/radial.\n");
}

}  // namespace

int main(int argc, char** argv) {
  // Built before any timing: the shared tables, the lean lights and the points.
  (void)ell::RadialTable::shared();
  (void)pub::PublishedTable::shared();
  (void)lean_light(configs()[0]);
  (void)points();
  register_map<LeanA>("lean-area");
  register_map<Plain<ell::AreaSampler>>("area");
  register_map<GamitoAdapter>("gamito");
  register_map<Plain<ell::ParallelMap>>("parallel");
  register_map<Plain<ell::RadialMap>>("radial");
  register_map<Plain<ell::LdRadialMap>>("ld-radial");
  register_map<Radial4Adapter>("radial4");
  register_map<Plain<ell::TabulatedMap>>("tabulated");
  register_map<Plain<ell::RadialFastMap>>("radial-fast");
  register_map<ProjectedAdapter>("projected");
  register_map<PublishedDouble>("published-radial-double");
  register_map<PublishedDefault>("published-radial-default");
  register_map<PublishedTab>("published-tabulated");
  return disklab::bench::run_benchmarks(argc, argv, print_summary);
}
