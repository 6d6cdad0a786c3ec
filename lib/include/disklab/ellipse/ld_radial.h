#pragma once
// The low-distortion radial map of Guillén et al. 2017 (Sec. 3.3, eq. 23): the unit square goes
// to the unit disk by Shirley and Chiu's concentric map, back to the square by the inverse polar
// map, and then through the radial map. With the full-ellipse convention of radial.h (eps1
// cumulative counter-clockwise, quadrants mirrored) the inverse polar map is simply
//     eps1 = theta / (2 pi),  eps2 = rho^2,
// which reproduces eq. (23) quadrant by quadrant (the mirroring of odd quadrants is the
// "1 - 2(theta - pi/2)/pi" branch), and eps2 = rho^2 with eps2 = 0 at the centre is the
// orientation under which the composition is concentric-like rather than inside out
// (docs/design.md section 3).
#include <cmath>

#include "disklab/disk/concentric.h"
#include "disklab/ellipse/radial.h"
#include "disklab/math/constants.h"

namespace disklab::ellipse {

struct LdRadialMap {
  RadialMap radial;

  static LdRadialMap make(const Disk& disk, const Vec3& o) noexcept {
    return LdRadialMap{RadialMap::make(disk, o)};
  }
  bool valid() const { return radial.valid(); }
  double pdf(const Vec3& direction) const { return radial.pdf(direction); }

  // Square -> the radial map's (eps1, eps2), eq. (23).
  static Point2 to_radial(Point2 u) {
    const Point2 d = disk::sample_concentric(u);
    double theta = std::atan2(d.y, d.x);
    if (theta < 0.0) theta += math::kTwoPi;
    const double e1 = std::min(theta / math::kTwoPi, math::kOneMinusEpsilon);
    const double rho2 = std::min(1.0, d.x * d.x + d.y * d.y);
    return {e1, rho2};
  }
  static Point2 from_radial(Point2 w) {
    const double theta = math::kTwoPi * w.x;
    const double rho = std::sqrt(std::clamp(w.y, 0.0, 1.0));
    return disk::invert_concentric({rho * std::cos(theta), rho * std::sin(theta)});
  }

  EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    if (!in_unit_square(u)) {
      if (iterations) *iterations = 0;
      return {};
    }
    return radial.sample(to_radial(u), iterations);
  }
  Point2 invert_local(const Vec3& l) const { return from_radial(radial.invert_local(l)); }
  Point2 invert(const Vec3& direction) const { return invert_local(radial.g.to_local(direction)); }
};

}  // namespace disklab::ellipse
