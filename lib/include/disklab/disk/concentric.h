#pragma once
// Concentric map (Shirley and Chiu 1997; Christensen 2018, Sec. 3 "Concentric map"), its
// quarter-disk variant and concentric4 (Sec. 3 "Concentric4 map").
//
// Trio sample / invert / pdf; pdfs are w.r.t. AREA on the unit disk (quarter disk), 0 outside.
// The square [0,1]^2 is first scaled to (a, b) in [-1,1]^2; each concentric square |a|, |b| = s
// goes to the circle of radius s, so the map is area-preserving with the constant Jacobian pi/4.
//
// sample_concentric is written in Shirley and Chiu's original four-region form. The seed blog's
// one-branch form (Cline's, radius = a or b with a sign) is implemented separately in the tests
// and shown to be the same map there.
#include <array>
#include <cmath>

#include "disklab/disk/common.h"
#include "disklab/disk/quadrant.h"
#include "disklab/math/constants.h"
#include "disklab/types.h"

namespace disklab::disk {

// Shirley and Chiu 1997, the four triangular regions of [-1,1]^2 cut by the diagonals:
//   1: a > -b, a > b:   r = a,  phi = (pi/4) (b/a)
//   2: a > -b, a <= b:  r = b,  phi = (pi/4) (2 - a/b)
//   3: a <= -b, a < b:  r = -a, phi = (pi/4) (4 + b/a)
//   4: a <= -b, a >= b: r = -b, phi = (pi/4) (6 - a/b)
// In each region the divisor has the largest magnitude, so b/a and a/b lie in [-1, 1]; only the
// centre a = b = 0 would divide by zero (region 4 with b = 0): it is special-cased first.
inline Point2 sample_concentric(Point2 uv) {
  const double a = 2.0 * clamp01(uv.x) - 1.0;
  const double b = 2.0 * clamp01(uv.y) - 1.0;
  if (a == 0.0 && b == 0.0) return {0.0, 0.0};  // the centre: phi is undefined, r = 0
  double r, phi;
  if (a > -b) {
    if (a > b) {
      r = a;
      phi = kQuarterPi * (b / a);
    } else {
      r = b;
      phi = kQuarterPi * (2.0 - a / b);
    }
  } else {
    if (a < b) {
      r = -a;
      phi = kQuarterPi * (4.0 + b / a);
    } else {
      r = -b;
      phi = kQuarterPi * (6.0 - a / b);
    }
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

// Inverse by the dominant coordinate: where |x| >= |y| the point came from the left/right
// regions (1, 3) with a = +-r and b/a = (4/pi) atan(y/x); otherwise from the top/bottom regions
// (2, 4) with b = +-r and a/b = (4/pi) atan(x/y). The ratio is at most 1 in magnitude, so atan is
// well conditioned and the result keeps an absolute accuracy of a few ulps. Centre -> (1/2, 1/2).
inline Point2 invert_concentric(Point2 p) {
  const double x = p.x, y = p.y;
  if (!(x != 0.0 || y != 0.0)) return {0.5, 0.5};  // the centre (and NaN input)
  const double r = std::fmin(std::hypot(x, y), 1.0);
  double a, b;
  if (std::fabs(x) >= std::fabs(y)) {
    a = std::copysign(r, x);
    b = a * (kFourOverPi * std::atan(y / x));
  } else {
    b = std::copysign(r, y);
    a = b * (kFourOverPi * std::atan(x / y));
  }
  return {clamp01(0.5 * (a + 1.0)), clamp01(0.5 * (b + 1.0))};
}

inline double pdf_concentric(Point2 p) {
  return inside_unit_disk(p) ? kInvPi : 0.0;
}

// ---- quarter-disk concentric: the concentric map of the quadrant a, b in [0,1] ----
// (u, v) play the role of (a, b) directly: only regions 1 and 2 occur, and the square [0,1]^2
// goes area-preservingly onto the quarter disk (Jacobian pi/4 again).

inline Point2 sample_concentric_quarter(Point2 uv) {
  const double a = clamp01(uv.x);
  const double b = clamp01(uv.y);
  if (a == 0.0 && b == 0.0) return {0.0, 0.0};  // the centre
  double r, phi;
  if (a > b) {
    r = a;
    phi = kQuarterPi * (b / a);
  } else {
    r = b;
    phi = kQuarterPi * (2.0 - a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

// Expects a first-quadrant point (negative coordinates count as 0). Centre -> (0, 0).
inline Point2 invert_concentric_quarter(Point2 q) {
  const double x = q.x > 0.0 ? q.x : 0.0;
  const double y = q.y > 0.0 ? q.y : 0.0;
  if (x == 0.0 && y == 0.0) return {0.0, 0.0};
  const double r = std::fmin(std::hypot(x, y), 1.0);
  if (x >= y) return {r, clamp01(r * (kFourOverPi * std::atan(y / x)))};
  return {clamp01(r * (kFourOverPi * std::atan(x / y))), r};
}

inline double pdf_concentric_quarter(Point2 q) {
  return (q.x >= 0.0 && q.y >= 0.0 && inside_unit_disk(q)) ? kFourOverPi : 0.0;
}

// ---- concentric4: quarter-disk concentric point, reused four times rotated ----

inline std::array<Point2, 4> sample_concentric4(Point2 uv) {
  return four_rotations(sample_concentric_quarter(uv));
}

// Inverse of one concentric4 output: the square point and the copy index k.
inline Inverse4 invert_concentric4(Point2 p) {
  const Folded f = fold_to_first_quadrant(p);
  return {invert_concentric_quarter(f.q), f.k};
}

}  // namespace disklab::disk
