#include "common/args.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "command.h"

namespace disklab::cli {
namespace {
std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t");
  return std::string(s.substr(b, e - b + 1));
}
}  // namespace

bool is_decimal_number(std::string_view t) {
  std::size_t i = 0;
  auto digits = [&] {
    const std::size_t from = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9')
      ++i;
    return i - from;
  };
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  std::size_t mantissa = digits();
  if (i < t.size() && t[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == t.size();
}

double parse_double(std::string_view text, std::string_view what) {
  const std::string t = trim(text);
  if (t.empty()) throw UsageError(std::string(what) + ": missing value");
  // Decimal only: strtod would also take hexadecimal ("0x1p-1"), "inf" and "nan".
  if (!is_decimal_number(t)) throw UsageError(std::string(what) + ": '" + t + "' is not a number");
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (end != t.c_str() + t.size())
    throw UsageError(std::string(what) + ": '" + t + "' is not a number");
  if (!std::isfinite(v))
    throw UsageError(std::string(what) + ": '" + t + "' is not a finite number");
  // A non-zero number that rounds to 0 (below the smallest subnormal, 4.9e-324) is not what the
  // user wrote; subnormal results are kept.
  const std::size_t mantissa_end = std::min(t.find_first_of("eE"), t.size());
  if (v == 0.0 && t.substr(0, mantissa_end).find_first_of("123456789") != std::string::npos)
    throw UsageError(std::string(what) + ": '" + t + "' underflows to 0");
  return v;
}

std::vector<double> parse_list(std::string_view text, std::size_t count, std::string_view what) {
  std::vector<double> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    values.push_back(parse_double(text.substr(start, comma - start), what));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (values.size() != count) {
    std::ostringstream msg;
    msg << what << ": expected " << count << " comma-separated numbers, got '" << text << "'";
    throw UsageError(msg.str());
  }
  return values;
}

Point2 parse_point2(std::string_view text, std::string_view what) {
  const auto v = parse_list(text, 2, what);
  return {v[0], v[1]};
}

Vec3 parse_vec3(std::string_view text, std::string_view what) {
  const auto v = parse_list(text, 3, what);
  return {v[0], v[1], v[2]};
}

void require_range(double value, double lo, double hi, std::string_view what) {
  if (!(value >= lo && value <= hi)) {
    std::ostringstream msg;
    msg.precision(17);
    msg << what << ": " << value << " is outside [" << lo << ", " << hi << "]";
    throw UsageError(msg.str());
  }
}

void require_positive(double value, std::string_view what) {
  if (!(value > 0.0)) {
    std::ostringstream msg;
    msg.precision(17);
    msg << what << ": " << value << " must be positive";
    throw UsageError(msg.str());
  }
}

uint64_t parse_u64(std::string_view text, std::string_view what) {
  uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end)
    throw UsageError(std::string(what) + ": '" + std::string(text) +
                     "' is not an unsigned 64-bit integer");
  return value;
}

std::vector<std::string> parse_name_list(std::string_view text,
                                         const std::vector<std::string>& valid,
                                         std::string_view what) {
  if (text.empty()) return valid;
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string name = trim(text.substr(start, comma - start));
    require_one_of(name, valid, what);
    for (const std::string& n : names)
      if (n == name) throw UsageError(std::string(what) + ": '" + name + "' is listed twice");
    names.push_back(name);
    start = comma + 1;
  }
  return names;
}

void require_one_of(std::string_view name, const std::vector<std::string>& valid,
                    std::string_view what) {
  for (const auto& v : valid)
    if (v == name) return;
  std::ostringstream msg;
  msg << what << ": unknown name '" << name << "' (valid:";
  for (const auto& v : valid)
    msg << ' ' << v;
  msg << ')';
  throw UsageError(msg.str());
}

}  // namespace disklab::cli
