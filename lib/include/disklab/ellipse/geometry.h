#pragma once
// The spherical ellipse subtended by a disk at a shading point (Guillén et al. 2017, Sec. 3,
// eqs. 3-5, 10, 12, 20), with the corrections of docs/design.md section 3.
//
// LIT SIDE. The disk emits towards +normal. With z_d = -n (eq. 3), a point o sees the front face
// when the disk lies ahead of it along z_d, i.e. when h = (o - c) . n > 0. A one-sided disk seen
// from h <= 0 is empty (Omega = 0); a two-sided disk is mirrored (n -> -n) so that h = |h|; any
// disk seen from its own plane (h == 0) is empty.
//
// FRAMES. R_d (eq. 3 with x and y swapped, docs/design.md): z_d = -n (of the lit face),
// x_d = normalize(z_d x (c - o)), y_d = z_d x x_d. Then the disk centre is at (0, -e, h) in R_d
// with e >= 0 its in-plane offset from the foot of o, and the tilt runs along y_d. On axis
// (e == 0) x_d is any unit vector in the plane. R_e = (x_e, y_e, z_e): x_e = x_d,
// z_e = the ellipse centre, y_e = z_e x x_e (both frames are right-handed).
//
// CLOSED FORMS (derived here, checked against the construction of eqs. 3-5 by the tests). The
// cone from o through the rim is h^2 X^2 + (h Y + e Z)^2 = r^2 Z^2 in R_d. Its principal axes give,
// with Q = h^2 + e^2 - r^2, S = sqrt(Q^2 + 4 r^2 h^2) and K = Q + S (> 0 for h > 0, formed as
// 4 r^2 h^2 / (S - Q) when Q < 0 so that it never cancels):
//     a_t = r sqrt(2 / K),  b_t = 2 r h / K,           (tangent semi-axes, a_t >= b_t)
//     a = r sqrt(2 / (K + 2 r^2)), b = r h sqrt(2 / (S K)),   1 - a^2 = K / (K + 2 r^2),
//     1 - b^2 = K / (2 S),  m = 1 - (1 - m),  1 - m = 2 S / (K + 2 r^2)     (eqs. 10 and 20),
//     n_r = (S - P) / K, 1 - n_r = 2 h^2 / K with P = h^2 + r^2 - e^2     (eq. 20),
//     z_e ~ (0, -e, h (1 + 2 r^2 / K)) in R_d.
// Every quantity is a product/quotient of positive terms: no cancellation at any distance
// (S - P is formed as 4 e^2 h^2 / (S + P) when P > 0). a_t >= b_t follows from S >= P.
#include <cmath>
#include <limits>

#include "disklab/math/frame.h"
#include "disklab/types.h"

namespace disklab::ellipse {

// A disk light: centre, normal (any non-zero length; the front face is the +normal side),
// radius >= 0, and whether it emits from both faces.
struct Disk {
  Vec3 center = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  double radius = 1.0;
  bool two_sided = false;
};

// Everything the solid angle and the maps need at one shading point. Built once per shading
// point by make_spherical_ellipse (not a hot path); read-only afterwards.
struct SphericalEllipse {
  // True when the disk is invisible from o (behind a one-sided disk, in its plane, radius 0):
  // then omega == quadrant == 0 and the other members keep their defaults.
  bool empty = true;

  // Scene, in the disk's own terms.
  Vec3 origin = Vec3::Zero();   // the shading point o
  Vec3 center = Vec3::Zero();   // disk centre c
  Vec3 normal = Vec3::UnitZ();  // unit normal of the face o sees (= -z_d)
  double radius = 0.0;          // r
  double h = 0.0;               // height of o above the lit face, > 0 unless empty
  double e = 0.0;               // in-plane distance from the foot of o to c, >= 0

  math::Frame frame;  // R_e = (x_e, y_e, z_e): x_e = x_d, z_e = ellipse centre

  // Shape (Sec. 3): semi-arcs alpha >= beta (eq. 5), planar semi-axes a = sin(alpha) >= b =
  // sin(beta) (eq. 4, the ellipse projected on the x_e y_e plane, a along x_e), tangent-ellipse
  // semi-axes a_t = tan(alpha) >= b_t = tan(beta).
  double a = 0.0, b = 0.0;
  double alpha = 0.0, beta = 0.0;
  double a_t = 0.0, b_t = 0.0;
  double one_minus_a2 = 1.0;  // 1 - a^2 = cos^2(alpha), without cancellation
  double one_minus_b2 = 1.0;  // 1 - b^2 = cos^2(beta)

  // Elliptic parameters. m is the same number in eq. (10) (parallel) and eq. (20) (radial):
  // m = (a_t^2 - b_t^2)/(a_t^2 + 1) = (a^2 - b^2)/(1 - b^2).
  double m = 0.0, one_minus_m = 1.0;
  double n_r = 0.0, one_minus_n_r = 1.0;  // radial characteristic n of eq. (20) and 1 - n
  double radial_coefficient = 0.0;        // eq. (19): b (1 - a^2) / (a sqrt(1 - b^2)) (= a h / r)
  // Eq. (10)'s c_t = a_t / sqrt(1 + a_t^2) is the planar semi-axis a itself.
  double n_p() const { return -b_t * b_t; }  // parallel characteristic n = -b_t^2 of eq. (12)

  // Solid angle of the disk (production, cancellation-free, see solid_angle.h) and the radial
  // quadrant Omega_r(pi/2) evaluated by the same function as Omega_r(phi) (radial_sector), so
  // that Omega_r(phi) / quadrant reaches exactly 1 at phi = pi/2: use it for eq. (21).
  double omega = 0.0;
  double quadrant = 0.0;

  // Parametric angle (eq. 20 variable) below which the radial sector uses eq. (19) and above
  // which Gauss-Legendre (solid_angle.h); 0 when Gauss covers everything, pi/2 when eq. (19) does.
  double radial_split = 0.0;

  // World direction of local coordinates in R_e, and back.
  Vec3 to_world(const Vec3& local) const { return frame.to_world(local); }
  Vec3 to_local(const Vec3& world) const { return frame.to_local(world); }

  // R_d = (x_d, y_d, z_d), eq. (3) with x and y swapped (docs/design.md): z_d = -normal, x_d = x_e,
  // y_d = z_d x x_d.
  math::Frame disk_frame() const {
    math::Frame f;
    f.z = -normal;
    f.x = frame.x;
    f.y = f.z.cross(f.x);
    return f;
  }
  // c - o in R_e, from the scalars (0, -e h a_t^2, e^2 + h^2 (1 + a_t^2)) / |(e, h (1 + a_t^2))|:
  // exact to a few ulps of each component. Projecting the world vector c - o onto x_e, y_e
  // instead carries an absolute error ~eps |c - o|, i.e. relative ~eps |c - o| / r of the
  // ellipse's size: 1e-8 at 1e8 radii.
  // The frame comes from the shape at a height h_s that differs from h only under the disk or
  // above its rim closer than kMinShapeHeight radii (shape_raised()):
  // k = h_s (1 + a_t^2), c - o = (0, -e (h_s a_t^2 + (h_s - h)), e^2 + k h) / |(e, k)|.
  // Lengths are first scaled by a power of two near 1/r (exact), so that k cannot overflow for
  // huge disks seen from close by (a_t^2 ~ 1e300 there), and h_s is formed in those units: as
  // kMinShapeHeight r it would be subnormal for r below ~1e-158, ~1e-11 off the shape's.
  Vec3 center_local() const {
    if (empty) return Vec3::UnitZ();
    const int p = std::ilogb(radius);
    const double hh = std::ldexp(h, -p), ee = std::ldexp(e, -p);
    const double hs = shape_raised() ? kMinShapeHeight * std::ldexp(radius, -p) : hh;
    const double k = hs * (1.0 + a_t * a_t), zn = std::hypot(ee, k);
    const Vec3 l(0.0, -(ee / zn) * (hs * (a_t * a_t) + (hs - hh)), (ee / zn) * ee + (k / zn) * hh);
    return {0.0, std::ldexp(l.y(), p), std::ldexp(l.z(), p)};
  }
  // Whether the shape (a, b, the frame) is computed for h raised to kMinShapeHeight r: under the
  // disk and above its rim (e <= r), where a smaller height changes Omega by less than rounding
  // but would overflow a_t^2 or reach subnormal terms. ellipse_shape raises it by the same test.
  bool shape_raised() const { return raises_height(h / radius, e / radius); }
  // The test, on h and e in units of r.
  static bool raises_height(double h_r, double e_r) { return e_r <= 1.0 && h_r < kMinShapeHeight; }
  static constexpr double kMinShapeHeight = 1e-150;
};

// Builds the spherical ellipse of `disk` seen from `o`.
// Throws std::invalid_argument for non-finite input, a zero normal or a negative radius.
// Defined answers: radius 0 (or subnormal), o in the disk's plane, o behind a one-sided disk ->
// empty.
SphericalEllipse make_spherical_ellipse(const Disk& disk, const Vec3& o);
// The same without exceptions: invalid input also gives an empty ellipse (for the samplers'
// set-up, which renderers may build with -fno-exceptions).
SphericalEllipse spherical_ellipse(const Disk& disk, const Vec3& o) noexcept;
// The same without the totals (omega and quadrant stay 0, `empty` false when o sees the disk):
// for samplers that obtain them more cheaply (the radial maps' series). Complete it with
// set_totals or compute_totals before anything reads omega or quadrant.
SphericalEllipse spherical_ellipse_shape(const Disk& disk, const Vec3& o) noexcept;
// The totals of a spherical_ellipse_shape result by solid_angle.h (what spherical_ellipse does).
void compute_totals(SphericalEllipse& se) noexcept;
// The totals from a quadrant Omega_r(pi/2) known otherwise: omega = 4 quadrant (at most 2 pi).
// Either makes the ellipse empty when the totals are not positive and finite.
void set_totals(SphericalEllipse& se, double quadrant) noexcept;
// Whether make_spherical_ellipse accepts the input (finite, non-zero normal, radius >= 0).
bool valid_disk_input(const Disk& disk, const Vec3& o) noexcept;

// The shape alone from the scalar scene (h > 0, e >= 0, r > 0): fills a, b, alpha, beta, a_t, b_t,
// the complements, m, n and the coefficients, and the directions of z_e in R_d as (0, y, z)
// (y = ze_y, z = ze_z). Used by make_spherical_ellipse; exposed for tests and tools.
struct EllipseShape {
  double a, b, alpha, beta, a_t, b_t, one_minus_a2, one_minus_b2;
  double m, one_minus_m, n_r, one_minus_n_r, c_t, radial_coefficient;
  double ze_y, ze_z;
};
EllipseShape ellipse_shape(double h, double e, double r);

}  // namespace disklab::ellipse
