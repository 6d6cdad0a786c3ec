#pragma once
// Scenes of the papers' studies: a disk light, opaque spheres, shading points on a receiver,
// and the irradiance integrand in the area measure of the light,
//   E(o) = int_disk L cos(theta_o) cos(theta_l) / d^2 V(o, x) dA(x).
// Everything here is plain geometry with exact visibility (segment-sphere tests); nothing uses
// the samplers under test, so references and estimators share only this description.
#include <string>
#include <vector>

#include "disklab/math/frame.h"
#include "disklab/types.h"

namespace disklab::study {

struct DiskLight {
  Vec3 center = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit; the emitting side of a one-sided light
  double radius = 1.0;
  bool two_sided = false;
  double radiance = 1.0;
  // In-plane axes (unit, orthogonal to the normal): unit-disk sample p sits at
  // center + radius (p.x axis_x + p.y axis_y).
  Vec3 axis_x = Vec3::UnitX();
  Vec3 axis_y = Vec3::UnitY();

  Vec3 point(Point2 p) const { return center + radius * (p.x * axis_x + p.y * axis_y); }
};

struct Sphere {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
};

struct Scene {
  DiskLight light;
  std::vector<Sphere> occluders;
};

struct ShadingPoint {
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit receiver normal
};

// A named grid of shading points: x = linspace(x0, x1, nx), y = linspace(y0, y1, ny) (endpoints
// included) on the receiver plane z = 0 with normal +z; points ordered x-major.
struct Region {
  std::string name;
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
  int nx = 4, ny = 4;
  std::vector<ShadingPoint> points() const;
};

// Does the closed segment from `from` to `to` meet any occluder? Closest approach of the
// segment to each centre, compared with the radius (touching counts as blocked).
inline bool occluded(const Scene& scene, const Vec3& from, const Vec3& to) {
  const Vec3 v = to - from;
  const double vv = v.squaredNorm();
  for (const Sphere& s : scene.occluders) {
    const Vec3 w = s.center - from;
    double t = vv > 0.0 ? w.dot(v) / vv : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    if ((w - t * v).squaredNorm() <= s.radius * s.radius) return true;
  }
  return false;
}

// The irradiance integrand at light point x (area measure): L cos_o cos_l / d^2, times V.
// cos_o is clamped at 0 (below the receiver's horizon); cos_l is 0 behind a one-sided light.
inline double irradiance_integrand(const Scene& scene, const ShadingPoint& sp, const Vec3& x) {
  const Vec3 v = x - sp.position;
  const double d2 = v.squaredNorm();
  if (!(d2 > 0.0)) return 0.0;
  const double cos_o_d = v.dot(sp.normal);      // d cos(theta_o)
  double cos_l_d = -v.dot(scene.light.normal);  // d cos(theta_l)
  if (scene.light.two_sided && cos_l_d < 0.0) cos_l_d = -cos_l_d;
  if (!(cos_o_d > 0.0) || !(cos_l_d > 0.0)) return 0.0;
  if (occluded(scene, sp.position, x)) return 0.0;
  return scene.light.radiance * cos_o_d * cos_l_d / (d2 * d2);
}

}  // namespace disklab::study
