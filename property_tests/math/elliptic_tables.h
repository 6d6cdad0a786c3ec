#pragma once
// Reading the committed 50-digit elliptic-integral tables (reference/elliptic_*.csv) and
// measuring errors in ulps. A missing or malformed table is a test FAILURE (an exception the
// test does not catch), never a skip.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference_csv.h"

namespace disklab::test {

using reference::EllipticRow;  // inputs (F: phi, m; Pi: n, phi, m), the 45-digit value

// A committed table by name; at least 100 rows: a truncated table must not pass as a smaller
// test.
inline std::vector<EllipticRow> read_elliptic_table(const std::string& name,
                                                    std::size_t input_count) {
  return reference::read_elliptic_table(std::string(DISKLAB_REFERENCE_DIR) + "/" + name,
                                        input_count, {}, 100);
}

using reference::ulp_distance;

// How a double compares with an exact value v (given to ~50 digits): its error in units of the
// spacing of doubles at v, and whether it is FAITHFUL, one of the two doubles around v (v itself
// where v is a double): below one ulp of v, the promise of a faithfully rounded function.
struct RoundingError {
  double ulps;
  bool faithful;
};
inline RoundingError rounding_error(double own,
                                    const boost::multiprecision::cpp_bin_float_50& exact) {
  using Real50 = boost::multiprecision::cpp_bin_float_50;
  // The double nearest v (the conversion's own rounding is not relied on).
  double nearest = exact.convert_to<double>();
  for (const double neighbour : {std::nextafter(nearest, -std::numeric_limits<double>::infinity()),
                                 std::nextafter(nearest, std::numeric_limits<double>::infinity())})
    if (abs(Real50(neighbour) - exact) < abs(Real50(nearest) - exact)) nearest = neighbour;
  const double spacing =
      std::nextafter(std::fabs(nearest), std::numeric_limits<double>::infinity()) -
      std::fabs(nearest);
  const Real50 diff_own = Real50(own) - exact, diff_nearest = Real50(nearest) - exact;
  const int64_t apart = ulp_distance(own, nearest);
  // own == nearest, or own is nearest's neighbour on the other side of v.
  const bool faithful = apart == 0 || ((apart == 1 || apart == -1) && diff_own * diff_nearest <= 0);
  return {static_cast<double>(abs(diff_own) / Real50(spacing)), faithful};
}

}  // namespace disklab::test
