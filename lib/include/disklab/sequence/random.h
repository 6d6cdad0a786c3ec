#pragma once
// Uniform random points from PCG32 (O'Neill 2014, XSH-RR output on a 64-bit LCG).
// Random access: at(i) jumps the generator to draw 2i (Brown 1994, arbitrary-stride LCG jump),
// so the sequence has the same deterministic, progressive `at` contract as the others.
#include <array>
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

  // Applies state -> mult * state + inc * plus: a jump precomputed for increment 1 (see
  // detail::LcgJump), the same as advance(d) for that jump's d.
  void jump(uint64_t mult, uint64_t plus) { state_ = mult * state_ + inc_ * plus; }

 private:
  uint64_t state_;
  uint64_t inc_;
};

namespace detail {
// A jump of the LCG by d draws, for any increment inc: state -> mult * state + inc * plus, with
// mult = a^d and plus = sum_{j<d} a^j (mod 2^64). Pcg32::advance computes the same map bit by
// bit, with inc folded in (its plus term is linear in inc).
struct LcgJump {
  uint64_t mult = 1;
  uint64_t plus = 0;
};
// `first`, then `then`.
constexpr LcgJump compose(LcgJump first, LcgJump then) {
  return {then.mult * first.mult, then.mult * first.plus + then.plus};
}
// jumps[k][b]: by 2 b 256^k draws (b points in byte k of the index). Jumps are powers of one
// map, so they commute and at(i) composes one entry per index byte: four steps instead of a
// loop over the 33 bits of 2i (8x faster; 16 KB shared by every instance).
struct PcgPointJumps {
  std::array<std::array<LcgJump, 256>, 4> jumps{};
};
constexpr PcgPointJumps make_pcg_point_jumps() {
  PcgPointJumps t;
  LcgJump unit{Pcg32::kMultiplier * Pcg32::kMultiplier, Pcg32::kMultiplier + 1};  // two draws
  for (int k = 0; k < 4; ++k) {
    for (int b = 1; b < 256; ++b)
      t.jumps[k][b] = compose(t.jumps[k][b - 1], unit);
    unit = compose(t.jumps[k][255], unit);  // 256 units of this byte: one of the next
  }
  return t;
}
inline constexpr PcgPointJumps kPcgPointJumps = make_pcg_point_jumps();
}  // namespace detail

class RandomSequence {
 public:
  explicit RandomSequence(uint64_t seed) : base_(seed) {}
  Point2 at(uint32_t index) const {
    const auto& t = detail::kPcgPointJumps.jumps;
    detail::LcgJump j = t[0][index & 255u];
    j = detail::compose(j, t[1][(index >> 8u) & 255u]);
    j = detail::compose(j, t[2][(index >> 16u) & 255u]);
    j = detail::compose(j, t[3][index >> 24u]);
    Pcg32 rng = base_;
    rng.jump(j.mult, j.plus);
    const double u = rng.next_double();
    const double v = rng.next_double();
    return {u, v};
  }

 private:
  Pcg32 base_;
};

}  // namespace disklab::sequence
