#pragma once
// Area sampling of the disk (the baseline of Guillén et al. 2017, Sec. 2 and Fig. 1a): a point
// uniform on the disk by Shirley and Chiu's concentric map, its density converted to solid angle,
//     p(w) = |o - x|^2 / (A(D) |w . n|),   A(D) = pi r^2.
// The local-frame direction is formed as R_e^T (c - o) + R_e^T (x - c): the small offset x - c is
// rotated on its own, so distant disks keep relative accuracy in the direction's x_e, y_e parts.
#include <algorithm>
#include <cmath>

#include "disklab/disk/concentric.h"
#include "disklab/ellipse/map_geometry.h"
#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/sampler.h"
#include "disklab/math/constants.h"

namespace disklab::ellipse {

struct AreaSampler {
  MapGeometry g;
  Vec3 e1 = Vec3::UnitX(), e2 = Vec3::UnitY();  // in-plane frame of the disk
  Vec3 center_local = Vec3::UnitZ();            // R_e^T (c - o)
  double inv_area = 0.0;

  static AreaSampler make(const Disk& disk, const Vec3& o) noexcept {
    AreaSampler s;
    s.g = MapGeometry::make(disk, o);
    if (s.g.empty) return s;
    s.e1 = s.g.frame.x;  // x_e = x_d lies in the disk plane
    s.e2 = s.g.normal.cross(s.e1);
    s.center_local = s.g.center_local();  // closed form: no eps |c - o| error across the axis
    s.inv_area = 1.0 / (math::kPi * s.g.radius * s.g.radius);
    return s;
  }
  bool valid() const { return !g.empty; }

  EllipseSample sample(Point2 u) const {
    if (g.empty) return {};
    const Point2 d = disk::sample_concentric(u);
    const Vec3 offset = g.radius * (d.x * e1 + d.y * e2);  // x - c
    Vec3 v = center_local + g.to_local(offset);            // R_e^T (x - o)
    const double dist2 = v.squaredNorm();
    const double dist = std::sqrt(dist2);
    EllipseSample out;
    out.local = v / dist;
    out.point = g.center + offset;
    out.direction = g.to_world(out.local).normalized();
    const double cos_light = std::abs(out.direction.dot(g.normal));
    out.pdf = cos_light > 0.0 ? dist2 * inv_area / cos_light : 0.0;
    out.valid = out.pdf > 0.0 && std::isfinite(out.pdf);
    return out;
  }

  // Solid-angle density of a direction: |o - x|^2 / (A |cos theta_l|) where it meets the disk,
  // 0 where it misses.
  double pdf(const Vec3& direction) const {
    if (!g.contains(direction)) return 0.0;
    const Vec3 d = direction.normalized();
    const double cos_light = std::abs(d.dot(g.normal));
    return cos_light > 0.0 ? (g.hit(d) - g.origin).squaredNorm() * inv_area / cos_light : 0.0;
  }

  // Direction -> (u, v) through the disk point and the inverse concentric map.
  Point2 invert(const Vec3& direction) const {
    if (g.empty) return {};
    const Vec3 off = g.hit(direction) - g.center;
    return disk::invert_concentric({off.dot(e1) / g.radius, off.dot(e2) / g.radius});
  }
};

}  // namespace disklab::ellipse
