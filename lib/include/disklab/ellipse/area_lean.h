#pragma once
// Area sampling as a renderer usually writes it: a concentric disk point in world space, the
// direction to it and the solid-angle density p(w) = |x - o|^2 / (A |cos theta_l|), A = pi r^2.
// Set-up per shading point is a copy of the light's precomputed frame and a plane test, so it
// costs about one sample. This is the cost baseline of bench_maps (issue 16).
//
// Against AreaSampler (area.h) it trades accuracy for set-up: the direction is formed from
// x - o in world coordinates, so its error is ~eps (|o| + |c| + r) / |x - o| rather than ~eps,
// and the density's cosine is that of the rounded direction (absolute error ~eps, relative
// eps / cos theta_l). Use AreaSampler where distant or grazing lights need full accuracy.
#include <cmath>
#include <limits>

#include "disklab/disk/common.h"
#include "disklab/ellipse/geometry.h"
#include "disklab/math/constants.h"
#include "disklab/math/frame.h"

namespace disklab::ellipse {

namespace detail {
// Shirley and Chiu's concentric map in two regions, the signed-radius form of pbrt-v4 and
// Mitsuba 3: with (a, b) = 2u - 1, the coordinate of larger magnitude is the signed radius and
// psi = (pi/4) (smaller / larger) lies in [-pi/4, pi/4]; the region decides whether the point is
// r (cos psi, sin psi) or r (sin psi, cos psi). The angle never leaves [-pi/4, pi/4], where
// std::sin and std::cos take their shortest path. u in [0,1]^2 (unchecked).
inline Point2 concentric_two_region(Point2 u) {
  const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0;
  if (std::abs(a) > std::abs(b)) {
    const double psi = disk::kQuarterPi * (b / a);
    return {a * std::cos(psi), a * std::sin(psi)};
  }
  if (b == 0.0) return {0.0, 0.0};  // the centre, a = b = 0
  const double psi = disk::kQuarterPi * (a / b);
  return {b * std::sin(psi), b * std::cos(psi)};
}
}  // namespace detail

// What the lean sampler returns: no ellipse frame, so no `local` direction.
struct LightSample {
  Vec3 direction = Vec3::Zero();  // unit vector from the shading point towards the disk
  Vec3 point = Vec3::Zero();      // where it meets the disk
  double pdf = 0.0;               // solid-angle density of `direction`
  bool valid = false;
};

// The per-light part, built once per light: unit normal and in-plane axes scaled by r.
struct LeanDiskLight {
  Vec3 center = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();                  // unit
  Vec3 t1 = Vec3::UnitX(), t2 = Vec3::UnitY();  // r times an orthonormal in-plane pair
  double inv_area = 0.0;                        // 1 / (pi r^2); 0 for a degenerate disk
  bool two_sided = false;

  static LeanDiskLight make(const Disk& disk) noexcept {
    LeanDiskLight l;
    l.center = disk.center;
    l.two_sided = disk.two_sided;
    const double nn = disk.normal.norm();
    const double area = math::kPi * disk.radius * disk.radius;
    if (!(nn > 0.0) || !std::isfinite(nn) || !(area > 0.0) || !std::isfinite(area) ||
        !disk.center.allFinite())
      return l;
    const math::Frame f = math::Frame::from_z(disk.normal / nn);
    l.normal = f.z;
    l.t1 = disk.radius * f.x;
    l.t2 = disk.radius * f.y;
    l.inv_area = 1.0 / area;
    return l;
  }
  bool valid() const { return inv_area > 0.0; }
};

struct LeanAreaSampler {
  const LeanDiskLight* light = nullptr;
  Vec3 o = Vec3::Zero();
  bool visible = false;  // o on the lit side of the disk's plane

  static LeanAreaSampler make(const LeanDiskLight& light, const Vec3& o) noexcept {
    LeanAreaSampler s;
    s.light = &light;
    s.o = o;
    const double h = (o - light.center).dot(light.normal);
    s.visible = light.valid() && o.allFinite() && (light.two_sided ? h != 0.0 : h > 0.0);
    return s;
  }
  bool valid() const { return visible; }

  // The concentric disk point (detail::concentric_two_region), the world point, the direction and
  // p(w) = |x - o|^2 / (A |cos theta_l|). Nothing is tested per sample but u and the finished
  // pdf: `visible` already excludes the degenerate lights and shading points.
  LightSample sample(Point2 u) const {
    LightSample out;
    if (!visible || !(u.x >= 0.0 && u.x <= 1.0 && u.y >= 0.0 && u.y <= 1.0)) return out;
    const Point2 d = detail::concentric_two_region(u);
    out.point = light->center + d.x * light->t1 + d.y * light->t2;
    const Vec3 v = out.point - o;
    const double dist2 = v.squaredNorm();
    out.direction = v / std::sqrt(dist2);
    out.pdf = dist2 * light->inv_area / std::abs(out.direction.dot(light->normal));
    // A distance that under- or overflows gives pdf 0, inf or NaN: no sample.
    if (!(out.pdf > 0.0 && out.pdf < std::numeric_limits<double>::infinity())) return {};
    out.valid = true;
    return out;
  }

  // Solid-angle density of any direction (for MIS): where the ray o + t w meets the disk,
  // t^2 / (A |cos theta_l|) for unit w; 0 where it misses.
  double pdf(const Vec3& direction) const {
    if (!visible) return 0.0;
    const double w2 = direction.squaredNorm();
    if (!(w2 > 0.0) || !std::isfinite(w2)) return 0.0;
    const Vec3 w = direction / std::sqrt(w2);
    const double den = w.dot(light->normal);
    const double h = (o - light->center).dot(light->normal);
    const double t = -h / den;  // ray parameter of the plane hit
    if (!(t > 0.0) || !std::isfinite(t)) return 0.0;
    const Vec3 off = o + t * w - light->center;
    const double r2 = light->t1.squaredNorm();
    if (off.squaredNorm() > r2) return 0.0;
    return t * t * light->inv_area / std::abs(den);
  }
};

}  // namespace disklab::ellipse
