#pragma once
// Constants and small helpers shared by the square-to-disk strategies.
#include <cmath>

#include "disklab/math/constants.h"
#include "disklab/types.h"

namespace disklab::disk {

inline constexpr double kInvPi = 1.0 / math::kPi;
// Density of a uniform point on the quarter disk, and the pad-zero weight: 4/pi.
inline constexpr double kFourOverPi = 4.0 / math::kPi;
inline constexpr double kQuarterPi = math::kPi / 4.0;

// Sample outputs may land a few ulps outside the unit circle (cos^2 + sin^2 rounds away from 1,
// sqrt(u) at u = 1 is exact but the products are not). pdfs still count such points as inside;
// 16 ulps of 1 covers the rounding of x*x + y*y for a point the maps produce.
inline constexpr double kRimSlack = 16.0 * 0x1p-52;

inline bool inside_unit_disk(Point2 p) {
  return p.x * p.x + p.y * p.y <= 1.0 + kRimSlack;
}

// Clamps to [0, 1]; NaN becomes 0 so that hot paths never propagate NaN.
inline double clamp01(double t) {
  return t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0;
}

}  // namespace disklab::disk
