#pragma once
// Reading the committed 50-digit elliptic-integral tables (reference/elliptic_*.csv) and
// measuring errors in ulps. A missing or malformed table is a test FAILURE (an exception the
// test does not catch), never a skip.
#include <stdexcept>
#include <string>
#include <vector>

#include "reference_csv.h"

namespace disklab::test {

struct EllipticRow {
  std::vector<double> inputs;  // F: phi, m;  Pi: n, phi, m
  std::string value;           // the 45-digit reference as text (parse at any precision)
  double value_rounded;        // correctly rounded to double (strtod rounds correctly)
};

inline std::vector<EllipticRow> read_elliptic_table(const std::string& name,
                                                    std::size_t input_count) {
  // At least 100 rows: a truncated table must not pass as a smaller test.
  const auto table =
      reference::read_csv_table(std::string(DISKLAB_REFERENCE_DIR) + "/" + name, {}, 100);
  if (table.columns.size() != input_count + 1)
    throw std::runtime_error(name + ": expected " + std::to_string(input_count + 1) + " columns");
  std::vector<EllipticRow> rows;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    EllipticRow row;
    for (std::size_t i = 0; i < input_count; ++i)
      row.inputs.push_back(table.number(r, i));
    row.value = table.rows[r][input_count];
    row.value_rounded = table.number(r, input_count);
    rows.push_back(std::move(row));
  }
  return rows;
}

using reference::ulp_distance;

}  // namespace disklab::test
