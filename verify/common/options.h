#pragma once
// The option-binding surface the subcommands see. Only main.cpp and options.cpp include CLI11:
// it is a large header, and every translation unit that parsed it paid for it in the build and
// in clang-tidy. The names mirror CLI11's so a subcommand reads like CLI11 code.
#include <cstddef>
#include <deque>
#include <functional>
#include <string>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace disklab::cli {

// One bound option (or flag); owned by the Options that made it.
class Option {
 public:
  explicit Option(CLI::Option* option) : option_(option) {}
  Option* capture_default_str();          // --help shows the bound value's default
  Option* required();                     // the parse fails without it
  Option* excludes(const Option* other);  // the parse fails when both are given
  std::size_t count() const;              // how often it was given (after the parse)

 private:
  CLI::Option* option_;
};

// The options of one (sub)command, bound to state the command owns.
class Options {
 public:
  explicit Options(CLI::App& app) : app_(&app) {}
  Options(const Options&) = delete;
  Options& operator=(const Options&) = delete;

  // T is one of the types options.cpp instantiates (string, path, numbers, string vectors).
  template <class T>
  Option* add_option(const std::string& name, T& target, const std::string& help);
  Option* add_flag(const std::string& name, bool& target, const std::string& help);
  Options* add_subcommand(const std::string& name, const std::string& summary);
  void require_subcommand(int n);
  void footer(const std::string& text);
  void callback(std::function<void()> f);  // runs when this (sub)command is parsed

 private:
  CLI::App* app_;
  std::deque<Option> options_;    // stable addresses: callers keep Option*
  std::deque<Options> children_;  // nested subcommands
};

}  // namespace disklab::cli
