#pragma once
// The Sobol' (0,2)-sequence (Sobol' 1967): its first two dimensions, van der Corput in base 2 and
// Sobol's second dimension, whose generator matrix is Pascal's triangle mod 2. Every aligned
// block of 2^m consecutive points (in particular every power-of-two prefix) is a (0,m,2)-net:
// each elementary interval [a 2^-k, (a+1) 2^-k) x [b 2^-(m-k), (b+1) 2^-(m-k)) holds one point.
//
// Randomizations (Christensen 2018, Sec. 2): Cranley-Patterson rotation (breaks the net property:
// the rotated points stratify a shifted grid only), Kollig-Keller xor scrambling and Owen
// scrambling (both keep it). Points are computed in 32-bit fixed point, randomized exactly, then
// scaled by 2^-32, so they lie in [0, 1 - 2^-32].
#include <array>
#include <cstdint>

#include "disklab/sequence/scramble.h"
#include "disklab/types.h"

namespace disklab::sequence {

// Column k of Sobol's second dimension: primitive polynomial x + 1 gives the direction-number
// recurrence V_k = V_{k-1} xor (V_{k-1} >> 1), V_0 = 2^31 (Sobol' 1967; Joe and Kuo 2008 with
// s = 1, m_1 = 1). The resulting matrix is Pascal's triangle mod 2.
constexpr uint32_t sobol_dim1_column(int k) {
  uint32_t v = 0x80000000u;
  for (int j = 0; j < k; ++j)
    v ^= v >> 1u;
  return v;
}

namespace detail {
// Per byte of the index: xor of the generator-matrix columns selected by that byte, so a point
// costs four lookups instead of a 32-step loop. dim1[b][byte] covers index bits 8b .. 8b+7.
struct SobolTables {
  std::array<std::array<uint32_t, 256>, 4> dim1{};
  std::array<std::array<uint32_t, 256>, 4> dim1_reversed{};  // bit-reversed, for Owen scrambling
};
constexpr SobolTables make_sobol_tables() {
  SobolTables t;
  for (int b = 0; b < 4; ++b)
    for (uint32_t byte = 0; byte < 256; ++byte) {
      uint32_t v = 0;
      for (int j = 0; j < 8; ++j)
        if (byte & (1u << j)) v ^= sobol_dim1_column(8 * b + j);
      t.dim1[b][byte] = v;
      t.dim1_reversed[b][byte] = reverse_bits(v);
    }
  return t;
}
inline constexpr SobolTables kSobolTables = make_sobol_tables();
}  // namespace detail

// Unrandomized Sobol' (0,2) coordinates of `index` as 32-bit fractions.
inline uint32_t sobol_dim0(uint32_t index) {
  return reverse_bits(index);
}
inline uint32_t sobol_dim1(uint32_t index) {
  const auto& t = detail::kSobolTables.dim1;
  return t[0][index & 255u] ^ t[1][(index >> 8u) & 255u] ^ t[2][(index >> 16u) & 255u] ^
         t[3][index >> 24u];
}
// reverse_bits(sobol_dim1(index)), straight from tables (saves a reversal before Owen hashing).
inline uint32_t sobol_dim1_reversed(uint32_t index) {
  const auto& t = detail::kSobolTables.dim1_reversed;
  return t[0][index & 255u] ^ t[1][(index >> 8u) & 255u] ^ t[2][(index >> 16u) & 255u] ^
         t[3][index >> 24u];
}

// Cranley-Patterson rotated Sobol' (0,2): one random offset per dimension.
class SobolRotated {
 public:
  explicit SobolRotated(uint64_t seed)
      : offset_x_(static_cast<uint32_t>(derive_seed(seed, 0x50b1))),
        offset_y_(static_cast<uint32_t>(derive_seed(seed, 0x50b2))) {}
  FixedPoint2 fixed_at(uint32_t index) const {
    return {rotate(sobol_dim0(index), offset_x_), rotate(sobol_dim1(index), offset_y_)};
  }
  Point2 at(uint32_t index) const { return to_point(fixed_at(index)); }
  uint32_t offset_x() const { return offset_x_; }
  uint32_t offset_y() const { return offset_y_; }

 private:
  uint32_t offset_x_, offset_y_;
};

// Kollig-Keller xor-scrambled Sobol' (0,2): one random 32-bit mask per dimension.
class SobolXor {
 public:
  explicit SobolXor(uint64_t seed)
      : mask_x_(static_cast<uint32_t>(derive_seed(seed, 0x50c1))),
        mask_y_(static_cast<uint32_t>(derive_seed(seed, 0x50c2))) {}
  FixedPoint2 fixed_at(uint32_t index) const {
    return {xor_scramble(sobol_dim0(index), mask_x_), xor_scramble(sobol_dim1(index), mask_y_)};
  }
  Point2 at(uint32_t index) const { return to_point(fixed_at(index)); }

 private:
  uint32_t mask_x_, mask_y_;
};

// Owen-scrambled Sobol' (0,2): independent nested uniform scrambles of the two dimensions
// (Owen 1997), hash-based (see owen_hash_reversed). Bit-reversed inputs come for free:
// reverse(van der Corput(i)) = i.
class SobolOwen {
 public:
  explicit SobolOwen(uint64_t seed)
      : key_x_(OwenKey::from_seed(derive_seed(seed, 0x50d1))),
        key_y_(OwenKey::from_seed(derive_seed(seed, 0x50d2))) {}
  FixedPoint2 fixed_at(uint32_t index) const {
    FixedPoint2 p{owen_hash_reversed(index, key_x_),
                  owen_hash_reversed(sobol_dim1_reversed(index), key_y_)};
    reverse_bits_pair(p.x, p.y);
    return p;
  }
  Point2 at(uint32_t index) const { return to_point(fixed_at(index)); }

 private:
  OwenKey key_x_, key_y_;
};

}  // namespace disklab::sequence
