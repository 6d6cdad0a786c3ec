#pragma once
// What the spherical-ellipse maps need from the geometry, in one place: a thin adapter over
// geometry.h (frame and shape, Guillén et al. 2017 Sec. 3 with the frame fix of DESIGN.md) and
// solid_angle.h (the cancellation-free cumulative solid angles of the radial and parallel maps).
//
// The maps' root finding uses the parametric angle s of the PLANAR projected ellipse,
// tan s = (a/b) tan phi, because there dOmega_r/ds = (1 - h_r) dphi/ds = a b / (1 + h_r) lies in
// [ab/2, ab] at every eccentricity (the planar sector element is r^2 dphi = a b ds). solid_angle.h
// works in the tangent ellipse's angle vphi of eq. (20), tan vphi = (a_t/b_t) tan phi; the two are
// related by tan vphi = (cos(beta)/cos(alpha)) tan s, one atan2.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "disklab/ellipse/geometry.h"
#include "disklab/ellipse/solid_angle.h"
#include "disklab/math/constants.h"
#include "disklab/types.h"

namespace disklab::ellipse {

struct MapGeometry {
  SphericalEllipse se;
  // Disk and shading point (copies of se's, kept for the samplers' readability).
  Vec3 o = Vec3::Zero(), c = Vec3::Zero(), n = Vec3::UnitZ();
  double radius = 0.0;
  // Ellipse frame R_e (x_e, y_e, z_e in world space).
  Vec3 xe = Vec3::UnitX(), ye = Vec3::UnitY(), ze = Vec3::UnitZ();
  double a = 0.0, b = 0.0;         // semi-axes, eq. (4); a along x_e, a >= b
  double alpha = 0.0, beta = 0.0;  // semi-arcs, eq. (5)
  double a_t = 0.0, b_t = 0.0;     // tangent-ellipse semi-axes
  double cos2_alpha = 1.0, cos2_beta = 1.0;
  double cos_alpha = 1.0, cos_beta = 1.0;
  // a^2 - b^2 = cos^2(beta) - cos^2(alpha) >= 0, from whichever form has the smaller rounding:
  // (a - b)(a + b) for small ellipses, the difference of the complements near the hemisphere.
  double a2_minus_b2 = 0.0;
  double quadrant = 0.0;  // Omega_r(pi/2), by the same function as Omega_r(phi)
  double omega = 0.0;     // solid angle of the disk (closed form, solid_angle.h)
  bool empty = true;

  // Never throws: invalid input (non-finite, zero normal, negative radius) gives an empty
  // geometry, which every sampler turns into "no sample".
  static MapGeometry make(const Vec3& center, const Vec3& normal, double radius, const Vec3& o) {
    MapGeometry g;
    if (!center.allFinite() || !normal.allFinite() || !o.allFinite() || !std::isfinite(radius) ||
        !(radius >= 0.0) || !(normal.squaredNorm() > 0.0))
      return g;
    try {
      g.se = make_spherical_ellipse(Disk{center, normal, radius, false}, o);
    } catch (const std::exception&) {
      return g;
    }
    const SphericalEllipse& se = g.se;
    if (se.empty || !(se.b > 0.0) || !(se.omega > 0.0) || !(se.quadrant > 0.0)) return g;
    g.o = se.origin;
    g.c = se.center;
    g.n = se.normal;
    g.radius = se.radius;
    g.xe = se.frame.x;
    g.ye = se.frame.y;
    g.ze = se.frame.z;
    g.a = se.a;
    g.b = se.b;
    g.alpha = se.alpha;
    g.beta = se.beta;
    g.a_t = se.a_t;
    g.b_t = se.b_t;
    g.cos2_alpha = se.one_minus_a2;
    g.cos2_beta = se.one_minus_b2;
    g.cos_alpha = std::sqrt(se.one_minus_a2);
    g.cos_beta = std::sqrt(se.one_minus_b2);
    g.a2_minus_b2 = std::max(
        0.0, g.a * g.a <= g.cos2_beta ? (g.a - g.b) * (g.a + g.b) : g.cos2_beta - g.cos2_alpha);
    g.quadrant = se.quadrant;
    g.omega = se.omega;
    g.empty = false;
    return g;
  }

  // 1 - h_r (eq. 17) as r^2 / (1 + sqrt(1 - r^2)), from sin/cos of the azimuth phi.
  double one_minus_hr(double sin_phi, double cos_phi) const {
    const double as = a * sin_phi, bc = b * cos_phi;
    const double den = as * as + bc * bc;
    const double r2 = (a * b) * (a * b) / den;
    const double one_minus_r2 = (as * as * cos2_beta + bc * bc * cos2_alpha) / den;
    return r2 / (1.0 + std::sqrt(std::max(0.0, one_minus_r2)));
  }
  double one_minus_hr(double phi) const { return one_minus_hr(std::sin(phi), std::cos(phi)); }

  // Omega_r (eq. 16/19) at the planar parametric angle s in [0, pi/2].
  double radial_sector_s(double s) const {
    const double vphi = std::atan2(cos_beta * std::sin(s), cos_alpha * std::cos(s));
    return radial_sector_parametric(se, vphi);
  }
  // Omega_r(phi), phi in [0, pi/2].
  double radial_sector(double phi) const { return ellipse::radial_sector(se, phi); }

  // h_p(phi_p), eq. (9), and Omega_p^+(phi_p), eqs. (8)/(11), phi_p in [0, beta].
  double hp(double phi_p) const { return h_p(se, phi_p); }
  double parallel_half(double phi_p) const { return parallel_half_sector(se, phi_p); }

  Vec3 to_world(const Vec3& local) const {
    return local.x() * xe + local.y() * ye + local.z() * ze;
  }
  Vec3 to_local(const Vec3& world) const { return {world.dot(xe), world.dot(ye), world.dot(ze)}; }

  // Where the ray from o along `dir` meets the disk plane.
  Vec3 hit(const Vec3& dir) const {
    const double den = dir.dot(n);
    const double t = (c - o).dot(n) / den;
    const Vec3 p = o + t * dir;
    return p.allFinite() ? p : c;
  }
};

}  // namespace disklab::ellipse
