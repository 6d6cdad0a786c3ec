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

}  // namespace disklab::ellipse
