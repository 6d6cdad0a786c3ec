#pragma once
// Shared by the bench_*.cpp programs: the console table as usual, then a summary of the ratios
// each program measured in the same run (the number to read on a loaded 2-core machine).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdio>

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace disklab::bench {

using Counters = std::map<std::string, double>;
// Benchmark name (function name and arguments, without Google Benchmark's decorations such as
// "/manual_time") -> its counters: the median over repetitions, or the single run's values.
using Results = std::map<std::string, Counters>;

// The value of `key`, or -1 when the benchmark did not report it.
inline double counter(const Counters& counters, const std::string& key) {
  const auto it = counters.find(key);
  return it == counters.end() ? -1.0 : it->second;
}

class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  using Summary = std::function<void(const Results&)>;
  // Colours only on a terminal: a file or a pipe gets plain text (scripts/bench greps it).
  explicit SummaryReporter(Summary summary)
      : ConsoleReporter(isatty(fileno(stdout)) ? OO_ColorTabular : OO_Tabular),
        summary_(std::move(summary)) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      const bool single = r.run_type == Run::RT_Iteration && r.repetitions <= 1;
      const bool median = r.run_type == Run::RT_Aggregate && r.aggregate_name == "median";
      if (!single && !median) continue;
      std::string name = r.run_name.function_name;
      if (!r.run_name.args.empty()) name += "/" + r.run_name.args;
      for (const auto& [key, value] : r.counters)
        results_[name][key] = value.value;
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    if (summary_) summary_(results_);
  }

 private:
  Summary summary_;
  Results results_;
};

// The body of every bench main: parse the flags, run what is registered, print the summary.
inline int run_benchmarks(int argc, char** argv, SummaryReporter::Summary summary) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  SummaryReporter reporter(std::move(summary));
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}

}  // namespace disklab::bench
