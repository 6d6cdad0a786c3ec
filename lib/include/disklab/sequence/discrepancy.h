#pragma once
// L2-star discrepancy of a point set in [0,1)^2 by Warnock's (1972) closed form:
//   D^2 = 1/9 - (1/(2N)) sum_i (1 - x_i^2)(1 - y_i^2)
//             + (1/N^2) sum_i sum_j (1 - max(x_i, x_j)) (1 - max(y_i, y_j)).
// O(N^2) time, O(1) memory. For N independent uniform points E[D^2] = (1/4 - 1/9) / N = 5/(36 N)
// exactly (the variance of the empirical anchored-box measure, integrated over boxes), which the
// tests use as an independent check.
#include <cstddef>
#include <vector>

#include "disklab/types.h"

namespace disklab::sequence {

// Returns D (not D^2). An empty set has D = 1/3 (the discrepancy of no points: sqrt(1/9)).
double l2_star_discrepancy(const std::vector<Point2>& points);

// E[D] is not available in closed form, but E[D^2] for uniform random points is.
inline double expected_random_l2_star_squared(std::size_t n) {
  return (1.0 / 4.0 - 1.0 / 9.0) / static_cast<double>(n);
}

}  // namespace disklab::sequence
