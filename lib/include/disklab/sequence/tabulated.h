#pragma once
// Sequences whose points depend on all earlier points, so they are generated once, in the
// constructor, up to a capacity chosen there: best candidates (Mitchell 1991), pmj02 and pmj02bn
// (Christensen, Kensler and Kilpatrick 2018). at() is then a table lookup: const, allocation-free
// and thread-safe.
//
// Indices past the capacity C keep the at() contract (deterministic, in [0,1)) by reusing the
// table in blocks: index = b C + r gives point r randomized per block b (a xor mask for pmj02,
// which keeps each block a (0, log2 C, 2)-net; a toroidal shift for best candidates, which keeps
// each block's distances). Prefixes longer than C are then only stratified block by block: pick
// the capacity to cover the sample counts you use (the registry uses kDefaultCapacity = 2^16).
#include <cstdint>
#include <vector>

#include "disklab/sequence/scramble.h"
#include "disklab/types.h"

namespace disklab::sequence {

inline constexpr uint32_t kDefaultCapacity = 1u << 16;

class TabulatedSequence {
 public:
  FixedPoint2 fixed_at(uint32_t index) const {
    const uint32_t block = index >> log2_capacity_;
    const FixedPoint2 p = points_[index & (capacity() - 1)];
    if (block == 0) return p;
    const uint64_t h = derive_seed(block_seed_, block);
    const auto hx = static_cast<uint32_t>(h), hy = static_cast<uint32_t>(h >> 32u);
    if (block_xor_) return {p.x ^ hx, p.y ^ hy};
    return {p.x + hx, p.y + hy};
  }
  Point2 at(uint32_t index) const { return to_point(fixed_at(index)); }
  uint32_t capacity() const { return 1u << log2_capacity_; }

 protected:
  // capacity is rounded up to a power of two in [1, 2^24].
  TabulatedSequence(uint64_t seed, uint32_t capacity, bool block_xor);
  std::vector<FixedPoint2> points_;
  int log2_capacity_ = 0;

 private:
  uint64_t block_seed_;
  bool block_xor_;
};

// Mitchell's best-candidate sequence, progressive: point i is the candidate, among `candidates`
// uniform random ones, farthest (toroidal distance) from points 0..i-1. Mitchell used a
// candidate count growing with i; a fixed count keeps generation O(C k) with the spatial grid and
// still pushes the minimum distance well above random's (see best_candidate_test.cpp).
class BestCandidate : public TabulatedSequence {
 public:
  static constexpr int kDefaultCandidates = 32;
  explicit BestCandidate(uint64_t seed, uint32_t capacity = kDefaultCapacity,
                         int candidates = kDefaultCandidates);
};

// Progressive multi-jittered (0,2) sequence (Christensen et al. 2018, Sec. 5). Point i with
// 2^(M-1) <= i < 2^M goes into an elementary interval of area 2^-M left empty by points
// 0..i-1, for all M+1 shapes, so every power-of-two prefix is a (0,m,2)-net, and so is every
// second half [2^(M-1), 2^M) (it fills the complement of a net). Smaller aligned blocks are not
// guaranteed to be nets (unlike Sobol'): see the note in tabulated.cpp. Its sub-square follows
// pmj's rule (Sec. 3): at 2 * 4^n points the new point lies in the sub-square diagonally opposite
// its parent's, then in the two remaining ones; within those constraints the strata are drawn at
// random (a random descent over free x strata, a randomized depth-first search over y strata) and
// the point is jittered uniformly in the finest cell. pmj02bn (`candidates` > 1): the valid
// candidate farthest from the earlier points, as the paper's blue-noise variant.
class Pmj02 : public TabulatedSequence {
 public:
  static constexpr int kBlueNoiseCandidates = 10;
  explicit Pmj02(uint64_t seed, uint32_t capacity = kDefaultCapacity, int candidates = 1);
  // How often the pmj sub-square rule had to be dropped to find a valid point (diagnostics).
  uint32_t rule_fallbacks() const { return rule_fallbacks_; }

 private:
  uint32_t rule_fallbacks_ = 0;
};

class Pmj02BlueNoise : public Pmj02 {
 public:
  explicit Pmj02BlueNoise(uint64_t seed, uint32_t capacity = kDefaultCapacity)
      : Pmj02(seed, capacity, kBlueNoiseCandidates) {}
};

}  // namespace disklab::sequence
