// Best candidates (Mitchell 1991): the point of the method is a large minimum distance. At equal
// N its minimum (toroidal) distance must clearly exceed that of uniform random points. pmj02bn's
// candidates make its sets at power-of-two counts blue noise: farther apart than pmj02's nets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "common.h"
#include "disklab/sequence/random.h"
#include "disklab/sequence/tabulated.h"

namespace disklab::sequence {
namespace {

double toroidal_distance2(Point2 a, Point2 b) {
  double dx = std::abs(a.x - b.x), dy = std::abs(a.y - b.y);
  dx = std::min(dx, 1.0 - dx);
  dy = std::min(dy, 1.0 - dy);
  return dx * dx + dy * dy;
}

// Exact minimum over all pairs. A pair closer than the cell width 1/s of an s x s grid lies in
// neighbouring cells (toroidally), so the grid finds it; if no pair is that close, all pairs.
double min_toroidal_distance(const std::vector<Point2>& p) {
  double best = std::numeric_limits<double>::infinity();
  const auto s = static_cast<int>(std::sqrt(static_cast<double>(p.size())));
  if (s >= 3) {
    auto cell = [s](double v) { return std::min(static_cast<int>(v * s), s - 1); };
    std::vector<std::vector<std::size_t>> cells(static_cast<std::size_t>(s) * s);
    for (std::size_t i = 0; i < p.size(); ++i)
      cells[cell(p[i].y) * s + cell(p[i].x)].push_back(i);
    for (std::size_t i = 0; i < p.size(); ++i)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int gx = (cell(p[i].x) + dx + s) % s, gy = (cell(p[i].y) + dy + s) % s;
          for (std::size_t j : cells[gy * s + gx])
            if (j != i) best = std::min(best, toroidal_distance2(p[i], p[j]));
        }
    if (best * s * s < 1.0) return std::sqrt(best);
  }
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      best = std::min(best, toroidal_distance2(p[i], p[j]));
  return std::sqrt(best);
}

template <class Gen>
std::vector<Point2> prefix(const Gen& gen, uint32_t n) {
  std::vector<Point2> p(n);
  for (uint32_t i = 0; i < n; ++i)
    p[i] = gen.at(i);
  return p;
}

TEST(BestCandidate, MinimumDistanceWellAboveRandom) {
  // Every prefix N (it is progressive), several seeds: the worst best-candidate minimum distance
  // against the best random one must still exceed kBestCandidateMinDistanceFactor.
  for (uint32_t n : {64u, 512u, 4096u}) {
    double worst_bc = std::numeric_limits<double>::infinity(), best_random = 0.0;
    for (uint64_t seed : test::seq::kStructureSeeds) {
      const BestCandidate bc(seed, 4096);
      worst_bc = std::min(worst_bc, min_toroidal_distance(prefix(bc, n)));
      best_random = std::max(best_random, min_toroidal_distance(prefix(RandomSequence(seed), n)));
    }
    const double ratio = worst_bc / best_random;
    RecordProperty("ratio_N" + std::to_string(n), std::to_string(ratio));
    EXPECT_GT(ratio, test::seq::kBestCandidateMinDistanceFactor)
        << "N=" << n << ": best-candidate min distance " << worst_bc
        << " (worst of seeds) vs random " << best_random << " (best of seeds); ratio " << ratio;
    // Blue noise keeps a fixed fraction of the densest packing's spacing at every N (hexagonal:
    // sqrt(2 / (sqrt(3) N))), where random points fall to ~(pi N)^-1/2 / N of it.
    const double hex = std::sqrt(2.0 / (std::sqrt(3.0) * n));
    EXPECT_GT(worst_bc, test::seq::kBestCandidateHexFraction * hex)
        << "N=" << n << ": min distance " << worst_bc << " below "
        << test::seq::kBestCandidateHexFraction << " of the hexagonal spacing " << hex;
  }
}

TEST(BestCandidate, Pmj02BlueNoiseIsBlueNoiseAtPowersOfTwo) {
  struct Case {
    uint32_t n;
    int seeds;
    double gain;  // 0: recorded only (see common.h)
  };
  for (const Case& c : {Case{256, test::seq::kBlueNoiseSeeds, test::seq::kBlueNoiseGainN256},
                        Case{1024, test::seq::kBlueNoiseSeeds, test::seq::kBlueNoiseGainN1024},
                        Case{4096, test::seq::kBlueNoiseSeedsN4096, 0.0}}) {
    double mean_bn = 0.0, mean_pmj = 0.0;
    for (int s = 0; s < c.seeds; ++s) {
      const auto seed = static_cast<uint64_t>(s);
      mean_bn += min_toroidal_distance(prefix(Pmj02BlueNoise(seed, c.n), c.n));
      mean_pmj += min_toroidal_distance(prefix(Pmj02(seed, c.n), c.n));
    }
    mean_bn /= c.seeds;
    mean_pmj /= c.seeds;
    const double ratio = mean_bn / mean_pmj;
    RecordProperty("ratio_N" + std::to_string(c.n), std::to_string(ratio));
    if (c.gain > 0.0) {
      EXPECT_GT(ratio, c.gain) << "N=" << c.n << ", " << c.seeds
                               << " seeds: mean min distance x sqrt(N) pmj02bn "
                               << mean_bn * std::sqrt(c.n) << " vs pmj02 "
                               << mean_pmj * std::sqrt(c.n) << "; ratio " << ratio;
    }
  }
}

}  // namespace
}  // namespace disklab::sequence
