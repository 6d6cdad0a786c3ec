#pragma once
// What every spherical-ellipse sampler returns, and the conventions they share.
//
// A sampler is a small struct set up once per shading point (`make`), then sampled many times.
// `sample` returns a unit direction from the shading point, the hit point on the disk and the
// pdf of the direction in the SOLID-ANGLE measure. `valid == false` means "no sample": either
// the geometry is degenerate (point behind or in the plane of the one-sided disk, zero radius,
// non-finite input), or a rejection sampler used in proposal mode rejected its candidate. In
// both cases the sample contributes zero to an estimator, which keeps every estimator unbiased.
// Hot paths allocate nothing, throw nothing and never return NaN.
//
// DOMAIN. u lies in [0, 1]^2 (both ends included). Any other u, NaN included, is "no sample":
// every map tests it first (in_unit_square), so no u reaches a table index or a root solve.
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "disklab/types.h"

namespace disklab::ellipse {

struct EllipseSample {
  Vec3 direction = Vec3::Zero();  // unit vector from the shading point towards the disk
  // The same direction in the ellipse frame R_e = (x_e, y_e, z_e) (Guillén et al. 2017, Sec. 3),
  // computed without cancellation: its x, y keep full relative accuracy for distant disks.
  Vec3 local = Vec3(0.0, 0.0, 1.0);
  Vec3 point = Vec3::Zero();  // where the direction meets the disk
  double pdf = 0.0;           // solid-angle density of `direction`
  bool valid = false;
};

// v / |v| for any finite non-zero v, however short or long: v is first divided by its largest
// component, so |v|^2 neither underflows (Eigen's normalized() returns a vector whose squared
// norm underflows unchanged, e.g. a direction of length 1e-300) nor overflows. Zero for v = 0.
// Where |v|^2 is a normal double this is v / sqrt(|v|^2), bit for bit Eigen's normalized().
inline Vec3 unit_vector(const Vec3& v) {
  const double n2 = v.squaredNorm();
  if (n2 >= std::numeric_limits<double>::min() && n2 < std::numeric_limits<double>::infinity())
    return v / std::sqrt(n2);
  const double m = v.cwiseAbs().maxCoeff();
  if (!(m > 0.0) || !std::isfinite(m)) return Vec3::Zero();
  const Vec3 w = v / m;
  return w / w.norm();
}

// v / |v| for a v that is unit up to a few roundings (a unit local direction rotated to the world):
// one Newton step for 1/sqrt, 1/|v| ~ (3 - |v|^2) / 2, whose error (|v|^2 - 1)^2 is far below an
// ulp when |v|^2 is within 1e-8 of 1; unit_vector otherwise.
[[gnu::always_inline]] inline Vec3 renormalized(const Vec3& v) {
  const double n2 = v.squaredNorm();
  return std::abs(n2 - 1.0) <= 1e-8 ? Vec3(v * (1.5 - 0.5 * n2)) : unit_vector(v);
}

// Whether u is in the maps' domain [0, 1]^2 (false for NaN).
inline bool in_unit_square(Point2 u) {
  return u.x >= 0.0 && u.x <= 1.0 && u.y >= 0.0 && u.y <= 1.0;
}

}  // namespace disklab::ellipse
