#pragma once
// What the spherical-ellipse maps need from the geometry, in one place: a thin adapter over
// geometry.h (frame and shape, Guillén et al. 2017 Sec. 3 with the frame fix of docs/design.md) and
// solid_angle.h (the cancellation-free cumulative solid angles of the radial and parallel maps).
//
// The maps' root finding uses the parametric angle s of the PLANAR projected ellipse,
// tan s = (a/b) tan phi, because there dOmega_r/ds = (1 - h_r) dphi/ds = a b / (1 + h_r) lies in
// [ab/2, ab] at every eccentricity (the planar sector element is r^2 dphi = a b ds). solid_angle.h
// works in the tangent ellipse's angle vphi of eq. (20), tan vphi = (a_t/b_t) tan phi; the two are
// related by tan vphi = (cos(beta)/cos(alpha)) tan s, one atan2.
#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "disklab/ellipse/geometry.h"
#include "disklab/ellipse/sampler.h"
#include "disklab/ellipse/solid_angle.h"
#include "disklab/math/constants.h"
#include "disklab/types.h"

namespace disklab::ellipse {

// A direction within this relative slack of the rim counts as inside (contains()): directions
// read back from %.17g text, or produced on the rim (eps2 = 1), lie within a few ulps of it.
inline constexpr double kRimSlack = 1e-9;
// The local-frame coordinates of a unit world direction carry an absolute error of a few eps (the
// rotation to and from R_e): contains() also accepts what lies within kDirectionAbsError of the
// ellipse to first order. This is the resolution of any unit direction: a disk seen edge-on
// (from within ~eps d of its plane) cannot be hit better than that.
inline constexpr double kDirectionAbsError = 16 * std::numeric_limits<double>::epsilon();

// The shape, frame and solid angle once (the SphericalEllipse base), plus the few derived numbers
// the root solves read on every sample.
struct MapGeometry : SphericalEllipse {
  double cos_alpha = 1.0, cos_beta = 1.0;
  // a^2 - b^2 = cos^2(beta) - cos^2(alpha) >= 0, from whichever form has the smaller rounding:
  // (a - b)(a + b) for small ellipses, the difference of the complements near the hemisphere.
  double a2_minus_b2 = 0.0;

  // Never throws, never allocates: invalid input (non-finite, zero normal, negative radius) and
  // what sees nothing give an empty geometry, which every sampler turns into "no sample".
  static MapGeometry make(const Disk& disk, const Vec3& o) noexcept {
    MapGeometry g = make_shape(disk, o);
    g.finish_totals(0.0);
    return g;
  }
  // The same in two steps, for samplers that know the quadrant more cheaply than solid_angle.h:
  // make_shape leaves omega and quadrant at 0 (spherical_ellipse_shape), finish_totals(q) sets
  // them from a quadrant q > 0 (omega = 4 q) or, for q <= 0, computes them as make does.
  static MapGeometry make_shape(const Disk& disk, const Vec3& o) noexcept {
    MapGeometry g;
    static_cast<SphericalEllipse&>(g) = spherical_ellipse_shape(disk, o);
    if (g.empty) return g;
    if (!(g.b > 0.0)) {
      g.empty = true;
      return g;
    }
    g.cos_alpha = std::sqrt(g.one_minus_a2);
    g.cos_beta = std::sqrt(g.one_minus_b2);
    g.a2_minus_b2 = std::max(0.0, g.a * g.a <= g.one_minus_b2 ? (g.a - g.b) * (g.a + g.b)
                                                              : g.one_minus_b2 - g.one_minus_a2);
    return g;
  }
  void finish_totals(double quadrant_known) noexcept {
    if (empty) return;
    if (quadrant_known > 0.0)
      set_totals(*this, quadrant_known);
    else
      compute_totals(*this);
    // A solid angle below the smallest normal double (seen from ~1e150 radii away) has a density
    // 1/Omega that overflows: no sampler can report it, so there is nothing to sample.
    if (!(omega >= std::numeric_limits<double>::min())) empty = true;
  }

  // h_r (eq. 17) and 1 - h_r, the radial map's segment, in the two angles the maps use:
  //  - the azimuth phi (its sine and cosine): 1 - h_r = r^2 / (1 + sqrt(1 - r^2)) with
  //    solid_angle.h's radius of eq. (18);
  //  - the planar parametric angle s (cs, ss): r^2 = a^2 cs^2 + b^2 ss^2 and
  //    1 - r^2 = cos^2(alpha) cs^2 + cos^2(beta) ss^2, both from positive terms.
  double one_minus_hr(double sin_phi, double cos_phi) const {
    return one_minus_h_r(*this, sin_phi, cos_phi);
  }
  double one_minus_hr(double phi) const { return one_minus_hr(std::sin(phi), std::cos(phi)); }
  double hr_parametric(double cs, double ss) const {
    return std::sqrt(std::max(0.0, one_minus_a2 * cs * cs + one_minus_b2 * ss * ss));
  }
  double one_minus_hr_parametric(double cs, double ss) const {
    return (a * a * cs * cs + b * b * ss * ss) / (1.0 + hr_parametric(cs, ss));
  }

  // Omega_r (eq. 16/19) at the planar parametric angle s in [0, pi/2].
  double radial_sector_s(double s) const {
    // vphi and its complement from the same sine and cosine (see radial_sector_parametric).
    const double x = cos_alpha * std::cos(s), y = cos_beta * std::sin(s);
    return radial_sector_parametric(*this, std::atan2(y, x), std::atan2(x, y));
  }
  // Omega_r(phi), phi in [0, pi/2].
  double radial_sector(double phi) const { return ellipse::radial_sector(*this, phi); }

  // h_p(phi_p), eq. (9), and Omega_p^+(phi_p), eqs. (8)/(11), phi_p in [0, beta].
  double hp(double phi_p) const { return h_p(*this, phi_p); }
  double parallel_half(double phi_p) const { return parallel_half_sector(*this, phi_p); }

  // Whether the ray from o along `direction` (any length) meets the disk: inside the spherical
  // ellipse, z_e > 0 and F = (x/a_t)^2 + (y/b_t)^2 - z^2 <= 0 (its gnomonic image is the tangent
  // ellipse), with two slacks: z^2 ((1 + kRimSlack)^2 - 1) (relative, the rim) and the most an
  // absolute error delta = kDirectionAbsError of the unit direction can change F: F is quadratic,
  // so |grad F| delta + delta^2 max(1, 1/a_t^2, 1/b_t^2) bounds it exactly (for distant disks
  // ~eps / b_t relative, for points near the disk's plane ~eps / z).
  bool contains(const Vec3& direction) const {
    if (empty || !direction.allFinite()) return false;
    const Vec3 unit = unit_vector(direction);
    if (!(unit.squaredNorm() > 0.0)) return false;
    const Vec3 l = to_local(unit);
    // z_e > 0 up to the same absolute error: near-hemisphere ellipses reach the horizon z = 0.
    if (!(l.z() > -kDirectionAbsError)) return false;
    // Everything multiplied by b_t^2 (b_t <= a_t), so that slivers with b_t ~ 1e-300 neither
    // overflow nor lose the slack: F b_t^2 = (x b_t/a_t)^2 + y^2 - (z b_t)^2, and the bound's
    // terms scale alike.
    const double ratio = b_t / a_t, zb = l.z() * b_t;
    const double xr = l.x() * ratio;
    const double f = xr * xr + l.y() * l.y() - zb * zb;
    const double grad = 2.0 * std::hypot(xr * ratio, l.y(), zb * b_t);
    const double rel = (1.0 + kRimSlack) * (1.0 + kRimSlack) - 1.0;
    const double curv = std::max(1.0, b_t * b_t);
    return f <= zb * zb * rel + grad * kDirectionAbsError +
                    curv * kDirectionAbsError * kDirectionAbsError;
  }

  // Where the ray from o along `dir` meets the disk plane.
  Vec3 hit(const Vec3& dir) const {
    const double den = dir.dot(normal);
    const double t = (center - origin).dot(normal) / den;
    const Vec3 p = origin + t * dir;
    return p.allFinite() ? p : center;
  }
};

}  // namespace disklab::ellipse
