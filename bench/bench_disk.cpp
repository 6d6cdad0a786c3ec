// Per-sample cost of the six disk strategies (Christensen 2018, Sec. 3), all in one run, next to
// the baseline of drawing a plain PCG32 pair (what every strategy needs anyway).
//
// Each benchmark draws its square points from PCG32 and produces disk samples; items are DISK
// samples: polar4/concentric4 count four per square point, rejection counts accepted points
// (it draws 4/pi square points per sample on average), pad-zero counts every point, zeros
// included. The summary after the table divides each per-sample time by the baseline's, from
// the same run (absolute times depend on the machine, ratios much less).
//
// Run: build/<preset>/bin/bench_disk [--benchmark_min_time=0.2]
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "bench_common.h"
#include "disklab/disk/strategy.h"
#include "disklab/sequence/random.h"

namespace {
using disklab::Point2;
using disklab::sequence::Pcg32;
namespace disk = disklab::disk;

constexpr int kBatch = 1024;  // disk samples per timed loop body, to amortise loop overhead

inline Point2 next_pair(Pcg32& rng) {
  const double u = rng.next_double();
  return {u, rng.next_double()};
}

void BM_Baseline_Pcg32Pair(benchmark::State& state) {
  Pcg32 rng(42);
  for (auto _ : state) {
    for (int i = 0; i < kBatch; ++i)
      benchmark::DoNotOptimize(next_pair(rng));
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}

template <Point2 (*Map)(Point2)>
void BM_Map(benchmark::State& state) {
  Pcg32 rng(42);
  for (auto _ : state) {
    for (int i = 0; i < kBatch; ++i)
      benchmark::DoNotOptimize(Map(next_pair(rng)));
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}

template <std::array<Point2, 4> (*Map4)(Point2)>
void BM_Map4(benchmark::State& state) {
  Pcg32 rng(42);
  for (auto _ : state) {
    for (int i = 0; i < kBatch / 4; ++i)
      benchmark::DoNotOptimize(Map4(next_pair(rng)));
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}

void BM_PadZero(benchmark::State& state) {
  Pcg32 rng(42);
  for (auto _ : state) {
    for (int i = 0; i < kBatch; ++i)
      benchmark::DoNotOptimize(disk::sample_pad_zero(next_pair(rng)));
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}

void BM_Rejection(benchmark::State& state) {
  Pcg32 rng(42);
  uint64_t tries = 0;
  for (auto _ : state) {
    for (int i = 0; i < kBatch; ++i) {
      disk::RejectionTry r;
      do {
        r = disk::try_rejection(next_pair(rng));
        ++tries;
      } while (!r.accepted);
      benchmark::DoNotOptimize(r.point);
    }
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
  state.counters["square_per_sample"] =
      double(tries) / double(std::max<int64_t>(1, state.iterations() * kBatch));
}

// The inverses, for the cost of mapping a disk point back (same baseline: the pair is drawn,
// mapped forward outside the timed region would cost more than it helps; a fixed point set is
// used instead).
template <Point2 (*Inverse)(Point2), Point2 (*Forward)(Point2)>
void BM_Inverse(benchmark::State& state) {
  Pcg32 rng(42);
  std::vector<Point2> pts(kBatch);
  for (auto& p : pts)
    p = Forward(next_pair(rng));
  for (auto _ : state) {
    for (const Point2& p : pts)
      benchmark::DoNotOptimize(Inverse(p));
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}

BENCHMARK(BM_Baseline_Pcg32Pair);
BENCHMARK(BM_PadZero);
BENCHMARK(BM_Rejection);
BENCHMARK(BM_Map<disk::sample_polar>)->Name("BM_Polar");
BENCHMARK(BM_Map<disk::sample_concentric>)->Name("BM_Concentric");
BENCHMARK(BM_Map4<disk::sample_polar4>)->Name("BM_Polar4");
BENCHMARK(BM_Map4<disk::sample_concentric4>)->Name("BM_Concentric4");
BENCHMARK(BM_Inverse<disk::invert_polar, disk::sample_polar>)->Name("BM_InvertPolar");
BENCHMARK(BM_Inverse<disk::invert_concentric, disk::sample_concentric>)
    ->Name("BM_InvertConcentric");

// After the console table: each benchmark's time per item over the baseline's.
void print_summary(const disklab::bench::Results& results) {
  std::map<std::string, double> ns_per_item;
  for (const auto& [name, v] : results) {
    const double per_second = disklab::bench::counter(v, "items_per_second");
    if (per_second > 0) ns_per_item[name] = 1e9 / per_second;
  }
  const auto base = ns_per_item.find("BM_Baseline_Pcg32Pair");
  if (base == ns_per_item.end()) return;
  std::printf("\nPer disk sample, relative to drawing one PCG32 pair (same run):\n");
  for (const auto& [name, ns] : ns_per_item)
    std::printf("  %-24s %8.2f ns  %6.2f x baseline\n", name.c_str(), ns, ns / base->second);
}

}  // namespace

int main(int argc, char** argv) {
  return disklab::bench::run_benchmarks(argc, argv, print_summary);
}
