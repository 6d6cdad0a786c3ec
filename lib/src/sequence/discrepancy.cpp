// Warnock's formula for the L2-star discrepancy (see discrepancy.h).
#include "disklab/sequence/discrepancy.h"

#include <algorithm>
#include <cmath>

namespace disklab::sequence {

double l2_star_discrepancy(const std::vector<Point2>& points) {
  const std::size_t n = points.size();
  if (n == 0) return 1.0 / 3.0;
  // D^2 is small (~1e-8 at N = 4096 for a net) against terms of order 0.1: accumulate in long
  // double, row by row, so the cancellation in the final sum costs few digits.
  long double single = 0.0L, pairs = 0.0L;
  for (std::size_t i = 0; i < n; ++i) {
    const double xi = points[i].x, yi = points[i].y;
    single += (1.0 - xi * xi) * (1.0 - yi * yi);
    double row = 0.0;  // j > i; the diagonal is added separately
    for (std::size_t j = i + 1; j < n; ++j)
      row += (1.0 - std::max(xi, points[j].x)) * (1.0 - std::max(yi, points[j].y));
    pairs += 2.0L * row + (1.0 - xi) * (1.0 - yi);
  }
  const long double nn = static_cast<long double>(n);
  const long double d2 = 1.0L / 9.0L - single / (2.0L * nn) + pairs / (nn * nn);
  return std::sqrt(static_cast<double>(std::max(d2, 0.0L)));
}

}  // namespace disklab::sequence
