#pragma once
// The spherical ellipse's quadrants, shared by the radial family and the tabulated map
// (docs/design.md section 3, "Full ellipse from one quadrant"). The ellipse is mirror-symmetric
// about the x_e and y_e planes; quadrant k (counter-clockwise from +x_e) holds eps1 in [k/4,
// (k+1)/4), and odd quadrants are mirrored so that the maps stay continuous across the seams.
#include <algorithm>
#include <cmath>

#include "disklab/types.h"

namespace disklab::ellipse {

// Full-ellipse eps1 -> (quadrant k, fraction t' in that quadrant, mirrored on odd quadrants).
// (NaN, which in_unit_square keeps out of the maps, counts as 0: no NaN reaches the int cast.)
inline int split_quadrant(double eps1, double& t_folded) {
  const double e = (eps1 > 0.0 ? std::min(eps1, 1.0) : 0.0) * 4.0;
  const int k = std::min(3, static_cast<int>(e));
  const double t = std::clamp(e - k, 0.0, 1.0);
  t_folded = (k & 1) ? 1.0 - t : t;
  return k;
}
inline double join_quadrant(int k, double t_folded) {
  const double t = (k & 1) ? 1.0 - t_folded : t_folded;
  return (k + t) * 0.25;
}

// A local-frame direction folded into the first quadrant: |x|, |y| and the quadrant k it came
// from (by the signs, so -0.0 counts as negative and every direction has one k).
struct FoldedDirection {
  double x, y;
  int k;
};
inline FoldedDirection fold_direction(const Vec3& l) {
  const bool left = std::signbit(l.x()), down = std::signbit(l.y());
  return {std::abs(l.x()), std::abs(l.y()), down ? (left ? 2 : 3) : (left ? 1 : 0)};
}
// The first-quadrant point (x, y) reflected into quadrant k.
inline Vec3 unfold_direction(int k, double x, double y, double z) {
  return {(k == 1 || k == 2) ? -x : x, k >= 2 ? -y : y, z};
}

// 1 - z of a unit local direction, (x^2 + y^2) / (1 + z): no cancellation near the centre.
inline double one_minus_z(const Vec3& l) {
  return (l.x() * l.x() + l.y() * l.y()) / (1.0 + std::max(0.0, l.z()));
}

}  // namespace disklab::ellipse
