// Name -> generator table for the CLI and the experiments. Add each new generator here once.
#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "disklab/sequence/art.h"
#include "disklab/sequence/halton.h"
#include "disklab/sequence/random.h"
#include "disklab/sequence/sequence.h"
#include "disklab/sequence/sobol.h"
#include "disklab/sequence/tabulated.h"

namespace disklab::sequence {
namespace {

struct Entry {
  const char* name;
  std::unique_ptr<Sequence> (*make)(const char* name, uint64_t seed, uint32_t capacity);
};

template <class Gen>
std::unique_ptr<Sequence> analytic(const char* name, uint64_t seed, uint32_t /*capacity*/) {
  return std::make_unique<SequenceAdapter<Gen>>(name, Gen(seed));
}

template <class Gen>
std::unique_ptr<Sequence> tabulated(const char* name, uint64_t seed, uint32_t capacity) {
  return std::make_unique<SequenceAdapter<Gen>>(name, Gen(seed, capacity));
}

// Memo order (Christensen 2018, Fig. 2): Ahmed's ART is (c), after best candidates.
const Entry kEntries[] = {
    {"random", analytic<RandomSequence>},
    {"best-candidate", tabulated<BestCandidate>},
    {"art", analytic<ArtSequence>},
    {"halton-rotated", analytic<HaltonRotated>},
    {"halton-scrambled", analytic<HaltonScrambled>},
    {"sobol-rotated", analytic<SobolRotated>},
    {"sobol-xor", analytic<SobolXor>},
    {"sobol-owen", analytic<SobolOwen>},
    {"pmj02", tabulated<Pmj02>},
    {"pmj02bn", tabulated<Pmj02BlueNoise>},
};

}  // namespace

std::vector<std::string> sequence_names() {
  std::vector<std::string> names;
  for (const Entry& e : kEntries)
    names.emplace_back(e.name);
  return names;
}

std::unique_ptr<Sequence> make_sequence(std::string_view name, uint64_t seed) {
  return make_sequence(name, seed, kDefaultCapacity);
}

std::unique_ptr<Sequence> make_sequence(std::string_view name, uint64_t seed, uint32_t max_count) {
  const uint32_t capacity = std::clamp<uint32_t>(max_count, 1u, 1u << 24);
  for (const Entry& e : kEntries)
    if (name == e.name) return e.make(e.name, seed, capacity);
  std::ostringstream msg;
  msg << "unknown sequence '" << name << "' (valid:";
  for (const Entry& e : kEntries)
    msg << ' ' << e.name;
  msg << ')';
  throw std::invalid_argument(msg.str());
}

}  // namespace disklab::sequence
