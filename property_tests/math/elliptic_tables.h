#pragma once
// Reading the committed 50-digit elliptic-integral tables (reference/elliptic_*.csv) and
// measuring errors in ulps. A missing or malformed table is a test FAILURE (an exception the
// test does not catch), never a skip.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace disklab::test {

struct EllipticRow {
  std::vector<double> inputs;  // F: phi, m;  Pi: n, phi, m
  std::string value;           // the 45-digit reference as text (parse at any precision)
  double value_rounded;        // correctly rounded to double (strtod rounds correctly)
};

inline std::vector<EllipticRow> read_elliptic_table(const std::string& name,
                                                    std::size_t input_count) {
  const std::string path = std::string(DISKLAB_REFERENCE_DIR) + "/" + name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("reference table missing: " + path);
  std::vector<EllipticRow> rows;
  std::string line;
  bool header_seen = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header_seen) {  // column names
      header_seen = true;
      continue;
    }
    std::stringstream ss(line);
    std::string field;
    EllipticRow row;
    while (std::getline(ss, field, ','))
      row.inputs.push_back(std::strtod(field.c_str(), nullptr));
    if (row.inputs.size() != input_count + 1)
      throw std::runtime_error("malformed row in " + path + ": " + line);
    row.value = line.substr(line.rfind(',') + 1);
    row.value_rounded = row.inputs.back();
    row.inputs.pop_back();
    rows.push_back(std::move(row));
  }
  if (rows.size() < 100) throw std::runtime_error("reference table too short: " + path);
  return rows;
}

// Signed distance in representable doubles between a and b (0 if equal; both finite).
inline int64_t ulp_distance(double a, double b) {
  auto key = [](double x) {
    int64_t i;
    std::memcpy(&i, &x, sizeof i);
    return i < 0 ? std::numeric_limits<int64_t>::min() - i : i;  // monotone in x
  };
  return key(a) - key(b);
}

}  // namespace disklab::test
