// The hash-based Owen scramble (scramble.h): the paired bit reversal, exact nested structure
// (digit t of the output depends only on digits 1..t of the input, and digit t always follows
// digit t's flip), an avalanche test (an earlier digit flips each later digit half of the time) and
// bucket tests (over seeds, a fixed input lands uniformly; two inputs sharing a prefix get
// independent tails).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common.h"
#include "disklab/sequence/random.h"
#include "disklab/sequence/scramble.h"
#include "support/stats.h"

namespace disklab::sequence {
namespace {

using test::seq::kAvalancheTolerance;
using test::seq::kAvalancheTrials;

// Digit t (1 = most significant) of a 32-bit fraction.
uint32_t digit(uint32_t v, int t) {
  return (v >> (32 - t)) & 1u;
}

TEST(Owen, NestedStructureIsExact) {
  Pcg32 rng(2024);
  for (int trial = 0; trial < 20000; ++trial) {
    const uint32_t v = rng.next_u32();
    const OwenKey seed = OwenKey::from_seed((uint64_t{rng.next_u32()} << 32) | rng.next_u32());
    const uint32_t out = owen_scramble(v, seed);
    const int t = 1 + static_cast<int>(rng.next_u32() % 32);
    const uint32_t flipped = owen_scramble(v ^ (1u << (32 - t)), seed);
    const uint32_t diff = out ^ flipped;
    // Digits before t unchanged, digit t flipped.
    ASSERT_EQ(diff >> (32 - t), 1u) << "v=" << v << " trial=" << trial << " flipped digit " << t
                                    << ": outputs " << out << " and " << flipped;
  }
}

// SobolOwen reverses both coordinates in one 64-bit word (reverse_bits_pair): each must come out
// as its own 32-bit reversal, in its own place.
TEST(Owen, PairReversalIsTwoReversals) {
  Pcg32 rng(77);
  for (int trial = 0; trial < 100000; ++trial) {
    const uint32_t x0 = trial < 4 ? (trial & 1 ? ~0u : 0u) : rng.next_u32();
    const uint32_t y0 = trial < 4 ? (trial & 2 ? ~0u : 1u) : rng.next_u32();
    uint32_t x = x0, y = y0;
    reverse_bits_pair(x, y);
    ASSERT_EQ(x, reverse_bits(x0)) << "x=" << x0 << " y=" << y0;
    ASSERT_EQ(y, reverse_bits(y0)) << "x=" << x0 << " y=" << y0;
  }
}

TEST(Owen, AvalancheLaterDigitsFlipHalfTheTime) {
  // flips[t][u]: how often flipping input digit t flips output digit u > t, over random inputs
  // and seeds. Every later digit must flip with probability 1/2 (a nested uniform scramble draws
  // an independent permutation for each prefix). Digits 1..24 are tested: beyond that the 32-bit
  // truncation leaves too few later digits to matter.
  constexpr int kDigits = 24;
  std::vector<std::vector<int>> flips(kDigits + 1, std::vector<int>(33, 0));
  Pcg32 rng(7);
  for (int trial = 0; trial < kAvalancheTrials; ++trial) {
    const uint32_t v = rng.next_u32();
    const OwenKey seed = OwenKey::from_seed((uint64_t{rng.next_u32()} << 32) | rng.next_u32());
    const uint32_t out = owen_scramble(v, seed);
    for (int t = 1; t <= kDigits; ++t) {
      const uint32_t diff = out ^ owen_scramble(v ^ (1u << (32 - t)), seed);
      for (int u = t + 1; u <= 32; ++u)
        flips[t][u] += static_cast<int>(digit(diff, u));
    }
  }
  double worst = 0.0;
  for (int t = 1; t <= kDigits; ++t)
    for (int u = t + 1; u <= 32; ++u) {
      const double p = static_cast<double>(flips[t][u]) / kAvalancheTrials;
      worst = std::max(worst, std::abs(p - 0.5));
      EXPECT_NEAR(p, 0.5, kAvalancheTolerance)
          << "flip of input digit " << t << " flips output digit " << u;
    }
  RecordProperty("worst_avalanche_bias", std::to_string(worst));
}

TEST(Owen, FixedInputLandsUniformlyOverSeeds) {
  // Bucket test: the first 8 output digits of a fixed input, over seeds, are uniform on 256
  // buckets (so is any single digit, in particular the first: a scramble is a random flip of it).
  const double alpha = test::sidak_alpha(test::seq::kFamilyAlpha, 4);
  for (uint32_t v : {0u, 0xffffffffu, 0x80000000u, 0x12345678u}) {
    constexpr int kSeeds = 256 * 40;
    std::vector<double> observed(256, 0.0), expected(256, kSeeds / 256.0);
    for (int s = 0; s < kSeeds; ++s)
      observed[owen_scramble(v, OwenKey::from_seed(derive_seed(99, static_cast<uint64_t>(s)))) >>
               24] += 1.0;
    const test::ChiSquareResult r = test::chi_square(observed, expected);
    EXPECT_GT(r.p_value, alpha) << "input " << v << ": " << r.summary();
  }
}

TEST(Owen, TailsAfterTheFirstDifferenceAreIndependent) {
  // Two inputs that agree on digits 1..p and differ at p+1 have independent permutations below:
  // the pair (digits p+2..p+4 of each output) is uniform on 64 buckets over seeds.
  const int prefixes[] = {0, 3, 10, 20};
  const double alpha = test::sidak_alpha(test::seq::kFamilyAlpha, std::size(prefixes));
  Pcg32 rng(11);
  for (int p : prefixes) {
    constexpr int kTrials = 64 * 60;
    std::vector<double> observed(64, 0.0), expected(64, kTrials / 64.0);
    for (int s = 0; s < kTrials; ++s) {
      const uint32_t v = rng.next_u32();
      const uint32_t w = v ^ (1u << (31 - p));  // differs first at digit p+1
      const OwenKey seed = OwenKey::from_seed((uint64_t{rng.next_u32()} << 32) | rng.next_u32());
      const uint32_t a = (owen_scramble(v, seed) << (p + 1)) >> 29;
      const uint32_t b = (owen_scramble(w, seed) << (p + 1)) >> 29;
      observed[a * 8 + b] += 1.0;
    }
    const test::ChiSquareResult r = test::chi_square(observed, expected);
    EXPECT_GT(r.p_value, alpha) << "shared prefix of " << p << " digits: " << r.summary();
  }
}

}  // namespace
}  // namespace disklab::sequence
