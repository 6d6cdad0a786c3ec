#pragma once
// The common interface of the 2D sample sequences (Christensen 2018, Sec. 2).
//
// Contract, for every generator:
//  - an instance is built from a 64-bit seed (its randomization); same seed -> same points;
//  - at(index) is deterministic, progressive (every prefix is a good set) and lies in [0,1)^2,
//    never 1.0;
//  - at() is const and thread-safe: any one-time set-up happens in the constructor.
// Concrete generators are usable directly (no virtual call) in hot loops; the type-erased
// Sequence below is what the CLI and the experiments use to pick a generator by name.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "disklab/types.h"

namespace disklab::sequence {

class Sequence {
 public:
  virtual ~Sequence() = default;
  virtual Point2 at(uint32_t index) const = 0;
  // out[i] = at(first + i) for every i: one virtual call for a whole block of points.
  virtual void fill(uint32_t first, std::span<Point2> out) const {
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i] = at(first + static_cast<uint32_t>(i));
  }
  // The CLI name of the generator, e.g. "sobol-owen".
  virtual std::string_view name() const = 0;
};

// Wraps a concrete generator (anything with `Point2 at(uint32_t) const`).
template <class Gen>
class SequenceAdapter final : public Sequence {
 public:
  SequenceAdapter(std::string name, Gen gen) : name_(std::move(name)), gen_(std::move(gen)) {}
  Point2 at(uint32_t index) const override { return gen_.at(index); }
  void fill(uint32_t first, std::span<Point2> out) const override {
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i] = gen_.at(first + static_cast<uint32_t>(i));
  }
  std::string_view name() const override { return name_; }
  const Gen& generator() const { return gen_; }

 private:
  std::string name_;
  Gen gen_;
};

// Names accepted by make_sequence, in the memo's order.
std::vector<std::string> sequence_names();

// Builds the generator called `name` randomized by `seed`.
// Throws std::invalid_argument (listing the valid names) for an unknown name.
// Sequences that precompute a table (best-candidate, pmj02, pmj02bn; see tabulated.h) size it
// for 2^16 points here.
std::unique_ptr<Sequence> make_sequence(std::string_view name, uint64_t seed);

// Same, for a caller that will use at most `max_count` points: tabulated sequences then build a
// table of max_count points (rounded up to a power of two, at most 2^24) instead of 2^16. The
// points do not depend on the table size (each table is a prefix of the larger ones), so this
// only saves set-up time (the candidate searches of best-candidate and pmj02bn dominate it).
std::unique_ptr<Sequence> make_sequence(std::string_view name, uint64_t seed, uint32_t max_count);

}  // namespace disklab::sequence
