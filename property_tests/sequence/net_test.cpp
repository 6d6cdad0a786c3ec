// (0,2)-net property (Christensen 2018, Sec. 2; docs/design.md "Randomizations and nets"): every
// power-of-two prefix up to 2^16 and every aligned power-of-two block of Sobol' (unrandomized,
// xor- and Owen-scrambled) and pmj02 puts exactly one point in each elementary interval; so do
// pmj02bn's prefixes and their second halves. pmj's sub-square rule holds for both.
// Cranley-Patterson rotation breaks the net property: asserted, as the documented fact it is.
#include <gtest/gtest.h>

#include <bit>
#include <functional>
#include <string>
#include <vector>

#include "common.h"
#include "disklab/sequence/sobol.h"
#include "disklab/sequence/tabulated.h"

namespace disklab::sequence {
namespace {

using test::seq::is_02_net;
using test::seq::kStructureSeeds;

constexpr int kMaxLog2 = 16;  // prefixes and blocks up to 2^16 points
constexpr uint32_t kCount = 1u << kMaxLog2;

template <class Gen>
std::vector<FixedPoint2> first_points(const Gen& gen, uint32_t count) {
  std::vector<FixedPoint2> points(count);
  for (uint32_t i = 0; i < count; ++i)
    points[i] = gen.fixed_at(i);
  return points;
}

// Every aligned block of 2^m points, m = 0..16, inside the first 2^16 (the prefixes are the
// blocks starting at 0).
void expect_all_blocks_are_nets(const std::vector<FixedPoint2>& points, const std::string& what) {
  int failures = 0;
  for (int m = 0; m <= kMaxLog2; ++m)
    for (std::size_t start = 0; start + (std::size_t{1} << m) <= points.size();
         start += std::size_t{1} << m) {
      std::string why;
      if (!is_02_net(points, start, m, &why)) {
        ADD_FAILURE() << what << ": not a (0," << m << ",2)-net: " << why;
        if (++failures > 5) return;
      }
    }
}

TEST(Net, UnrandomizedSobolBlocksAreNets) {
  struct Plain {
    FixedPoint2 fixed_at(uint32_t i) const { return {sobol_dim0(i), sobol_dim1(i)}; }
  };
  expect_all_blocks_are_nets(first_points(Plain{}, kCount), "sobol (no randomization)");
}

TEST(Net, SobolFirstPointsMatchTheKnownSequence) {
  // Sobol' (0,2) in index (not Gray-code) order: x = van der Corput, y from Pascal's matrix.
  const double expected[8][2] = {{0, 0},         {0.5, 0.5},     {0.25, 0.75},   {0.75, 0.25},
                                 {0.125, 0.625}, {0.625, 0.125}, {0.375, 0.375}, {0.875, 0.875}};
  for (uint32_t i = 0; i < 8; ++i) {
    EXPECT_EQ(to_unit(sobol_dim0(i)), expected[i][0]) << "index " << i;
    EXPECT_EQ(to_unit(sobol_dim1(i)), expected[i][1]) << "index " << i;
  }
  // The byte tables agree with the direct column sum on a spread of indices.
  for (uint32_t i : {0x12345678u, 0xffffffffu, 0x80000001u, 65535u}) {
    uint32_t direct = 0;
    for (int k = 0; k < 32; ++k)
      if (i & (1u << k)) direct ^= sobol_dim1_column(k);
    EXPECT_EQ(sobol_dim1(i), direct) << "index " << i;
    EXPECT_EQ(sobol_dim1_reversed(i), reverse_bits(direct)) << "index " << i;
  }
}

TEST(Net, XorScrambledSobolKeepsNets) {
  for (uint64_t seed : kStructureSeeds)
    expect_all_blocks_are_nets(first_points(SobolXor(seed), kCount),
                               "sobol-xor seed " + std::to_string(seed));
}

TEST(Net, OwenScrambledSobolKeepsNets) {
  for (uint64_t seed : kStructureSeeds)
    expect_all_blocks_are_nets(first_points(SobolOwen(seed), kCount),
                               "sobol-owen seed " + std::to_string(seed));
}

// pmj02bn's stratum search (Christensen et al. 2018) guarantees the power-of-two prefixes; the
// second half of each prefix, [2^(m-1), 2^m), is then a (0,m-1,2)-net too (in every elementary
// interval of area 2^-(m-1) the first half left exactly one of two sub-intervals free). Smaller
// aligned blocks are not constrained by the 2018 algorithm (see tabulated.h), so they are not
// tested for it.
void expect_prefixes_and_halves_are_nets(const std::vector<FixedPoint2>& points, int max_log2,
                                         const std::string& what) {
  for (int m = 0; m <= max_log2; ++m) {
    std::string why;
    EXPECT_TRUE(is_02_net(points, 0, m, &why)) << what << ": prefix 2^" << m << ": " << why;
    if (m >= 1) {
      EXPECT_TRUE(is_02_net(points, std::size_t{1} << (m - 1), m - 1, &why))
          << what << ": second half of prefix 2^" << m << ": " << why;
    }
  }
}

// pmj's sub-square rule (Christensen et al. 2018, Sec. 3): the first k 4^n points, k = 1..4, put
// k points in every square of side 2^-n, in distinct sub-squares of side 2^-(n+1), and the two
// points at k = 2 in diagonally opposite ones. Checked for every n with 4^(n+1) <= points.size().
void expect_sub_square_rule(const std::vector<FixedPoint2>& points, const std::string& what) {
  int failures = 0;
  for (int n = 0; (std::size_t{4} << (2 * n)) <= points.size(); ++n) {
    const std::size_t squares = std::size_t{1} << (2 * n);
    for (uint32_t k = 1; k <= 4; ++k) {
      // Per square: a bit mask of the occupied sub-squares (bit 2 sx + sy) and the point count.
      std::vector<uint8_t> mask(squares, 0), count(squares, 0);
      for (std::size_t j = 0; j < k * squares; ++j) {
        const uint64_t cx = points[j].x >> (31 - n), cy = points[j].y >> (31 - n);  // n+1 digits
        const std::size_t sq = ((cx >> 1u) << n) | (cy >> 1u);
        mask[sq] |= static_cast<uint8_t>(1u << (2 * (cx & 1u) + (cy & 1u)));
        ++count[sq];
      }
      for (std::size_t sq = 0; sq < squares && failures <= 5; ++sq) {
        const bool distinct = count[sq] == k && std::popcount(mask[sq]) == static_cast<int>(k);
        const bool diagonal = k != 2 || mask[sq] == 0b1001 || mask[sq] == 0b0110;
        if (!distinct || !diagonal) {
          ADD_FAILURE() << what << ": first " << k << " x 4^" << n << " points: square " << sq
                        << " holds " << int(count[sq]) << " points, sub-square mask "
                        << int(mask[sq]);
          ++failures;
        }
      }
    }
  }
}

TEST(Net, Pmj02IsAProgressiveNet) {
  // The xor construction (Helmer et al. 2021) makes every aligned block a net, as Sobol' has.
  for (uint64_t seed : kStructureSeeds) {
    const Pmj02 gen(seed, kCount);
    expect_all_blocks_are_nets(first_points(gen, kCount), "pmj02 seed " + std::to_string(seed));
  }
}

TEST(Net, Pmj02FollowsTheSubSquareRule) {
  for (uint64_t seed : kStructureSeeds)
    expect_sub_square_rule(first_points(Pmj02(seed, kCount), kCount),
                           "pmj02 seed " + std::to_string(seed));
}

// pmj02bn (the 2018 stratum search with best candidates): prefixes and their halves are nets, the
// sub-square rule held for every candidate of these seeds, and so it holds for the points.
TEST(Net, Pmj02BlueNoiseIsAProgressiveNet) {
  for (uint64_t seed : {uint64_t{3}, uint64_t{77}}) {
    const std::string what = "pmj02bn seed " + std::to_string(seed);
    const Pmj02BlueNoise gen(seed, kCount);
    const std::vector<FixedPoint2> points = first_points(gen, kCount);
    expect_prefixes_and_halves_are_nets(points, kMaxLog2, what);
    EXPECT_EQ(gen.rule_fallbacks(), 0u) << what;
    expect_sub_square_rule(points, what);
  }
}

TEST(Net, Pmj02BlocksPastCapacityAreNets) {
  // Past the table, blocks are xor-scrambled copies: each block of C points is still a net.
  const uint32_t capacity = 1u << 10;
  const Pmj02 gen(5, capacity);
  std::vector<FixedPoint2> points(4 * capacity);
  for (uint32_t i = 0; i < points.size(); ++i)
    points[i] = gen.fixed_at(i);
  for (std::size_t start = 0; start < points.size(); start += capacity) {
    std::string why;
    EXPECT_TRUE(is_02_net(points, start, 10, &why)) << why;
  }
  EXPECT_FALSE(points[capacity] == points[0]) << "block 1 must not repeat block 0";
}

TEST(Net, RotationBreaksTheNetProperty) {
  // A rotation shifts the elementary intervals' grid: the 1D shapes (2^m x 1, 1 x 2^m) stay
  // stratified (equally spaced coordinates stay equally spaced mod 1), the mixed ones do not,
  // unless the offset happens to be aligned with the grid. Among 2^m-point prefixes, m = 2..16,
  // a random offset keeps the net property only by a coincidence of probability about 2^-m per
  // shape, so for each seed we expect the property broken for every m >= 4.
  constexpr int kFirstBrokenLog2 = 4;
  for (uint64_t seed : kStructureSeeds) {
    const SobolRotated gen(seed);
    const std::vector<FixedPoint2> points = first_points(gen, kCount);
    for (int m = kFirstBrokenLog2; m <= kMaxLog2; ++m)
      EXPECT_FALSE(is_02_net(points, 0, m, nullptr))
          << "sobol-rotated seed " << seed << " (offsets " << gen.offset_x() << ", "
          << gen.offset_y() << "): prefix 2^" << m << " is still a net";
    // ...yet the rotated points stratify the rotated grid exactly: subtracting the offset mod 1
    // gives back the Sobol' net (the failure above is the rotation, nothing else).
    std::vector<FixedPoint2> unrotated(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      unrotated[i] = {points[i].x - gen.offset_x(), points[i].y - gen.offset_y()};
    std::string why;
    EXPECT_TRUE(is_02_net(unrotated, 0, kMaxLog2, &why)) << why;
  }
}

}  // namespace
}  // namespace disklab::sequence
