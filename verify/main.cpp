// `disklab`: accuracy reports, the papers' experiments and single evaluations.
#include <algorithm>
#include <cstdio>
#include <deque>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "command.h"
#include "common/args.h"

namespace disklab::cli {
std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}
}  // namespace disklab::cli

namespace {
// Every value given on the command line, for every option of the chosen subcommand: an empty
// value is an error (it would otherwise mean the option's default: stdout for --out, every name
// for --sequences), and a number option takes decimal numbers only (CLI11 also reads 0x10, 0b10).
void check_option_values(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands()) {
    for (const CLI::Option* opt : sub->get_options()) {
      if (opt->count() == 0 || opt->get_type_size_min() == 0) continue;  // not given, or a flag
      const std::string type = opt->get_type_name();
      const bool number = type == "INT" || type == "UINT" || type == "FLOAT";
      for (const std::string& value : opt->results()) {
        if (value.empty()) throw disklab::cli::UsageError(opt->get_name() + ": empty value");
        if (number && !disklab::cli::is_decimal_number(value)) {
          std::string msg = opt->get_name();
          msg += ": '";
          msg += value;
          msg += "' is not a decimal number";
          throw disklab::cli::UsageError(msg);
        }
      }
    }
  }
}
}  // namespace

static int run_cli(int argc, char** argv) {
  using namespace disklab::cli;
  CLI::App app{
      "disklab: sample disk-shaped area lights, and prove the samplers.\n"
      "Square sequences, square-to-disk strategies (Christensen 2018) and solid-angle maps of\n"
      "the spherical ellipse (Guillen et al. 2017), with their accuracy and convergence studies.",
      "disklab"};
  app.require_subcommand(1);
  app.footer(
      "Run `disklab <command> --help` for a command's options and examples.\n"
      "Exit codes: 0 success, 1 internal failure, 2 invalid input.");

  auto& commands = registry();
  std::sort(commands.begin(), commands.end(),
            [](const Command& a, const Command& b) { return a.name < b.name; });
  std::function<int()> action;
  std::deque<Options> bound;  // outlives the parse: the actions query their options' counts
  for (Command& command : commands) {
    CLI::App* sub = app.add_subcommand(command.name, command.summary);
    auto run = command.setup(bound.emplace_back(*sub));
    sub->callback([&action, run] { action = run; });
  }

  // CLI11 reports an unknown first word as "a subcommand is required"; name it instead.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string first = argv[1];
    const bool known = std::any_of(commands.begin(), commands.end(),
                                   [&](const Command& c) { return c.name == first; });
    if (!known) {
      std::string names;
      for (const Command& c : commands)
        names += " " + c.name;
      std::fprintf(stderr, "disklab: error: unknown command '%s' (valid:%s)\n", first.c_str(),
                   names.c_str());
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    std::replace(what.begin(), what.end(), '\n', ' ');
    std::fprintf(stderr, "disklab: error: %s (see --help)\n", what.c_str());
    return 2;
  }
  try {
    check_option_values(app);
    const int code = action ? action() : 2;
    // Output that never reached its destination (a full disk, a closed pipe) is a failure, not a
    // success: flush and look.
    std::cout.flush();
    if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout) {
      std::fprintf(stderr, "disklab: error: writing to stdout failed\n");
      return 1;
    }
    return code;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "disklab: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "disklab: internal error: %s\n", e.what());
    return 1;
  }
}

// Building the app can throw too (an allocation, a registry clash): no exception leaves main.
int main(int argc, char** argv) {
  try {
    return run_cli(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "disklab: internal error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "disklab: internal error: unknown exception\n");
  }
  return 1;
}
