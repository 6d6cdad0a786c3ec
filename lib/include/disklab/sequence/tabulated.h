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

// Progressive multi-jittered (0,2) sequence (Christensen, Kensler and Kilpatrick 2018), built with
// the stochastic construction of Helmer, Christensen and Kensler 2021 ("Stochastic Generation of
// (t, s) Sample Sequences") in O(1) per point. Point i with 2^n <= i < 2^(n+1) copies the top n
// binary digits of x from point i xor 2^n and those of y from point i xor d_n (d_n in
// [2^n, 2^(n+1)): the index whose Sobol' y starts with n zeros), takes the complement of that
// point's digit n+1, and draws the digits below. In Sobol' (0,2) those partners share exactly
// these digits with point i, and the drawn digits sit where a nested uniform (Owen) scrambling
// tree is visited first, so every run is an Owen-scrambled Sobol' sequence: every aligned block
// of 2^m points is a (0,m,2)-net (prefixes, their halves and smaller blocks alike). pmj's
// sub-square rule (Christensen et al. 2018, Sec. 3) follows: at 2 * 4^n points every square of
// side 2^-n holds two points in diagonally opposite sub-squares, at 3 * 4^n three in distinct ones.
//
// pmj02bn (`candidates` > 1): the blue-noise variant of Christensen et al. 2018 (Sec. 6), built
// with their stratum search instead: point i with 2^(M-1) <= i < 2^M goes into an elementary
// interval of area 2^-M left empty by points 0..i-1, for all M+1 shapes, in a sub-square the pmj
// rule allows; `candidates` such positions are drawn as the 2018 search draws them (a uniform
// free x stratum that admits a y stratum, a random descent over the valid y strata, uniform jitter
// in the finest cell) and the one farthest (toroidal distance) from all earlier points is kept.
// So the sets at 2^m points are blue noise, not only their order. Every power-of-two prefix is a
// (0,m,2)-net and so is its second half (it fills the complement of a net); smaller aligned blocks
// are not guaranteed.
class Pmj02 : public TabulatedSequence {
 public:
  static constexpr int kBlueNoiseCandidates = 10;
  explicit Pmj02(uint64_t seed, uint32_t capacity = kDefaultCapacity, int candidates = 1);
  // pmj02bn: how often a candidate had to drop the pmj sub-square rule to find a valid position
  // (diagnostics; 0 for pmj02, whose construction always meets it).
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
