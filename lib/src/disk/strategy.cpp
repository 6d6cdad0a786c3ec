// Name table of the disk strategies (Christensen 2018, Sec. 3 order).
#include "disklab/disk/strategy.h"

namespace disklab::disk {

const std::vector<std::string>& strategy_names() {
  static const std::vector<std::string> names = {"pad-zero",   "rejection", "polar",
                                                 "concentric", "polar4",    "concentric4"};
  return names;
}

std::string_view strategy_name(Strategy s) {
  return strategy_names()[static_cast<std::size_t>(s)];
}

std::optional<Strategy> parse_strategy(std::string_view name) {
  for (Strategy s : kAllStrategies)
    if (strategy_name(s) == name) return s;
  return std::nullopt;
}

}  // namespace disklab::disk
