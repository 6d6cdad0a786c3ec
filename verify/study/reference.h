#pragma once
// Reference irradiance for the studies, computed without the samplers under test.
//  - disk_irradiance_parallel: the closed form for a receiver parallel to the disk and facing
//    it, unoccluded (the form factor of a coaxial-plane disk, written without cancellation).
//  - irradiance_quadrature: any shading point with a receiver above whose horizon the disk lies,
//    with sphere occluders, by polar coordinates in the light's plane around the foot of the
//    shading point. Along each ray the visible intervals are exact (disk and shadow-cone roots,
//    classified by the same segment-sphere test the estimators use) and the radial integral
//    is closed-form; the angular integral is split at every angle where the intervals change
//    shape (tangents to the disk and to the shadow cone, rim-shadow crossings) and integrated
//    by adaptive Gauss-Legendre after a substitution that removes the square-root behaviour
//    at tangents.
#include <string>
#include <vector>

#include "study/scene.h"

namespace disklab::study {

// E = (pi L / 2) (1 - (h^2 + d^2 - R^2) / sqrt((h^2 + d^2 + R^2)^2 - 4 d^2 R^2)) for a receiver
// at height h below a one-sided disk facing it, d off its axis. With X = h^2 + d^2 - R^2 and
// Y = sqrt(h^2 + (d-R)^2) sqrt(h^2 + (d+R)^2), 1 - X/Y = 4 R^2 h^2 / (Y (Y + X)) (as
// Y^2 - X^2 = 4 R^2 h^2): that form where X >= 0, the printed one where X < 0, so neither
// cancels.
double disk_irradiance_parallel(double radiance, double radius, double height, double offset);

struct ReferenceValue {
  double value = 0.0;
  double error_estimate = 0.0;  // absolute; a bound on the quadrature and rounding error
};

// Throws std::domain_error where the method does not apply: the shading point inside an
// occluder, an occluder crossing the light's plane, or visible parts of the disk below the
// receiver's horizon. `rel_tol` is the target error relative to the result.
ReferenceValue irradiance_quadrature(const Scene& scene, const ShadingPoint& sp,
                                     double rel_tol = 1e-14);

// The unoccluded irradiance of a uniform disk (either side, so one- and two-sided lights alike
// where the point sees the emitting face) lying wholly above the receiver's horizon, as a
// boundary integral: E = L n_o . (1/2) oint (x cross dx) / |x|^2 over the rim, x = rim - o
// (the vector irradiance of a region whose boundary is the rim; Lambert's polygon formula
// in the limit of many edges). The integrand is periodic and analytic in the rim angle, so
// the trapezoid rule converges geometrically; nodes double until two levels agree to
// `rel_tol`, and the error estimate is that difference plus the summation's rounding.
// Throws std::domain_error when part of the rim is on or below the horizon.
ReferenceValue irradiance_rim(const DiskLight& light, const ShadingPoint& sp,
                              double rel_tol = 1e-15);

// A region's shading points with their references, as the studies report them.
struct PointReference {
  ShadingPoint point;
  ReferenceValue reference;
};
struct RegionReferences {
  std::string region;
  std::string method;  // how the values were computed, e.g. "closed-form", "quadrature"
  std::vector<PointReference> points;
};

}  // namespace disklab::study
