#pragma once
// The Halton sequence in bases 2 and 3 (Halton 1964): x = radical inverse of the index in base 2,
// y = radical inverse in base 3. Every aligned block of 2^a 3^b consecutive indices puts exactly
// one point in every cell of the 2^a x 3^b grid (the index mod 2^a fixes x's first a digits,
// the index mod 3^b fixes y's first b digits, and by the Chinese remainder theorem every pair
// occurs once).
//
// Fixed point: x as a 32-bit fraction (x * 2^32), y as an integer Y over 3^21 (y = Y / 3^21).
// 21 base-3 digits cover every 32-bit index (3^21 > 2^32), so the radical inverse is exact.
// Randomizations (Christensen 2018, Sec. 2):
//  - HaltonRotated: Cranley-Patterson rotation, exact modulo 1 in fixed point (the y offset is a
//    multiple of 3^-21, far below double resolution of the sample positions that matter);
//  - HaltonScrambled: random digit scrambling, an independent random permutation of the digits
//    {0, .., b-1} at each of the 32 (base 2) or 21 (base 3) digit positions. The permutation is
//    applied to every position, including the leading zeros of short indices; skipping those
//    (the classic bug) would leave y(0) = 0 and all early points piled near zero in the low digits.
#include <array>
#include <cstdint>

#include "disklab/sequence/scramble.h"
#include "disklab/types.h"

namespace disklab::sequence {

inline constexpr int kHalton3Digits = 21;
inline constexpr uint64_t kHalton3Scale = 10460353203ULL;  // 3^21

// Base-3 radical inverse of index as an integer over 3^21: digit k (k = 0 least significant of
// the index) lands at weight 3^(20-k).
constexpr uint64_t radical_inverse3_fixed(uint32_t index) {
  uint64_t y = 0, weight = kHalton3Scale;
  for (int k = 0; k < kHalton3Digits; ++k) {
    weight /= 3;
    y += (index % 3u) * weight;
    index /= 3u;
  }
  return y;
}

// The same, four digits at a time: 81^g chunk g of the index holds digits 4g .. 4g+3, and
// kRadical3Chunks[g][c] is their contribution. Six dependent divisions instead of 21 (about 4x
// faster); digit 20 is the only one of chunk 5 (index / 3^20 < 3).
inline constexpr int kHalton3Chunks = 6;
inline constexpr uint32_t kHalton3ChunkBase = 81;  // 3^4
using Halton3ChunkTable = std::array<std::array<uint64_t, kHalton3ChunkBase>, kHalton3Chunks>;
// table[g][c] = sum over the digits d_j of c (j < 4, position k = 4g + j <= 20) of digit(k, d_j),
// where digit(k, d) is what digit d at position k adds to Y.
template <class DigitValue>
constexpr Halton3ChunkTable make_halton3_chunks(DigitValue digit) {
  Halton3ChunkTable t{};
  for (int g = 0; g < kHalton3Chunks; ++g)
    for (uint32_t c = 0; c < kHalton3ChunkBase; ++c) {
      uint64_t sum = 0;
      uint32_t rest = c;
      for (int j = 0; j < 4; ++j) {
        const int k = 4 * g + j;
        if (k < kHalton3Digits) sum += digit(k, rest % 3u);
        rest /= 3u;
      }
      t[g][c] = sum;
    }
  return t;
}
inline constexpr uint64_t halton3_weight(int k) {  // 3^(20-k)
  uint64_t w = 1;
  for (int j = k; j < kHalton3Digits - 1; ++j)
    w *= 3;
  return w;
}
inline constexpr Halton3ChunkTable kRadical3Chunks =
    make_halton3_chunks([](int k, uint32_t d) { return d * halton3_weight(k); });
inline uint64_t radical_inverse3_chunked(uint32_t index, const Halton3ChunkTable& t) {
  uint64_t y = 0;
  for (int g = 0; g < kHalton3Chunks; ++g) {
    y += t[g][index % kHalton3ChunkBase];
    index /= kHalton3ChunkBase;
  }
  return y;
}

// y = Y / 3^21 with Y < 3^21: the quotient is at most 1 - 3^-21 (about 1 - 1e-10), so rounding
// the double product can never reach 1.0.
constexpr double halton3_to_unit(uint64_t y) {
  return static_cast<double>(y) * (1.0 / static_cast<double>(kHalton3Scale));
}

struct HaltonFixed {
  uint32_t x = 0;  // x * 2^32
  uint64_t y = 0;  // y * 3^21
};
inline Point2 to_point(HaltonFixed p) {
  return {to_unit(p.x), halton3_to_unit(p.y)};
}

class HaltonRotated {
 public:
  explicit HaltonRotated(uint64_t seed)
      : offset_x_(static_cast<uint32_t>(derive_seed(seed, 0x4a11))),
        offset_y_(derive_seed(seed, 0x4a12) % kHalton3Scale) {}
  HaltonFixed fixed_at(uint32_t index) const {
    uint64_t y = radical_inverse3_chunked(index, kRadical3Chunks) + offset_y_;
    if (y >= kHalton3Scale) y -= kHalton3Scale;
    return {rotate(reverse_bits(index), offset_x_), y};
  }
  Point2 at(uint32_t index) const { return to_point(fixed_at(index)); }
  uint32_t offset_x() const { return offset_x_; }
  uint64_t offset_y() const { return offset_y_; }

 private:
  uint32_t offset_x_;
  uint64_t offset_y_;
};

class HaltonScrambled {
 public:
  explicit HaltonScrambled(uint64_t seed)
      // A permutation of {0, 1} per binary digit is "flip or not": a xor with a random mask over
      // all 32 positions (leading zeros included).
      : mask_x_(static_cast<uint32_t>(derive_seed(seed, 0x4b11))) {
    // The six permutations of {0, 1, 2}, one drawn uniformly per base-3 digit position.
    static constexpr std::array<std::array<uint8_t, 3>, 6> kPerms{
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    for (int k = 0; k < kHalton3Digits; ++k)
      perm_y_[k] = kPerms[derive_seed(seed, 0x4b20 + k) % 6];
    // Digits are permuted independently, so precompute per-position contributions:
    // table_[k][d] = perm_k(d) * 3^(20-k).
    uint64_t weight = kHalton3Scale;
    for (int k = 0; k < kHalton3Digits; ++k) {
      weight /= 3;
      for (int d = 0; d < 3; ++d)
        table_[k][d] = perm_y_[k][d] * weight;
    }
    chunks_ = make_halton3_chunks([this](int k, uint32_t d) { return table_[k][d]; });
  }
  HaltonFixed fixed_at(uint32_t index) const {
    // All 21 positions (chunks cover every one), so leading zeros of the index are permuted too.
    const uint64_t y = radical_inverse3_chunked(index, chunks_);
    return {xor_scramble(reverse_bits(index), mask_x_), y};
  }
  Point2 at(uint32_t index) const { return to_point(fixed_at(index)); }
  // perm(k, d): the digit that replaces digit d at position k (k = 0: the most significant
  // base-3 digit of y, i.e. the least significant digit of the index).
  int perm_y(int k, int d) const { return perm_y_[k][d]; }
  uint32_t mask_x() const { return mask_x_; }

 private:
  uint32_t mask_x_;
  std::array<std::array<uint8_t, 3>, kHalton3Digits> perm_y_{};
  std::array<std::array<uint64_t, 3>, kHalton3Digits> table_{};
  Halton3ChunkTable chunks_{};  // table_ summed four digits at a time
};

}  // namespace disklab::sequence
