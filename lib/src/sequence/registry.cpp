// Name -> generator table for the CLI and the experiments. Add each new generator here once.
#include <sstream>
#include <stdexcept>

#include "disklab/sequence/random.h"
#include "disklab/sequence/sequence.h"

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
const Entry kEntries[] = {
    {"random", [](uint64_t s) { return make_adapter<RandomSequence>("random", s); }},
};

}  // namespace

std::vector<std::string> sequence_names() {
  std::vector<std::string> names;
  for (const Entry& e : kEntries) names.emplace_back(e.name);
  return names;
}

std::unique_ptr<Sequence> make_sequence(std::string_view name, uint64_t seed) {
  for (const Entry& e : kEntries)
    if (name == e.name) return e.make(seed);
  std::ostringstream msg;
  msg << "unknown sequence '" << name << "' (valid:";
  for (const Entry& e : kEntries) msg << ' ' << e.name;
  msg << ')';
  throw std::invalid_argument(msg.str());
}

}  // namespace disklab::sequence
