#pragma once
// Polar map of the unit square onto the unit disk, its quarter-disk variant and polar4
// (Christensen 2018, Sec. 3 "Polar map", "Polar4 map" and Appendix A).
//
// Every map is a trio sample / invert / pdf. pdfs are densities with respect to AREA on the unit
// disk (or quarter disk), for points the map can produce; 0 elsewhere.
// Domain: u, v in [0, 1] (closed: v = 1 is the seam v = 0 again). Inverses accept any point,
// clamp the radius to 1 and return values in [0, 1]; the centre has a defined inverse.
#include <array>
#include <cmath>

#include "disklab/disk/common.h"
#include "disklab/disk/quadrant.h"
#include "disklab/math/constants.h"
#include "disklab/types.h"

namespace disklab::disk {

// ---- polar: r = sqrt(u), phi = 2 pi v (memo Sec. 3) ----

// sqrt makes the map area-preserving: the disk area inside radius r is pi r^2 = pi u.
inline Point2 sample_polar(Point2 uv) {
  const double r = std::sqrt(clamp01(uv.x));
  const double phi = math::kTwoPi * clamp01(uv.y);
  return {r * std::cos(phi), r * std::sin(phi)};
}

// u = r^2 is computed as x*x + y*y (no sqrt to undo). v comes from atan2, which is accurate to
// an ulp in angle at every radius, so v keeps an absolute accuracy of a few ulps even near the
// centre. The centre (either sign of zero: atan2(-0, -0) is -pi) maps to (0, 0); a -0.0 in y
// on the positive x axis gives v = +0 via the + 0.0.
inline Point2 invert_polar(Point2 p) {
  if (p.x == 0.0 && p.y == 0.0) return {0.0, 0.0};
  const double u = clamp01(p.x * p.x + p.y * p.y);
  double phi = std::atan2(p.y, p.x) + 0.0;
  if (phi < 0.0) phi += math::kTwoPi;
  return {u, clamp01(phi / math::kTwoPi)};
}

// Uniform on the disk: 1/pi w.r.t. area.
inline double pdf_polar(Point2 p) {
  return inside_unit_disk(p) ? kInvPi : 0.0;
}

// ---- quarter-disk polar: r = sqrt(u), phi = (pi/2) v (memo Appendix A, before the rotation) ----

inline Point2 sample_polar_quarter(Point2 uv) {
  const double r = std::sqrt(clamp01(uv.x));
  const double phi = math::kHalfPi * clamp01(uv.y);
  return {r * std::cos(phi), r * std::sin(phi)};
}

// Expects a first-quadrant point; coordinates below 0 are treated as 0 (fold a disk point with
// fold_to_first_quadrant first). The centre maps to (0, 0).
inline Point2 invert_polar_quarter(Point2 q) {
  const double x = q.x > 0.0 ? q.x : 0.0;
  const double y = q.y > 0.0 ? q.y : 0.0;
  const double u = clamp01(x * x + y * y);
  return {u, clamp01(std::atan2(y, x) / math::kHalfPi)};
}

// Uniform on the closed first quadrant of the disk: 4/pi w.r.t. area.
inline double pdf_polar_quarter(Point2 q) {
  return (q.x >= 0.0 && q.y >= 0.0 && inside_unit_disk(q)) ? kFourOverPi : 0.0;
}

// ---- polar4: one square point, four disk points rotated by 0, 90, 180, 270 degrees ----

// Copy k is the memo's sample s with s mod 4 = k: uniform on quadrant k (density 4/pi there).
// A uniformly chosen copy is uniform on the disk (pdf_polar), so an estimate over whole groups
// of four is unbiased; the four copies are not independent, which is the point of the strategy.
inline std::array<Point2, 4> sample_polar4(Point2 uv) {
  return four_rotations(sample_polar_quarter(uv));
}

// Inverse of one polar4 output: the square point and the copy index k that produce p.
inline Inverse4 invert_polar4(Point2 p) {
  const Folded f = fold_to_first_quadrant(p);
  return {invert_polar_quarter(f.q), f.k};
}

}  // namespace disklab::disk
