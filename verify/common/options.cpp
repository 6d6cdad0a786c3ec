#include "common/options.h"

#include <cstdint>
#include <filesystem>
#include <vector>

#include <CLI/CLI.hpp>

namespace disklab::cli {

Option* Option::capture_default_str() {
  option_->capture_default_str();
  return this;
}
Option* Option::required() {
  option_->required();
  return this;
}
Option* Option::excludes(const Option* other) {
  option_->excludes(other->option_);
  return this;
}
std::size_t Option::count() const {
  return option_->count();
}

template <class T>
Option* Options::add_option(const std::string& name, T& target, const std::string& help) {
  return &options_.emplace_back(app_->add_option(name, target, help));
}

Option* Options::add_flag(const std::string& name, bool& target, const std::string& help) {
  return &options_.emplace_back(app_->add_flag(name, target, help));
}

Options* Options::add_subcommand(const std::string& name, const std::string& summary) {
  return &children_.emplace_back(*app_->add_subcommand(name, summary));
}

void Options::require_subcommand(int n) {
  app_->require_subcommand(n);
}
void Options::footer(const std::string& text) {
  app_->footer(text);
}
void Options::callback(std::function<void()> f) {
  app_->callback(std::move(f));
}

// The value types the subcommands bind.
template Option* Options::add_option(const std::string&, std::string&, const std::string&);
template Option* Options::add_option(const std::string&, std::filesystem::path&,
                                     const std::string&);
template Option* Options::add_option(const std::string&, double&, const std::string&);
template Option* Options::add_option(const std::string&, int&, const std::string&);
template Option* Options::add_option(const std::string&, long&, const std::string&);
template Option* Options::add_option(const std::string&, unsigned&, const std::string&);
template Option* Options::add_option(const std::string&, std::uint64_t&, const std::string&);
template Option* Options::add_option(const std::string&, std::vector<std::string>&,
                                     const std::string&);

}  // namespace disklab::cli
