#pragma once
// Random disk-and-point scenes for the geometry and solid-angle suites (geometry_*_test.cpp,
// solid_angle_*_test.cpp). A scene is drawn from a 64-bit seed (rapidcheck generates and prints
// the seed, so a failure replays with RC_PARAMS="reproduce=..."), from 1e-3 to 1e6 radii away,
// at any angle from the axis down to 3 degrees above the plane.
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>

#include "disklab/ellipse/geometry.h"
#include "disklab/math/constants.h"

namespace disklab::test {

struct Scene {
  ellipse::Disk disk;
  Vec3 point = Vec3::Zero();
  double distance = 0.0;  // |o - c| / r
  std::string describe() const {
    std::ostringstream s;
    s.precision(17);
    s << "{c=(" << disk.center.transpose() << ") n=(" << disk.normal.transpose()
      << ") r=" << disk.radius << (disk.two_sided ? " two-sided" : "") << " o=("
      << point.transpose() << ") |o-c|/r=" << distance << "}";
    return s.str();
  }
};

inline Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> N;
  Vec3 v;
  do
    v = Vec3(N(rng), N(rng), N(rng));
  while (v.norm() < 1e-3);
  return v.normalized();
}

// A visible scene (o in front of the lit face): the point is at distance r 10^U(lo, hi) from
// the centre, at an angle from the normal uniform in cosine over [sin(3 deg), 1].
inline Scene random_scene(uint64_t seed, double log10_lo = -3.0, double log10_hi = 6.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Scene s;
  s.disk.center = Vec3(20 * U(rng) - 10, 20 * U(rng) - 10, 20 * U(rng) - 10);
  const Vec3 n = random_unit(rng);
  s.disk.normal = n * std::exp2(2 * U(rng) - 1);  // the normal need not be unit
  s.disk.radius = std::exp2(10 * U(rng) - 5);
  s.disk.two_sided = U(rng) < 0.5;
  const double d = s.disk.radius * std::pow(10.0, log10_lo + (log10_hi - log10_lo) * U(rng));
  const double min_cos = std::sin(3.0 * math::kPi / 180.0);
  const double cos_t = min_cos + (1.0 - min_cos) * U(rng);
  // In-plane unit direction.
  Vec3 t = random_unit(rng);
  t = (t - t.dot(n) * n).normalized();
  const double sin_t = std::sqrt(1.0 - cos_t * cos_t);
  // Two-sided disks are seen from behind half the time.
  const double side = (s.disk.two_sided && U(rng) < 0.5) ? -1.0 : 1.0;
  s.point = s.disk.center + d * (side * cos_t * n + sin_t * t);
  s.distance = (s.point - s.disk.center).norm() / s.disk.radius;
  return s;
}

}  // namespace disklab::test
