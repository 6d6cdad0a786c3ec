// Halton (bases 2, 3) randomized by rotation and by random digit scrambling (Christensen 2018,
// Sec. 2): aligned blocks of 2^a 3^b points stratify the 2^a x 3^b grid (the scrambled sequence on
// the grid itself, the rotated one on the grid shifted by its offset), and the digit scrambling
// permutes the leading zero digits of short indices too (the classic bug).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common.h"
#include "disklab/sequence/halton.h"
#include "support/stats.h"

namespace disklab::sequence {
namespace {

using test::seq::kStructureSeeds;

uint64_t pow3(int b) {
  uint64_t p = 1;
  for (int i = 0; i < b; ++i)
    p *= 3;
  return p;
}

struct Cell {
  uint32_t cx;
  uint64_t cy;
};

// Whether the 2^a 3^b points start, start+1, ... occupy distinct cells of the 2^a x 3^b grid,
// with cells computed by `cell` from the fixed-point coordinates (exact).
template <class CellOf>
bool stratifies(uint32_t start, int a, int b, CellOf cell, std::string* why) {
  const uint64_t nx = uint64_t{1} << a, ny = pow3(b), count = nx * ny;
  std::vector<uint32_t> owner(count, 0);
  for (uint64_t i = start; i < start + count; ++i) {
    const Cell c = cell(static_cast<uint32_t>(i));
    const uint64_t id = c.cx * ny + c.cy;
    if (owner[id] != 0) {
      *why = "points " + std::to_string(owner[id] - 1) + " and " + std::to_string(i) +
             " share cell (" + std::to_string(c.cx) + ", " + std::to_string(c.cy) + ") of the 2^" +
             std::to_string(a) + " x 3^" + std::to_string(b) + " grid";
      return false;
    }
    owner[id] = static_cast<uint32_t>(i) + 1;
  }
  return true;
}

// (a, b) grids and which aligned blocks to check: the first three and one far out.
constexpr int kGrids[][2] = {{1, 1}, {2, 1}, {1, 2}, {3, 2}, {4, 3}, {6, 4}, {0, 5}, {7, 0}};

uint32_t block_start(int which, uint64_t size) {
  return which < 3 ? static_cast<uint32_t>(which * size)
                   : static_cast<uint32_t>((1000003 / size + 1) * size);
}

TEST(Halton, ScrambledBlocksStratifyTheGrid) {
  for (uint64_t seed : kStructureSeeds) {
    const HaltonScrambled gen(seed);
    for (const auto& g : kGrids)
      for (int which = 0; which < 4; ++which) {
        const int a = g[0], b = g[1];
        const uint64_t size = (uint64_t{1} << a) * pow3(b);
        const uint32_t start = block_start(which, size);
        std::string why;
        const bool ok = stratifies(
            start, a, b,
            [&](uint32_t i) {
              const HaltonFixed p = gen.fixed_at(i);
              return Cell{static_cast<uint32_t>((uint64_t{p.x} << a) >> 32), p.y / pow3(21 - b)};
            },
            &why);
        EXPECT_TRUE(ok) << "halton-scrambled seed " << seed << ", block at " << start << ": "
                        << why;
      }
  }
}

TEST(Halton, RotatedBlocksStratifyTheShiftedGrid) {
  for (uint64_t seed : kStructureSeeds) {
    const HaltonRotated gen(seed);
    for (const auto& g : kGrids)
      for (int which = 0; which < 4; ++which) {
        const int a = g[0], b = g[1];
        const uint64_t size = (uint64_t{1} << a) * pow3(b);
        const uint32_t start = block_start(which, size);
        std::string why;
        const bool ok = stratifies(
            start, a, b,
            [&](uint32_t i) {
              const HaltonFixed p = gen.fixed_at(i);
              // Undo the offset modulo 1 (exact in fixed point), then take the cell.
              const uint32_t x = p.x - gen.offset_x();
              const uint64_t y = (p.y + kHalton3Scale - gen.offset_y()) % kHalton3Scale;
              return Cell{static_cast<uint32_t>((uint64_t{x} << a) >> 32), y / pow3(21 - b)};
            },
            &why);
        EXPECT_TRUE(ok) << "halton-rotated seed " << seed << " (offsets " << gen.offset_x() << ", "
                        << gen.offset_y() << "), block at " << start << ": " << why;
      }
  }
}

TEST(Halton, UnscrambledRadicalInverseIsExact) {
  // Index 5 = 12 in base 3 -> 0.21 in base 3 = 2/3 + 1/9 = 7/9.
  EXPECT_EQ(radical_inverse3_fixed(5), 7 * pow3(19));
  EXPECT_EQ(radical_inverse3_fixed(0), 0u);
  // The largest index has 21 base-3 digits (3^20 < 2^32 < 3^21): nothing is lost.
  uint32_t i = 0xffffffffu;
  uint64_t y = radical_inverse3_fixed(i), back = 0;
  for (int k = 0; k < kHalton3Digits; ++k) {
    back = back * 3 + (y % 3);
    y /= 3;
  }
  EXPECT_EQ(back, i);
}

TEST(Halton, ScramblingPermutesEveryDigitIncludingLeadingZeros) {
  for (uint64_t seed : kStructureSeeds) {
    const HaltonScrambled gen(seed);
    for (uint32_t index : {0u, 1u, 2u, 5u, 80u, 12345u, 0xffffffffu}) {
      const HaltonFixed p = gen.fixed_at(index);
      // y's digit at position k (k = 0 most significant) must be perm_k(index's k-th digit),
      // for all 21 positions, i.e. also where the index has only leading zeros.
      uint64_t y = p.y;
      uint32_t digits[kHalton3Digits];
      for (int k = kHalton3Digits - 1; k >= 0; --k) {
        digits[k] = static_cast<uint32_t>(y % 3);
        y /= 3;
      }
      uint32_t rest = index;
      for (int k = 0; k < kHalton3Digits; ++k) {
        EXPECT_EQ(digits[k], static_cast<uint32_t>(gen.perm_y(k, static_cast<int>(rest % 3))))
            << "seed " << seed << " index " << index << " digit position " << k;
        rest /= 3;
      }
      EXPECT_EQ(p.x, reverse_bits(index) ^ gen.mask_x()) << "seed " << seed << " index " << index;
    }
  }
}

TEST(Halton, FirstPointIsUniformOverSeeds) {
  // Behavioural check of the same fact: index 0 has only zero digits, so with the classic bug
  // (permuting only the index's own digits) point 0 is (0, 0) for every seed. Correct scrambling
  // makes it uniform over seeds: chi-square on the 4 x 9 grid of (first 2 binary digits of x,
  // first 2 ternary digits of y) over kSeeds seeds.
  constexpr int kSeeds = 3600;  // 100 expected per cell
  std::vector<double> observed(36, 0.0), expected(36, kSeeds / 36.0);
  for (int s = 0; s < kSeeds; ++s) {
    const HaltonFixed p = HaltonScrambled(static_cast<uint64_t>(s)).fixed_at(0);
    observed[(p.x >> 30) * 9 + p.y / pow3(19)] += 1.0;
  }
  const test::ChiSquareResult r = test::chi_square(observed, expected);
  EXPECT_GT(r.p_value, test::seq::kFamilyAlpha) << r.summary();
}

}  // namespace
}  // namespace disklab::sequence
