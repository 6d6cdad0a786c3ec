#pragma once
// Parsing and validation of user input. Every failure throws UsageError with a message that
// names the option and the offending text.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "disklab/types.h"

namespace disklab::cli {

// Whether `text` is a decimal floating-point number ([+-]digits[.digits][e[+-]digits]): no
// hexadecimal, no inf or nan, no surrounding text.
bool is_decimal_number(std::string_view text);

// A finite decimal double that does not underflow to 0; `what` names the option in the error
// ("--radius").
double parse_double(std::string_view text, std::string_view what);

// Exactly `count` comma-separated finite doubles ("0.5,0.25").
std::vector<double> parse_list(std::string_view text, std::size_t count, std::string_view what);

Point2 parse_point2(std::string_view text, std::string_view what);
Vec3 parse_vec3(std::string_view text, std::string_view what);

// Throws unless lo <= value <= hi.
void require_range(double value, double lo, double hi, std::string_view what);
// Throws unless value > 0.
void require_positive(double value, std::string_view what);

// An unsigned 64-bit decimal integer (a seed); `what` names the option.
uint64_t parse_u64(std::string_view text, std::string_view what);

// A comma-separated list of names, each one of `valid`, without repeats, in the given order;
// empty text gives `valid` itself (the default "all").
std::vector<std::string> parse_name_list(std::string_view text,
                                         const std::vector<std::string>& valid,
                                         std::string_view what);

// Throws unless `name` is one of `valid` (message lists them).
void require_one_of(std::string_view name, const std::vector<std::string>& valid,
                    std::string_view what);

}  // namespace disklab::cli
