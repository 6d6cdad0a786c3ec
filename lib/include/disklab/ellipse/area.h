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

  static AreaSampler make(const Disk& disk, const Vec3& o) noexcept {
    AreaSampler s;
    s.g = MapGeometry::make(disk, o);
    if (s.g.empty) return s;
    s.e1 = s.g.frame.x;  // x_e = x_d lies in the disk plane
    s.e2 = s.g.normal.cross(s.e1);
    s.center_local = s.g.center_local();  // closed form: no eps |c - o| error across the axis
    return s;
  }
  bool valid() const { return !g.empty; }

  // p(w) = |o - x|^2 / (pi r^2 cos theta_l) with cos theta_l = h / |o - x| (x on the disk's plane,
  // h = o's height above it, known to ~1 ulp): p = (|o - x| / r)^2 (|o - x| / h) / pi. The cosine
  // of the rounded unit direction would carry an absolute error ~eps, relative eps |o - x| / h;
  // and the ratios keep r^2 and |o - x|^2 from overflowing or underflowing (r up to ~1e308). A
  // density below the smallest double (a point of a huge disk right under o) is "no sample".
  double density_at_distance(double dist) const {
    return (dist / g.radius) * (dist / g.radius) * (dist / g.h) / math::kPi;
  }

  EllipseSample sample(Point2 u) const {
    if (g.empty || !in_unit_square(u)) return {};
    const Point2 d = disk::sample_concentric(u);
    const Vec3 offset = g.radius * (d.x * e1 + d.y * e2);  // x - c
    const Vec3 v = center_local + g.to_local(offset);      // R_e^T (x - o)
    const double vmax = v.cwiseAbs().maxCoeff();
    if (!(vmax > 0.0) || !std::isfinite(vmax)) return {};
    const double dist = vmax * (v / vmax).norm();
    EllipseSample out;
    out.local = unit_vector(v);
    out.point = g.center + offset;
    out.direction = unit_vector(g.to_world(out.local));
    out.pdf = density_at_distance(dist);
    out.valid = out.pdf > 0.0 && std::isfinite(out.pdf);
    if (!out.valid) out.pdf = 0.0;
    return out;
  }

  // Solid-angle density of a direction: |o - x|^2 / (A |cos theta_l|) where it meets the disk,
  // 0 where it misses; |o - x| = h / |cos theta_l| from the direction itself. Agrees with the
  // sample's pdf to ~3 kDirectionAbsError / cos theta_l relative: the cosine of a unit direction
  // is known to an absolute ~eps only (near the disk's plane that is the documented limit).
  double pdf(const Vec3& direction) const {
    if (!g.contains(direction)) return 0.0;
    const double cos_light = std::abs(unit_vector(direction).dot(g.normal));
    if (!(cos_light > 0.0)) return 0.0;
    const double p = density_at_distance(g.h / cos_light);
    return std::isfinite(p) ? p : 0.0;
  }

  // Direction -> (u, v) through the disk point and the inverse concentric map. The hit is found
  // in R_e, from the closed-form c - o and o's height: x - c = t l - R_e^T (c - o), t = h / (-l .
  // n). Its error is ~eps |x - o| / cos(theta_l) (the direction's own resolution: relative
  // eps d / (r cos theta_l) of the disk), independent of where the scene sits in world space (a
  // world-space intersection would add eps |o| and eps |c|). Where it reaches the disk's size
  // (points within ~eps d of the disk's plane) the direction does not determine the hit, nor u.
  Point2 invert(const Vec3& direction) const {
    if (g.empty) return {};
    const Vec3 l = g.to_local(unit_vector(direction));
    const Vec3 n_local = g.to_local(g.normal);
    const double den = -l.dot(n_local);
    if (!(den > 0.0)) return {};
    const Vec3 off = (g.h / den) * l - center_local;  // R_e^T (x - c)
    const double ux = off.dot(g.to_local(e1)) / g.radius, uy = off.dot(g.to_local(e2)) / g.radius;
    return disk::invert_concentric({ux, uy});
  }
};

}  // namespace disklab::ellipse
