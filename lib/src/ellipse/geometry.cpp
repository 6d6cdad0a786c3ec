// Set-up of the spherical ellipse (Guillén et al. 2017, Sec. 3); see geometry.h for the closed
// forms and solid_angle.h for the solid angle.
#include "disklab/ellipse/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "disklab/ellipse/solid_angle.h"
#include "disklab/math/constants.h"

namespace disklab::ellipse {
namespace {

// Error-free transformations (Knuth's TwoSum, fma TwoProd) for the height of o above the plane:
// h decides what o sees and, for grazing points, sets Omega almost proportionally, so it is
// formed to ~1 ulp from the inputs (Ogita-Rump-Oishi Dot2 over the exact differences c - o).
inline void two_sum(double a, double b, double& s, double& err) {
  s = a + b;
  const double bb = s - a;
  err = (a - (s - bb)) + (b - bb);
}

// (p - q) . n with p - q formed exactly.
double height_dot(const Vec3& p, const Vec3& q, const Vec3& n) {
  double sum = 0.0, comp = 0.0;
  for (int i = 0; i < 3; ++i) {
    double v_hi, v_lo;
    two_sum(p[i], -q[i], v_hi, v_lo);
    const double p = v_hi * n[i];
    const double p_err = std::fma(v_hi, n[i], -p);
    double s, s_err;
    two_sum(sum, p, s, s_err);
    sum = s;
    comp += s_err + p_err + v_lo * n[i];
  }
  return sum + comp;
}

// The normal scaled by a power of two (exactly, component by component) so that its largest
// component lies in [1, 2): |n|^2 then neither underflows nor overflows for any finite non-zero
// normal (lengths from the smallest subnormal to ~1e308), and for ordinary lengths every number
// derived from it (unit normal, height) is bit for bit the one the unscaled normal gives.
Vec3 scaled_normal(const Vec3& n) {
  const double m = n.cwiseAbs().maxCoeff();
  if (!(m > 0.0) || !std::isfinite(m)) return n;
  // Ordinary lengths: scaling by a power of two would change no number derived from n (see
  // above), so it is skipped (ilogb and ldexp are library calls on the set-up's path).
  if (m >= 0x1p-500 && m <= 0x1p500) return n;
  const int k = std::ilogb(m);
  return {std::ldexp(n.x(), -k), std::ldexp(n.y(), -k), std::ldexp(n.z(), -k)};
}

}  // namespace

EllipseShape ellipse_shape(double h, double e, double r) {
  EllipseShape s{};
  // The shape depends on h/r and e/r only: work with r = 1 so that lengths near 1e+-200 cannot
  // overflow or underflow in the squares below (a_t ~ r/h would otherwise lose the disk).
  h /= r;
  e /= r;
  r = 1.0;
  // Under the disk (e < r) and closer than 1e-150 radii, a_t ~ sqrt(r^2 - e^2)/h would overflow in
  // a_t^2; Omega there equals 2 pi - O(h/r) = 2 pi in double, as it does at h = 1e-150 r. Exactly
  // above the rim (e == r) Omega = pi - O(sqrt(h/r)), pi in double at h = 1e-150 r, while below it
  // the terms that scale like h (1 - a^2, C = a h / r) reach the subnormal range and lose the
  // limit. (For e > r, a_t stays below ~sqrt(r/h) and Omega ~ h: no clamp, it keeps the true
  // scale.)
  if (SphericalEllipse::raises_height(h, e)) h = SphericalEllipse::kMinShapeHeight;
  // Cone principal axes (geometry.h): Q = h^2 + e^2 - r^2, S = sqrt(Q^2 + 4 r^2 h^2), K = Q + S.
  const double two_rh = 2.0 * r * h;
  const double Q = std::fma(h, h, (e - r) * (e + r));
  const double S = std::hypot(Q, two_rh);
  // Q < 0 (o inside the sphere through the rim): Q + S cancels; K = 4 r^2 h^2 / (S - Q) instead.
  const double K = Q >= 0.0 ? Q + S : two_rh * (two_rh / (S - Q));
  // S - P, P = h^2 + r^2 - e^2: for P > 0 it cancels far away; S^2 - P^2 = 4 e^2 h^2.
  const double P = std::fma(h, h, (r - e) * (r + e));
  const double two_eh = 2.0 * e * h;
  const double S_minus_P = P <= 0.0 ? S - P : two_eh * (two_eh / (S + P));

  s.a_t = r * std::sqrt(2.0 / K);
  s.b_t = two_rh / K;
  s.alpha = std::atan(s.a_t);
  s.beta = std::atan(s.b_t);
  const double ha = std::hypot(1.0, s.a_t), hb = std::hypot(1.0, s.b_t);
  s.a = s.a_t / ha;  // sin(atan x) = x / sqrt(1 + x^2)
  s.b = s.b_t / hb;
  s.one_minus_a2 = (1.0 / ha) / ha;
  s.one_minus_b2 = (1.0 / hb) / hb;
  // n_r = (a^2 - b^2) / (a^2 (1 - b^2)) = (S - P) / K, 1 - n_r = 2 h^2 / K = (a_t h / r)^2,
  // m = a^2 n_r, 1 - m = (1 + b_t^2) / (1 + a_t^2) (eqs. 10 and 20 coincide).
  s.n_r = S_minus_P / K;
  const double ath = s.a_t * (h / r);
  s.one_minus_n_r = ath * ath;
  s.m = s.a * s.a * s.n_r;
  // b_t <= a_t, so 1 - m <= 1; on the axis (a_t == b_t) the two roundings can exceed it by ulps.
  s.one_minus_m = std::min(1.0, (hb / ha) * (hb / ha));
  s.c_t = s.a;
  s.radial_coefficient = s.a * (h / r);  // eq. (19): b (1 - a^2) / (a sqrt(1 - b^2)) = a h / r
  // Ellipse centre: eigenvector of the cone's negative eigenvalue, (0, -e, h (1 + 2 r^2/K)).
  const double zy = -e, zz = h * (1.0 + s.a_t * s.a_t);
  const double zn = std::hypot(zy, zz);
  s.ze_y = zy / zn;
  s.ze_z = zz / zn;
  return s;
}

bool valid_disk_input(const Disk& disk, const Vec3& o) noexcept {
  if (!disk.center.allFinite() || !disk.normal.allFinite() || !o.allFinite()) return false;
  if (!std::isfinite(disk.radius) || disk.radius < 0.0) return false;
  const double nn = scaled_normal(disk.normal).norm();
  return nn > 0.0 && std::isfinite(nn);
}

SphericalEllipse make_spherical_ellipse(const Disk& disk, const Vec3& o) {
  if (!disk.center.allFinite())
    throw std::invalid_argument("spherical ellipse: non-finite disk centre");
  if (!disk.normal.allFinite())
    throw std::invalid_argument("spherical ellipse: non-finite disk normal");
  if (!o.allFinite()) throw std::invalid_argument("spherical ellipse: non-finite shading point");
  if (!std::isfinite(disk.radius))
    throw std::invalid_argument("spherical ellipse: non-finite radius");
  if (disk.radius < 0.0) throw std::invalid_argument("spherical ellipse: negative radius");
  if (!valid_disk_input(disk, o)) throw std::invalid_argument("spherical ellipse: zero normal");
  return spherical_ellipse(disk, o);
}

SphericalEllipse spherical_ellipse_shape(const Disk& disk, const Vec3& o) noexcept {
  if (!valid_disk_input(disk, o)) return {};
  const Vec3 normal = scaled_normal(disk.normal);
  const double nn = normal.norm();
  SphericalEllipse se;
  se.origin = o;
  se.center = disk.center;
  se.radius = disk.radius;
  Vec3 n = normal / nn;
  se.normal = n;
  // A subnormal radius carries fewer than 52 bits, as do the coordinates of a disk that small
  // seen from close enough to see it: below the smallest normal double the disk is taken as a
  // point, like radius 0 (its directions would miss it by up to ~1e-3).
  if (disk.radius < std::numeric_limits<double>::min()) return se;

  // Height of o above the front face (eq. 3's z_d = -n puts the disk at z_d > 0 iff h > 0).
  double h = height_dot(o, disk.center, normal) / nn;  // (o - c) . n
  if (h == 0.0) return se;                             // in the plane: sees the disk edge-on
  if (h < 0.0) {
    if (!disk.two_sided) return se;  // behind a one-sided disk
    h = -h;
    n = -n;
  }
  se.normal = n;
  // c - o divided by its largest component: its norm's squares neither overflow nor underflow
  // at lengths near 1e+-300 (e and the frame only need its direction and length).
  const Vec3 v = disk.center - o;
  const double v_max = v.cwiseAbs().maxCoeff();  // > 0: h != 0
  const Vec3 v_unit_max = v / v_max;
  const Vec3 zd = -n;
  const double e = v_unit_max.cross(n).norm() * v_max;

  // Eq. (3) with x and y swapped (docs/design.md section 3): x_d = normalize(z_d x (c - o)).
  const math::Frame disk_frame = math::Frame::from_zx(zd, zd.cross(v_unit_max));
  const EllipseShape s = ellipse_shape(h, e, disk.radius);
  if (!(s.a_t > 0.0) || !std::isfinite(s.a_t) || !(s.b_t > 0.0) || !std::isfinite(s.b_t))
    return se;  // under/overflow at absurd scales: nothing measurable

  se.h = h;
  se.e = e;
  se.a = s.a;
  se.b = s.b;
  se.alpha = s.alpha;
  se.beta = s.beta;
  se.a_t = s.a_t;
  se.b_t = s.b_t;
  se.one_minus_a2 = s.one_minus_a2;
  se.one_minus_b2 = s.one_minus_b2;
  se.m = s.m;
  se.one_minus_m = s.one_minus_m;
  se.n_r = s.n_r;
  se.one_minus_n_r = s.one_minus_n_r;
  se.radial_coefficient = s.radial_coefficient;

  // z_e = (0, ze_y, ze_z) in R_d, y_e = z_e x x_e.
  se.frame.x = disk_frame.x;
  se.frame.z = (s.ze_y * disk_frame.y + s.ze_z * disk_frame.z).normalized();
  se.frame.y = se.frame.z.cross(se.frame.x);

  // Radial sector split (solid_angle.h): Gauss-Legendre where r_t^2 <= 3, eq. (19) where
  // r_t^2 > 3. r_t^2 = a_t^2 cos^2 t + b_t^2 sin^2 t decreases from a_t^2 to b_t^2.
  constexpr double kSplit = 3.0;
  const double at2 = s.a_t * s.a_t, bt2 = s.b_t * s.b_t;
  if (bt2 >= kSplit) {
    se.radial_split = math::kHalfPi;
  } else if (at2 <= kSplit) {
    se.radial_split = 0.0;
  } else {
    se.radial_split = std::atan2(std::sqrt(at2 - kSplit), std::sqrt(kSplit - bt2));
  }
  se.empty = false;
  return se;
}

namespace {
void check_totals(SphericalEllipse& se) {
  if (!(se.omega > 0.0) || !std::isfinite(se.omega) || !(se.quadrant > 0.0) ||
      !std::isfinite(se.quadrant)) {
    se.empty = true;
    se.omega = se.quadrant = 0.0;
  }
}
}  // namespace

void compute_totals(SphericalEllipse& se) noexcept {
  if (se.empty) return;
  se.quadrant = radial_sector_parametric(se, math::kHalfPi);
  // A disk seen from one side never covers more than the hemisphere; rounding near it can
  // exceed 2 pi by an ulp.
  se.omega = std::min(solid_angle_stable(se), math::kTwoPi);
  check_totals(se);
}

void set_totals(SphericalEllipse& se, double quadrant) noexcept {
  if (se.empty) return;
  se.quadrant = quadrant;
  se.omega = std::min(4.0 * quadrant, math::kTwoPi);
  check_totals(se);
}

SphericalEllipse spherical_ellipse(const Disk& disk, const Vec3& o) noexcept {
  SphericalEllipse se = spherical_ellipse_shape(disk, o);
  compute_totals(se);
  return se;
}

double solid_angle(const Disk& disk, const Vec3& o) {
  return make_spherical_ellipse(disk, o).omega;
}

}  // namespace disklab::ellipse
