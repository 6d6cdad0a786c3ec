#include "support/spherical.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace disklab::test {

double triangle_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double triple = a.dot((b - a).cross(c - a));
  const double denom = 1.0 + a.dot(b) + b.dot(c) + c.dot(a);
  return 2.0 * std::atan2(triple, denom);
}

double pole_triangle_solid_angle(const Vec3& b, const Vec3& c) {
  const double triple = b.x() * c.y() - b.y() * c.x();
  const double denom = 1.0 + b.z() + c.z() + b.dot(c);
  return 2.0 * std::atan2(triple, denom);
}

double polygon_solid_angle_local(const std::vector<Vec3>& ring) {
  double sum = 0.0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
    sum += pole_triangle_solid_angle(ring[i], ring[(i + 1) % n]);
  return sum;
}

RefinedSolidAngle refined_solid_angle(const std::function<Vec3(double)>& boundary, std::size_t k0,
                                      double rel_tol, double abs_tol, std::size_t max_points) {
  // Each refinement doubles the points and reuses the previous ones (the new points are the
  // midpoints in the parameter).
  std::size_t k = std::max<std::size_t>(k0, 4);
  std::vector<Vec3> ring(k);
  for (std::size_t i = 0; i < k; ++i)
    ring[i] = boundary(static_cast<double>(i) / k);
  auto refine = [&]() {
    std::vector<Vec3> finer(2 * k);
    for (std::size_t i = 0; i < k; ++i) {
      finer[2 * i] = ring[i];
      finer[2 * i + 1] = boundary((i + 0.5) / k);
    }
    ring.swap(finer);
    k *= 2;
  };
  RefinedSolidAngle out;
  double coarse = polygon_solid_angle_local(ring);
  double previous_extrapolated = coarse;
  bool have_previous = false;
  while (true) {
    refine();
    const double fine = polygon_solid_angle_local(ring);
    // The chord error is c k^-2 + O(k^-4) for a smooth boundary: eliminate the k^-2 term.
    const double extrapolated = (4.0 * fine - coarse) / 3.0;
    out.value = extrapolated;
    out.points = k;
    if (have_previous) {
      out.error = std::abs(extrapolated - previous_extrapolated);
      if (out.error <= std::max(rel_tol * std::abs(extrapolated), abs_tol)) return out;
    }
    if (2 * k > max_points) {
      if (!have_previous) out.error = std::abs(fine - coarse);
      return out;
    }
    previous_extrapolated = extrapolated;
    have_previous = true;
    coarse = fine;
  }
}

std::vector<double> grid_counts(const std::vector<Point2>& points, std::size_t n) {
  std::vector<double> counts(n * n, 0.0);
  const double scale = static_cast<double>(n);
  for (const Point2& p : points) {
    const auto ix =
        std::min<std::size_t>(n - 1, static_cast<std::size_t>(std::max(0.0, p.x * scale)));
    const auto iy =
        std::min<std::size_t>(n - 1, static_cast<std::size_t>(std::max(0.0, p.y * scale)));
    counts[iy * n + ix] += 1.0;
  }
  return counts;
}

}  // namespace disklab::test
