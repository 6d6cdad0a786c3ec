#pragma once
// Spherical-polygon solid angles and binning helpers for the spherical-ellipse suites.
//
// The solid angle of a mapped stratum is computed here from its boundary alone (a fan of
// spherical triangles), independently of any map's Jacobian or pdf, so that an area-preservation
// test compares two independent computations.
#include <cstddef>
#include <functional>
#include <vector>

#include "disklab/types.h"

namespace disklab::test {

// Signed solid angle of the spherical triangle (a, b, c) of unit vectors, positive when the
// vertices run counter-clockwise seen from outside (Van Oosterom & Strackee 1983:
// tan(Omega/2) = a.(b x c) / (1 + a.b + b.c + c.a)). The triple product is formed from the edge
// differences a.((b-a) x (c-a)), which keeps relative accuracy for tiny triangles.
double triangle_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c);

// Same, with the first vertex fixed at the pole (0,0,1) of a local frame and b, c given in that
// frame: the triple product is then b.x c.y - b.y c.x, exact to rounding whatever the triangle's
// size. This is what keeps spherical-ellipse strata 1e8 radii away measurable in double.
double pole_triangle_solid_angle(const Vec3& b, const Vec3& c);

// Signed solid angle enclosed by the closed polygon `ring` (local-frame unit vectors, last
// vertex joined to the first), as the fan of pole triangles. Valid for any simple polygon that
// stays in the open upper hemisphere z > 0 of the frame.
double polygon_solid_angle_local(const std::vector<Vec3>& ring);

// Solid angle of a region with a smooth closed boundary `boundary(t)`, t in [0,1), given in the
// local frame: the boundary is sampled with k, 2k, 4k, ... points (the chords' error falls as
// k^-2) and Richardson-extrapolated until two successive estimates agree to `rel_tol` relative
// (or `abs_tol`), at most `max_points` points. `error` receives the last difference.
struct RefinedSolidAngle {
  double value = 0.0;
  double error = 0.0;  // |difference of the last two extrapolated estimates|
  std::size_t points = 0;
};
RefinedSolidAngle refined_solid_angle(const std::function<Vec3(double)>& boundary, std::size_t k0,
                                      double rel_tol, double abs_tol, std::size_t max_points);

// Counts of 2D points in an n x n grid of [0,1)^2 (points on the upper edges go to the last
// cell); bins are row-major, index = iy * n + ix.
std::vector<double> grid_counts(const std::vector<Point2>& points, std::size_t n);

}  // namespace disklab::test
