// ART (Ahmed, Niese, Huang, Deussen 2017; sequence/art.h) is what the method says it is: the
// compiled table is self-consistent (each tile's point is shared by its first child), the first
// 16^k points stratify the 4^k x 4^k lattice and m 16^k points put m in every level-k tile, the
// sequence is not a (0,2)-net, and its L2-star discrepancy lies between random's and pmj02's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common.h"
#include "disklab/sequence/art.h"
#include "disklab/sequence/discrepancy.h"
#include "disklab/sequence/random.h"
#include "disklab/sequence/sequence.h"
#include "disklab/sequence/tabulated.h"

namespace disklab::sequence {
namespace {

using test::seq::is_02_net;
using test::seq::kStructureSeeds;

// The CSV records each point as the double nearest the exact base-4 expansion; the library keeps
// its first 16 digits (32 bits), i.e. truncates: recorded - 2^-32 < library <= recorded, plus the
// double's own rounding (half an ulp of a value below 1: 2^-54).
constexpr double kRecordedPointSlack = 0x1p-32 + 0x1p-54;

TEST(ArtTable, EachPointIsSharedByItsFirstChild) {
  ASSERT_GE(art::tile_count(), 2u);
  for (uint32_t t = 0; t < art::tile_count(); ++t) {
    const art::Tile& tile = art::tile(t);
    const uint32_t cell = tile.order[0];
    const art::Tile& child = art::tile(tile.child[cell]);
    // p = (cell + p_child) / 4, exactly, in 32-bit fractions (the child's last digit drops out).
    EXPECT_EQ(tile.point.x, ((cell & 3u) << 30u) | (child.point.x >> 2u)) << "type " << t;
    EXPECT_EQ(tile.point.y, ((cell >> 2u) << 30u) | (child.point.y >> 2u)) << "type " << t;
    const Point2 rec = art::recorded_point(t);
    const double x = to_unit(tile.point.x), y = to_unit(tile.point.y);
    EXPECT_TRUE(x <= rec.x && rec.x - x <= kRecordedPointSlack)
        << "type " << t << ": library x " << x << ", CSV " << rec.x;
    EXPECT_TRUE(y <= rec.y && rec.y - y <= kRecordedPointSlack)
        << "type " << t << ": library y " << y << ", CSV " << rec.y;
  }
}

TEST(Art, FirstPointIsTheRootTilesPoint) {
  for (uint64_t seed : kStructureSeeds) {
    const ArtSequence seq(seed);
    EXPECT_EQ(seq.lattice_at(0), art::tile(seq.root()).point) << "seed " << seed;
  }
}

// Level-k tile (of the unshifted lattice) holding a point: the top 2k bits of each coordinate.
uint32_t tile_of(FixedPoint2 p, int k) {
  if (k == 0) return 0;
  return ((p.y >> (32 - 2 * k)) << (2 * k)) | (p.x >> (32 - 2 * k));
}

TEST(Art, PowersOf16StratifyTheShiftedLattice) {
  // At N = 16^k every cell of the 4^k x 4^k grid, shifted with the lattice by shift(), holds
  // exactly one point (k = 1, 2, 3); the shift is undone in integer arithmetic (exact).
  for (uint64_t seed : kStructureSeeds) {
    const ArtSequence seq(seed);
    const FixedPoint2 s = seq.shift();
    for (int k = 1; k <= 3; ++k) {
      const uint32_t n = 1u << (4 * k);
      std::vector<int> count(n, 0);
      for (uint32_t i = 0; i < n; ++i) {
        const FixedPoint2 p = seq.fixed_at(i);
        const FixedPoint2 unshifted{p.x - s.x, p.y - s.y};
        ASSERT_EQ(unshifted, seq.lattice_at(i)) << "seed " << seed << " index " << i;
        ++count[tile_of(unshifted, k)];
      }
      for (uint32_t c = 0; c < n; ++c)
        ASSERT_EQ(count[c], 1) << "seed " << seed << ", N = 16^" << k << ": cell ("
                               << (c % (1u << 2 * k)) << ", " << (c >> 2 * k) << ") holds "
                               << count[c] << " points";
    }
  }
}

TEST(Art, PrefixesOfM16kPutMPointsInEveryLevelKTile) {
  // The progressive traversal: N = m 16^k points are the first m children of every level-k tile,
  // so every level-k tile holds m of them (m = 1..16, k = 0..2), and each a different child.
  for (uint64_t seed : kStructureSeeds) {
    const ArtSequence seq(seed);
    for (int k = 0; k <= 2; ++k) {
      const uint32_t tiles = 1u << (4 * k);
      for (uint32_t m = 1; m <= 16; ++m) {
        std::vector<int> count(tiles, 0), child_count(tiles * 16, 0);
        for (uint32_t i = 0; i < m * tiles; ++i) {
          const FixedPoint2 p = seq.lattice_at(i);
          ++count[tile_of(p, k)];
          ++child_count[tile_of(p, k + 1)];
        }
        for (uint32_t c = 0; c < tiles; ++c)
          ASSERT_EQ(count[c], static_cast<int>(m))
              << "seed " << seed << ", N = " << m << " x 16^" << k << ", tile " << c;
        for (uint32_t c = 0; c < tiles * 16; ++c)
          ASSERT_LE(child_count[c], 1) << "seed " << seed << ", N = " << m << " x 16^" << k;
      }
    }
  }
}

TEST(Art, IsNotA02Net) {
  // One point per cell of a 4^k grid is the (0,2)-net shape 2^2k x 2^2k only; the tile offsets
  // are blue-noise positions, not digit permutations, so the elongated elementary intervals
  // (1/16 x 1 at N = 16, ...) are not one-per-interval. Asserted as the method predicts.
  for (uint64_t seed : kStructureSeeds) {
    const ArtSequence seq(seed);
    std::vector<FixedPoint2> points(4096);
    for (uint32_t i = 0; i < points.size(); ++i)
      points[i] = seq.fixed_at(i);
    for (int m : {4, 8, 12}) {
      std::string why;
      EXPECT_FALSE(is_02_net(points, 0, m, &why)) << "seed " << seed << ": prefix 2^" << m;
    }
  }
}

TEST(Art, DiscrepancyLiesBetweenRandomAndPmj02) {
  // Mean L2-star discrepancy over kSeeds seeds at N = 256, 1024, 4096: pmj02 < art < random.
  // Strict order of the means, no tolerance: the printed standard errors show the gaps are many
  // of them wide.
  constexpr int kSeeds = 8;
  const uint32_t sizes[] = {256, 1024, 4096};
  const char* names[] = {"random", "art", "pmj02"};
  double mean[3][3] = {}, mean2[3][3] = {};
  for (int s = 0; s < kSeeds; ++s) {
    const RandomSequence random(static_cast<uint64_t>(s));
    const ArtSequence art_seq(static_cast<uint64_t>(s));
    const Pmj02 pmj(static_cast<uint64_t>(s), 4096);
    for (int k = 0; k < 3; ++k) {
      std::vector<Point2> p[3];
      for (uint32_t i = 0; i < sizes[k]; ++i) {
        p[0].push_back(random.at(i));
        p[1].push_back(art_seq.at(i));
        p[2].push_back(pmj.at(i));
      }
      for (int q = 0; q < 3; ++q) {
        const double d = l2_star_discrepancy(p[q]);
        mean[q][k] += d / kSeeds;
        mean2[q][k] += d * d / kSeeds;
      }
    }
  }
  for (int k = 0; k < 3; ++k) {
    std::printf("N=%5u:", sizes[k]);
    for (int q = 0; q < 3; ++q) {
      const double se =
          std::sqrt(std::max(0.0, mean2[q][k] - mean[q][k] * mean[q][k]) / (kSeeds - 1));
      std::printf("  %s %.3e +- %.1e", names[q], mean[q][k], se);
    }
    std::printf("   (mean L2-star over %d seeds)\n", kSeeds);
    EXPECT_LT(mean[1][k], mean[0][k]) << "art not below random at N = " << sizes[k];
    EXPECT_GT(mean[1][k], mean[2][k]) << "art not above pmj02 at N = " << sizes[k];
  }
}

}  // namespace
}  // namespace disklab::sequence
