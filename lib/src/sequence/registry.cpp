// Name -> generator table for the CLI and the experiments. Add each new generator here once.
#include <sstream>
#include <stdexcept>

#include "disklab/sequence/halton.h"
#include "disklab/sequence/random.h"
#include "disklab/sequence/sequence.h"
#include "disklab/sequence/sobol.h"
#include "disklab/sequence/tabulated.h"

namespace disklab::sequence {
namespace {

struct Entry {
  const char* name;
  std::unique_ptr<Sequence> (*make)(uint64_t seed);
};

template <class Gen>
std::unique_ptr<Sequence> make_adapter(const char* name, uint64_t seed) {
  return std::make_unique<SequenceAdapter<Gen>>(name, Gen(seed));
}

// Memo order (Christensen 2018, Fig. 2).
// Ahmed ART (c) belongs between best-candidate and halton-rotated; it has its own issue.
const Entry kEntries[] = {
    {"random", [](uint64_t s) { return make_adapter<RandomSequence>("random", s); }},
    {"best-candidate", [](uint64_t s) { return make_adapter<BestCandidate>("best-candidate", s); }},
    {"halton-rotated", [](uint64_t s) { return make_adapter<HaltonRotated>("halton-rotated", s); }},
    {"halton-scrambled",
     [](uint64_t s) { return make_adapter<HaltonScrambled>("halton-scrambled", s); }},
    {"sobol-rotated", [](uint64_t s) { return make_adapter<SobolRotated>("sobol-rotated", s); }},
    {"sobol-xor", [](uint64_t s) { return make_adapter<SobolXor>("sobol-xor", s); }},
    {"sobol-owen", [](uint64_t s) { return make_adapter<SobolOwen>("sobol-owen", s); }},
    {"pmj02", [](uint64_t s) { return make_adapter<Pmj02>("pmj02", s); }},
    {"pmj02bn", [](uint64_t s) { return make_adapter<Pmj02BlueNoise>("pmj02bn", s); }},
};

}  // namespace

std::vector<std::string> sequence_names() {
  std::vector<std::string> names;
  for (const Entry& e : kEntries)
    names.emplace_back(e.name);
  return names;
}

std::unique_ptr<Sequence> make_sequence(std::string_view name, uint64_t seed) {
  for (const Entry& e : kEntries)
    if (name == e.name) return e.make(seed);
  std::ostringstream msg;
  msg << "unknown sequence '" << name << "' (valid:";
  for (const Entry& e : kEntries)
    msg << ' ' << e.name;
  msg << ')';
  throw std::invalid_argument(msg.str());
}

}  // namespace disklab::sequence
