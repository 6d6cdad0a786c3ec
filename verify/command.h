#pragma once
// Subcommand registry of the `disklab` CLI. Each verify/<name>.cpp defines one subcommand and
// registers it with a file-scope `Registrar`; main.cpp builds the CLI11 app from the registry
// (the subcommands bind options through common/options.h and never see CLI11).
//
// Conventions every subcommand keeps (a contract scripts rely on):
//  - numbers on stdout use fmt17 (%.17g) so they round-trip;
//  - bad user input throws UsageError: main prints one line "disklab: error: ..." on stderr and
//    exits 2; other failures exit 1;
//  - files are written through AtomicFile (common/output.h): nothing partial is left behind;
//  - --help has examples (CLI11 footer).
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/options.h"

namespace disklab::cli {

// Invalid input from the user: exit code 2, message printed as one line.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ReportOptions {
  std::filesystem::path dir;  // where the report writes (already created)
  bool quick = false;         // smaller runs (CI, smoke tests)
  // Markdown a part adds to the index's claims section (paper claim, measured value, verdict);
  // null when the caller keeps no index.
  std::string* claims = nullptr;
  // Markdown a part adds to the index's first screen: the answer a reader came for (which
  // strategy and sequence, which map, at what error and cost); null when there is no index.
  std::string* answers = nullptr;
};

struct Command {
  std::string name;
  std::string summary;
  // Adds options to `sub` (binding them to state the command owns) and returns the action that
  // runs after a successful parse. The returned int is the exit code.
  std::function<std::function<int()>(Options& sub)> setup;
  // Optional part of `disklab report`: writes this command's outputs into options.dir.
  std::function<int(const ReportOptions& options)> report;
};

std::vector<Command>& registry();

struct Registrar {
  explicit Registrar(Command command) { registry().push_back(std::move(command)); }
};

}  // namespace disklab::cli
