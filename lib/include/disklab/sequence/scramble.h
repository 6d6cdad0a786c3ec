#pragma once
// Randomizations shared by the low-discrepancy sequences (Christensen 2018, Sec. 2): seed
// derivation, Cranley-Patterson rotation, xor scrambling (Kollig and Keller 2002) and hash-based
// nested uniform (Owen 1997) scrambling of 32-bit binary fractions.
//
// All work on 32-bit fixed-point fractions v (value v * 2^-32), so every randomization is exact
// integer arithmetic: a rotation is an addition mod 2^32 (= mod 1), a scramble a bijection of
// [0, 2^32). Converting with to_unit() gives at most 1 - 2^-32: never 1.0.
#include <cstdint>

#include "disklab/types.h"

namespace disklab::sequence {

// splitmix64's finalizer (Steele, Lea, Flood 2014): a bijective 64-bit mixer; used to derive
// independent-looking sub-seeds from one user seed, so nearby seeds give decorrelated instances.
constexpr uint64_t mix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30u)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27u)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31u);
}

// Sub-seed number `purpose` of `seed` (dimension, rotation vs. scramble, ...).
constexpr uint64_t derive_seed(uint64_t seed, uint64_t purpose) {
  return mix64(seed ^ mix64(purpose + 0x5851f42d4c957f2dULL));
}

constexpr uint32_t reverse_bits(uint32_t v) {
  v = ((v >> 1u) & 0x55555555u) | ((v & 0x55555555u) << 1u);
  v = ((v >> 2u) & 0x33333333u) | ((v & 0x33333333u) << 2u);
  v = ((v >> 4u) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4u);
  v = ((v >> 8u) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8u);
  return (v >> 16u) | (v << 16u);
}

// reverse_bits of x and of y in one 64-bit reversal: reversing the word y 2^32 + x gives
// reverse_bits(x) 2^32 + reverse_bits(y): half the operations of two 32-bit reversals.
constexpr void reverse_bits_pair(uint32_t& x, uint32_t& y) {
  uint64_t v = (uint64_t{y} << 32u) | x;
  v = ((v >> 1u) & 0x5555555555555555ull) | ((v & 0x5555555555555555ull) << 1u);
  v = ((v >> 2u) & 0x3333333333333333ull) | ((v & 0x3333333333333333ull) << 2u);
  v = ((v >> 4u) & 0x0f0f0f0f0f0f0f0full) | ((v & 0x0f0f0f0f0f0f0f0full) << 4u);
  v = ((v >> 8u) & 0x00ff00ff00ff00ffull) | ((v & 0x00ff00ff00ff00ffull) << 8u);
  v = ((v >> 16u) & 0x0000ffff0000ffffull) | ((v & 0x0000ffff0000ffffull) << 16u);
  v = (v >> 32u) | (v << 32u);
  x = static_cast<uint32_t>(v >> 32u);
  y = static_cast<uint32_t>(v);
}

// v * 2^-32: exact in double, in [0, 1 - 2^-32].
constexpr double to_unit(uint32_t v) {
  return v * 0x1p-32;
}

// A point as two 32-bit fractions: what the binary sequences compute, exact for net tests.
struct FixedPoint2 {
  uint32_t x = 0;
  uint32_t y = 0;
  friend bool operator==(const FixedPoint2&, const FixedPoint2&) = default;
};
inline Point2 to_point(FixedPoint2 p) {
  return {to_unit(p.x), to_unit(p.y)};
}

// Cranley and Patterson (1976) rotation by offset * 2^-32, mod 1 (unsigned wrap-around).
constexpr uint32_t rotate(uint32_t v, uint32_t offset) {
  return v + offset;
}

// Kollig and Keller (2002) random digit flipping: a xor keeps every elementary interval's
// occupancy because it maps each dyadic interval onto a dyadic interval of the same size.
constexpr uint32_t xor_scramble(uint32_t v, uint32_t mask) {
  return v ^ mask;
}

// Nested uniform scrambling on bit-reversed input: with r = reverse_bits(v), bit j of r is the
// (j+1)-th binary digit of v. Every operation below changes bit j of r by a function of bits
// < j only (adding a constant: carries move upwards; x * even: bit j depends on lower bits;
// x * odd: bit j is x_j xor a function of lower bits). So digit j+1 of v is flipped by a
// function of the digits before it and of the key: Owen's nested permutation, with the flip
// decisions drawn from a hash instead of independent coins (Laine and Karras 2011 introduced this
// structure). Fixed multipliers alone flip a digit by a *fixed* linear function of the lower
// digits, the same for every seed; seed-dependent odd multipliers and addends make those
// decisions random per seed, and three rounds mix the low digits enough to pass the avalanche and
// bucket tests in property_tests/sequence/owen_test.cpp (a first version with fixed multipliers
// and a single seeded one failed them: digit 3 flipped digit 5 in 59% of trials). Constants ours.
struct OwenKey {
  uint32_t add[3];
  uint32_t mul[3];  // odd
  static constexpr OwenKey from_seed(uint64_t seed) {
    OwenKey key{};
    for (int round = 0; round < 3; ++round) {
      const uint64_t h = derive_seed(seed, 0x0e11 + round);
      key.add[round] = static_cast<uint32_t>(h);
      key.mul[round] = static_cast<uint32_t>(h >> 32u) | 1u;
    }
    return key;
  }
};

constexpr uint32_t owen_hash_reversed(uint32_t r, const OwenKey& key) {
  r += key.add[0];
  r *= key.mul[0];
  r ^= r * 0x6c8e9cf4u;
  r += key.add[1];
  r *= key.mul[1];
  r ^= r * 0xb5d3a6a2u;
  r += key.add[2];
  r *= key.mul[2];
  return r;
}

// Owen-scrambled fraction v: digit k of the result is digit k of v flipped by a hash of the
// first k-1 digits of v. Bijective on [0, 2^32); every dyadic interval maps to one of its size.
constexpr uint32_t owen_scramble(uint32_t v, const OwenKey& key) {
  return reverse_bits(owen_hash_reversed(reverse_bits(v), key));
}

}  // namespace disklab::sequence
