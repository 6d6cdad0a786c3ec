#pragma once
// What the spherical-ellipse maps need from the geometry, in one place: the ellipse frame and
// semi-axes (Guillén et al. 2017, Sec. 3, eqs. 3-5, with the frame fix of DESIGN.md Sec. 3), the
// cumulative solid angles of the radial and parallel maps as functions of the azimuth, and their
// derivatives 1 - h_r and 2 h_p (eqs. 9, 16-18).
//
// All forms are cancellation-free for distant disks: the radial sector is integrated in the
// tangent ellipse's parametric angle s (tan s = (a/b) tan phi), where the planar sector element
// r^2 dphi = a b ds turns eq. (16) into
//     Omega_r(phi) = a b int_0^s ds' / (1 + sqrt(cos^2(alpha) cos^2 s' + cos^2(beta) sin^2 s')),
// a smooth integrand between 1/2 and 1 whose terms are all O(ab); the parallel half-area eq. (8)
// is integrated in the angle varphi of eq. (12), where it becomes
//     Omega_p^+ = 2 a b_t int_0^varphi cos^2 t / ((1 + b_t^2 sin^2 t) sqrt(1 - m sin^2 t)) dt.
// Both are evaluated by composite Gauss-Legendre quadrature on fixed panels (so each is one
// smooth, monotone function of its argument, which Newton needs).
#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Geometry>
#include "disklab/math/constants.h"

#include "disklab/types.h"

namespace disklab::ellipse {

namespace detail {

// Gauss-Legendre rule with 8 nodes on [-1, 1], computed once by Newton on P_8.
struct GaussLegendre8 {
  std::array<double, 8> x{}, w{};
  GaussLegendre8() {
    constexpr int n = 8;
    for (int i = 0; i < n; ++i) {
      double z = std::cos(math::kPi * (i + 0.75) / (n + 0.5));
      double dp = 1.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1.0);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-17) break;
      }
      x[i] = z;
      w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
  }
};

inline const GaussLegendre8& gauss_legendre8() {
  static const GaussLegendre8 rule;
  return rule;
}

// int_0^t f over fixed panels of [0, T] (panel count `panels`), the last one partial.
template <class F>
double panel_integral(F&& f, double t, double T, int panels) {
  const auto& gl = gauss_legendre8();
  const double width = T / panels;
  double sum = 0.0;
  double start = 0.0;
  for (int p = 0; p < panels && start < t; ++p, start += width) {
    const double end = std::min(t, start + width);
    const double half = 0.5 * (end - start), mid = 0.5 * (end + start);
    double panel = 0.0;
    for (int i = 0; i < 8; ++i)
      panel += gl.w[i] * f(mid + half * gl.x[i]);
    sum += half * panel;
  }
  return sum;
}

}  // namespace detail

struct MapGeometry {
  // Disk and shading point.
  Vec3 o = Vec3::Zero(), c = Vec3::Zero(), n = Vec3::UnitZ();
  double radius = 0.0;
  // Ellipse frame R_e (columns x_e, y_e, z_e in world space).
  Vec3 xe = Vec3::UnitX(), ye = Vec3::UnitY(), ze = Vec3::UnitZ();
  double a = 0.0, b = 0.0;         // semi-axes, eq. (4); a along x_e, a >= b
  double alpha = 0.0, beta = 0.0;  // semi-arcs, eq. (5)
  double a_t = 0.0, b_t = 0.0;     // tangent-ellipse semi-axes
  double cos2_alpha = 1.0, cos2_beta = 1.0;
  double m_p = 0.0;       // parallel map module m, eq. (10)
  double quadrant = 0.0;  // Omega_r(pi/2)
  double omega = 0.0;     // solid angle of the disk
  bool empty = true;

  static constexpr int kRadialPanels = 16;
  static constexpr int kParallelPanels = 64;

  static MapGeometry make(const Vec3& center, const Vec3& normal, double radius, const Vec3& o) {
    MapGeometry g;
    g.o = o;
    g.c = center;
    g.radius = radius;
    const double nn = normal.norm();
    if (!(radius > 0.0) || !std::isfinite(radius) || !(nn > 0.0) || !std::isfinite(nn) ||
        !center.allFinite() || !o.allFinite())
      return g;
    g.n = normal / nn;
    const Vec3 d = center - o;
    const Vec3 zd = -g.n;
    const double z_c = d.dot(zd);  // depth of the disk plane in front of o
    if (!(z_c > 0.0)) return g;    // behind the one-sided disk or in its plane: sees nothing
    // Frame of eq. (3) with x and y swapped (DESIGN.md Sec. 3): y_d along the tilt.
    Vec3 xd = zd.cross(d);
    const double xn = xd.norm();
    if (xn > 1e-300 * d.norm() && xn > 0.0) {
      xd /= xn;
    } else {  // on axis: any in-plane direction
      xd = (std::abs(zd.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(zd).normalized();
    }
    const Vec3 yd = zd.cross(xd);
    const double y_c = d.dot(yd);
    const double y0 = y_c - radius, y1 = y_c + radius;
    const double L0 = std::hypot(y0, z_c), L1 = std::hypot(y1, z_c);
    // Full angle between the directions to the boundary points y0, y1: atan2 of their 2D cross
    // and dot products, both free of cancellation. beta is half of it.
    const double gamma = std::atan2(2.0 * radius * z_c, y0 * y1 + z_c * z_c);
    g.beta = 0.5 * gamma;
    g.b = std::sin(g.beta);
    g.b_t = std::tan(g.beta);
    // Ellipse centre direction: bisector of the two boundary directions.
    const double yp = y0 / L0 + y1 / L1, zp = z_c / L0 + z_c / L1;
    const double zn = std::hypot(yp, zp);
    // Chord through the re-projected centre: y_h = (y0 L1 + y1 L0)/(L0 + L1) and its half
    // length x1 = 2 r sqrt(L0 L1)/(L0 + L1) (closed forms of Sec. 3's construction).
    const double y_h = (y0 * L1 + y1 * L0) / (L0 + L1);
    const double x1 = 2.0 * radius * std::sqrt(L0 * L1) / (L0 + L1);
    const double rho = std::hypot(y_h, z_c);
    g.a_t = x1 / rho;
    g.alpha = std::atan2(x1, rho);
    g.a = std::sin(g.alpha);
    g.cos2_alpha = 1.0 / (1.0 + g.a_t * g.a_t);
    g.cos2_beta = 1.0 / (1.0 + g.b_t * g.b_t);
    g.m_p = (g.a_t * g.a_t - g.b_t * g.b_t) / (g.a_t * g.a_t + 1.0);
    if (!std::isfinite(g.m_p)) g.m_p = 1.0;
    g.m_p = std::clamp(g.m_p, 0.0, 1.0);
    g.xe = xd;
    g.ze = ((yp / zn) * yd + (zp / zn) * zd).normalized();
    g.ye = g.ze.cross(g.xe);
    g.quadrant = g.radial_sector_s(math::kHalfPi);
    g.omega = 4.0 * g.quadrant;
    g.empty = !(g.omega > 0.0) || !std::isfinite(g.omega) || !(g.b > 0.0);
    return g;
  }

  // The frame-free part of the geometry from the semi-arcs alone (0 < beta <= alpha < pi/2):
  // what a table over (beta/alpha, eps) needs. The frame is the identity.
  static MapGeometry from_arcs(double alpha, double beta) {
    MapGeometry g;
    g.alpha = alpha;
    g.beta = beta;
    g.a = std::sin(alpha);
    g.b = std::sin(beta);
    g.a_t = std::tan(alpha);
    g.b_t = std::tan(beta);
    g.cos2_alpha = std::cos(alpha) * std::cos(alpha);
    g.cos2_beta = std::cos(beta) * std::cos(beta);
    g.m_p = std::clamp((g.a_t * g.a_t - g.b_t * g.b_t) / (g.a_t * g.a_t + 1.0), 0.0, 1.0);
    g.quadrant = g.radial_sector_s(math::kHalfPi);
    g.omega = 4.0 * g.quadrant;
    g.empty = !(g.omega > 0.0) || !std::isfinite(g.omega) || !(g.b > 0.0);
    return g;
  }

  // Squared planar radius of the ellipse at azimuth phi, eq. (18), from sin/cos of phi.
  double r2(double sin_phi, double cos_phi) const {
    const double den = a * a * sin_phi * sin_phi + b * b * cos_phi * cos_phi;
    return a * a * b * b / den;
  }
  // 1 - h_r(phi) (eq. 17) as r^2 / (1 + sqrt(1 - r^2)), with 1 - r^2 formed without cancellation.
  double one_minus_hr(double sin_phi, double cos_phi) const {
    const double s2 = sin_phi * sin_phi, c2 = cos_phi * cos_phi;
    const double den = a * a * s2 + b * b * c2;
    const double r2v = a * a * b * b / den;
    const double one_minus_r2 = (a * a * cos2_beta * s2 + b * b * cos2_alpha * c2) / den;
    return r2v / (1.0 + std::sqrt(std::max(0.0, one_minus_r2)));
  }
  double one_minus_hr(double phi) const { return one_minus_hr(std::sin(phi), std::cos(phi)); }

  // Omega_r as a function of the parametric angle s in [0, pi/2].
  double radial_sector_s(double s) const {
    const double ca = cos2_alpha, cb = cos2_beta;
    auto f = [ca, cb](double t) {
      const double ct = std::cos(t), st = std::sin(t);
      return 1.0 / (1.0 + std::sqrt(ca * ct * ct + cb * st * st));
    };
    return a * b * detail::panel_integral(f, s, math::kHalfPi, kRadialPanels);
  }
  // Omega_r(phi), eq. (16)/(19), phi in [0, pi/2].
  double radial_sector(double phi) const {
    const double s = std::atan2(a * std::sin(phi), b * std::cos(phi));
    return radial_sector_s(s);
  }

  // The parallel map's angle varphi_p of eq. (12) for phi_p in [0, beta].
  double parallel_varphi(double phi_p) const {
    const double t = std::tan(phi_p) / b_t;
    return std::asin(std::clamp(t, 0.0, 1.0));
  }
  // h_p(phi_p), eq. (9), written in varphi: h_p = c_t cos(varphi) / sqrt(1 - m sin^2 varphi).
  double hp(double phi_p) const {
    const double v = parallel_varphi(std::abs(phi_p));
    const double sv = std::sin(v);
    return a * std::cos(v) / std::sqrt(1.0 - m_p * sv * sv);
  }
  // Omega_p^+(phi_p), eqs. (8)/(11), phi_p in [0, beta].
  double parallel_half(double phi_p) const {
    const double v = parallel_varphi(phi_p);
    const double bt2 = b_t * b_t, m = m_p;
    auto f = [bt2, m](double t) {
      const double st = std::sin(t), ct = std::cos(t);
      return ct * ct / ((1.0 + bt2 * st * st) * std::sqrt(1.0 - m * st * st));
    };
    return 2.0 * a * b_t * detail::panel_integral(f, v, math::kHalfPi, kParallelPanels);
  }

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
