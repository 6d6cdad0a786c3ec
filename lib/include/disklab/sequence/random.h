#pragma once
// Uniform random points from PCG32 (O'Neill 2014, XSH-RR output on a 64-bit LCG).
// Random access: at(i) jumps the generator to draw 2i in O(log i) (Brown 1994, arbitrary-stride
// LCG jump), so the sequence has the same deterministic, progressive `at` contract as the others.
#include <cstdint>

#include "disklab/types.h"

namespace disklab::sequence {

class Pcg32 {
 public:
  static constexpr uint64_t kMultiplier = 6364136223846793005ULL;

  explicit Pcg32(uint64_t seed, uint64_t stream = 0xda3e39cb94b95bdbULL)
      : state_(0), inc_((stream << 1u) | 1u) {
    next_u32();
    state_ += seed;
    next_u32();
  }

  uint32_t next_u32() {
    const uint64_t old = state_;
    state_ = old * kMultiplier + inc_;
    const auto xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  // Uniform in [0,1): a 32-bit integer times 2^-32 is exact and at most 1 - 2^-32.
  double next_double() { return next_u32() * 0x1p-32; }

  // Moves the generator `delta` draws ahead in O(log delta) steps.
  void advance(uint64_t delta) {
    uint64_t acc_mult = 1, acc_plus = 0, cur_mult = kMultiplier, cur_plus = inc_;
    while (delta > 0) {
      if (delta & 1u) {
        acc_mult *= cur_mult;
        acc_plus = acc_plus * cur_mult + cur_plus;
      }
      cur_plus = (cur_mult + 1) * cur_plus;
      cur_mult *= cur_mult;
      delta >>= 1u;
    }
    state_ = acc_mult * state_ + acc_plus;
  }

 private:
  uint64_t state_;
  uint64_t inc_;
};

class RandomSequence {
 public:
  explicit RandomSequence(uint64_t seed) : base_(seed) {}
  Point2 at(uint32_t index) const {
    Pcg32 rng = base_;
    rng.advance(2 * static_cast<uint64_t>(index));
    const double u = rng.next_double();
    const double v = rng.next_double();
    return {u, v};
  }

 private:
  Pcg32 base_;
};

}  // namespace disklab::sequence
