#pragma once
// Planar geometry for the disk suites: areas computed independently of any map's Jacobian.
#include <cmath>
#include <cstddef>
#include <vector>

#include "disklab/math/constants.h"
#include "disklab/types.h"

namespace disklab::test {

inline double cross(Point2 a, Point2 b) {
  return a.x * b.y - a.y * b.x;
}
inline Point2 sub(Point2 a, Point2 b) {
  return {a.x - b.x, a.y - b.y};
}

struct AreaEstimate {
  double area = 0.0;
  double error = 0.0;  // the quadrature's own error estimate (sum over edges, Romberg)
  int max_level = 0;   // deepest refinement used: 2^level chords per edge
};

// Signed area between the image of the straight parameter segment uv0 -> uv1 under `map` and
// the chord joining the images of its ends: positive when the curve bulges to the right of the
// chord (outwards for a counter-clockwise boundary).
//
// Green's theorem on the boundary, discretised as polygons: with m = 2^k chords the polygon
// area is a midpoint-type sum whose error expands in even powers of 1/m for a smooth edge
// (Euler-Maclaurin), so Romberg extrapolation of the sequence k = 0, 1, 2, ... converges fast.
// Refinement stops when two successive diagonal Romberg values differ by less than `tol` (after
// a minimum level, so that a symmetric curve cannot stop early by accident); that difference is
// the reported error. Only map values are used: no derivative, no Jacobian.
template <class Map>
AreaEstimate edge_bulge_area(const Map& map, Point2 uv0, Point2 uv1, double tol) {
  constexpr int kMinLevel = 4;   // 16 chords before any convergence decision
  constexpr int kMaxLevel = 18;  // 262144 chords: never reached by the smooth maps tested
  std::vector<Point2> pts{map(uv0), map(uv1)};
  std::vector<double> prev_row, row;
  AreaEstimate est;
  for (int level = 0; level <= kMaxLevel; ++level) {
    if (level > 0) {  // insert the midpoints: 2^level chords
      const std::size_t m = pts.size() - 1;
      std::vector<Point2> next;
      next.reserve(2 * m + 1);
      for (std::size_t i = 0; i < m; ++i) {
        next.push_back(pts[i]);
        const double t = (2.0 * i + 1.0) / (2.0 * m);
        next.push_back(map(Point2{uv0.x + t * (uv1.x - uv0.x), uv0.y + t * (uv1.y - uv0.y)}));
      }
      next.push_back(pts.back());
      pts.swap(next);
    }
    // Fan from the first point: the polygon pts[0..m] closed by the chord.
    double d = 0.0;
    for (std::size_t i = 1; i + 1 < pts.size(); ++i)
      d += cross(sub(pts[i], pts[0]), sub(pts[i + 1], pts[0]));
    // The fan traverses the curve then returns along the chord: counter-clockwise (positive)
    // exactly when the curve bulges to the right of the chord, i.e. outwards.
    d *= 0.5;
    row.assign(1, d);
    double factor = 4.0;
    for (std::size_t j = 1; j <= prev_row.size(); ++j, factor *= 4.0)
      row.push_back(row[j - 1] + (row[j - 1] - prev_row[j - 1]) / (factor - 1.0));
    est.area = row.back();
    est.max_level = level;
    if (!prev_row.empty()) {
      est.error = std::fabs(row.back() - prev_row.back());
      if (level >= kMinLevel && est.error < tol) break;
    }
    prev_row.swap(row);
  }
  return est;
}

// Signed area of the image of the rectangle [u0,u1] x [v0,v1] under `map` (positive for an
// orientation-preserving map): the shoelace area of the four mapped corners plus the bulge of
// each mapped edge. `tol` is the absolute error allowed for the whole stratum.
template <class Map>
AreaEstimate stratum_image_area(const Map& map, double u0, double u1, double v0, double v1,
                                double tol) {
  const Point2 c[4] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};  // counter-clockwise
  Point2 p[4];
  for (int i = 0; i < 4; ++i)
    p[i] = map(c[i]);
  AreaEstimate total;
  total.area =
      0.5 * (cross(sub(p[1], p[0]), sub(p[2], p[0])) + cross(sub(p[2], p[0]), sub(p[3], p[0])));
  for (int i = 0; i < 4; ++i) {
    const AreaEstimate e = edge_bulge_area(map, c[i], c[(i + 1) % 4], tol / 4.0);
    total.area += e.area;
    total.error += e.error;
    total.max_level = std::max(total.max_level, e.max_level);
  }
  return total;
}

// Exact area of [x0,x1] x [y0,y1] intersected with the unit disk (x0 <= x1, y0 <= y1), from the
// antiderivative of sqrt(1 - x^2): the expected count of a chi-square bin, not a Monte Carlo
// estimate.
double disk_rect_area(double x0, double x1, double y0, double y1);

// NEGATIVE CONTROL, NOT UNIFORM. The seed blog's "polar" snippet (Whittle 2014):
// phi = 2 pi u, radius = v (no square root), so points crowd the centre with density
// 1 / (2 pi r). Kept only to show that the uniformity test has the power to reject it.
inline Point2 sample_polar_linear_radius_NOT_UNIFORM(Point2 uv) {
  const double phi = math::kTwoPi * uv.x;
  const double radius = uv.y;
  return {std::cos(phi) * radius, std::sin(phi) * radius};
}

}  // namespace disklab::test
