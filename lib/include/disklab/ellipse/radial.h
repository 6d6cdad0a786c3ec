#pragma once
// The radial map of Guillén et al. 2017 (Sec. 3.3, eqs. 16-22), over the full ellipse.
//
// Conventions (DESIGN.md Sec. 3):
//  - eps1 is the cumulative solid-angle fraction of the azimuth, counter-clockwise from +x_e
//    towards +y_e. Quadrant k = floor(4 eps1), local fraction t = 4 eps1 - k, mirrored (1 - t)
//    on odd quadrants, so the map is continuous across the seams;
//  - eps2 = 0 at the ellipse centre: 1 - h = eps2 (1 - h_r(phi)), the analogue of r = sqrt(u)
//    (eq. 22 as printed puts eps2 = 0 on the rim).
// Root finding works in the tangent ellipse's parametric angle s (tan s = (a/b) tan phi, the
// varphi_r of eq. 20) instead of phi: dOmega_r/ds = (1 - h_r) dphi/ds = a b / (1 + h_r) lies in
// [ab/2, ab], so Omega_r(s) is nearly linear, s0 = t pi/2 is the exact planar-ellipse answer,
// and safeguarded Newton converges in a few steps at every eccentricity. The point is formed
// from (a cos s, b sin s) / r without trigonometric round trips through phi.
#include <algorithm>
#include <cmath>

#include "disklab/ellipse/map_geometry.h"
#include "disklab/ellipse/sampler.h"
#include "disklab/math/constants.h"
#include "disklab/math/roots.h"

namespace disklab::ellipse {

// Newton stops when |Omega_r(s) - t Omega_q| <= kRadialNewtonTol * Omega_q: eps1 is then exact
// to 2.5e-16 (eps1 = (k + t)/4), below the 1e-14 the maps promise.
inline constexpr double kRadialNewtonTol = 1e-15;

// Quadrant-local part of the radial map, shared by radial, ld-radial, radial4 and radial-fast.
struct RadialQuadrant {
  const MapGeometry* g = nullptr;

  // 1 - h_r and the planar radius^2 at parametric angle s.
  double one_minus_hr_s(double cs, double ss) const {
    const double r2 = g->a * g->a * cs * cs + g->b * g->b * ss * ss;
    const double one_minus_r2 = g->cos2_alpha * cs * cs + g->cos2_beta * ss * ss;
    return r2 / (1.0 + std::sqrt(std::max(0.0, one_minus_r2)));
  }

  // s with Omega_r(s) = t Omega_r(pi/2), eq. (21); t in [0, 1]. Starts from s0 when given.
  double solve_s(double t, int* iterations = nullptr, double s0 = -1.0) const {
    if (iterations) *iterations = 0;
    if (!(t > 0.0)) return 0.0;
    if (!(t < 1.0)) return math::kHalfPi;
    const double target = t * g->quadrant;
    const double ab = g->a * g->b;
    auto eval = [this, target, ab](double s) {
      const double cs = std::cos(s), ss = std::sin(s);
      const double one_minus_r2 = g->cos2_alpha * cs * cs + g->cos2_beta * ss * ss;
      const double deriv = ab / (1.0 + std::sqrt(std::max(0.0, one_minus_r2)));
      return std::pair<double, double>(g->radial_sector_s(s) - target, deriv);
    };
    const double start = s0 >= 0.0 ? s0 : t * math::kHalfPi;
    const math::RootResult root = math::safeguarded_newton(
        eval, 0.0, math::kHalfPi, start, kRadialNewtonTol * g->quadrant, 1e-16, 64);
    if (iterations) *iterations = root.iterations;
    return root.x;
  }

  // Local-frame direction for quadrant k, parametric angle s and eps2 (eq. 22, reversed).
  Vec3 local_point(int k, double s, double eps2) const {
    const double cs = std::cos(s), ss = std::sin(s);
    const double px = g->a * cs, py = g->b * ss;
    const double r = std::hypot(px, py);
    const double omh = eps2 * one_minus_hr_s(cs, ss);  // 1 - h
    const double h = 1.0 - omh;
    const double rho = std::sqrt(std::max(0.0, omh * (2.0 - omh)));  // sqrt(1 - h^2)
    double x = r > 0.0 ? rho * px / r : rho, y = r > 0.0 ? rho * py / r : 0.0;
    if (k == 1 || k == 2) x = -x;
    if (k >= 2) y = -y;
    return {x, y, h};
  }

  // Inverse of local_point within a quadrant: (t', eps2) for a local direction folded into the
  // first quadrant; returns the quadrant index in k.
  Point2 invert_local(const Vec3& l, int& k) const {
    const double x = l.x(), y = l.y();
    const bool left = std::signbit(x), down = std::signbit(y);
    k = down ? (left ? 2 : 3) : (left ? 1 : 0);
    const double ax = std::abs(x), ay = std::abs(y);
    // tan s = (a/b) tan phi = (a |y|) / (b |x|).
    const double s = std::atan2(g->a * ay, g->b * ax);
    const double t = std::clamp(g->radial_sector_s(s) / g->quadrant, 0.0, 1.0);
    const double cs = std::cos(s), ss = std::sin(s);
    const double rho2 = x * x + y * y;
    const double omh = rho2 / (1.0 + std::max(0.0, l.z()));  // 1 - h without cancellation
    const double bound = one_minus_hr_s(cs, ss);
    const double eps2 = bound > 0.0 ? std::clamp(omh / bound, 0.0, 1.0) : 0.0;
    return {t, eps2};
  }
};

inline EllipseSample finish_sample(const MapGeometry& g, const Vec3& local, double pdf) {
  EllipseSample out;
  out.local = local;
  out.direction = g.to_world(local).normalized();
  out.point = g.hit(out.direction);
  out.pdf = pdf;
  out.valid = true;
  return out;
}

// Full-ellipse eps1 -> (quadrant k, fraction t' in that quadrant, mirrored on odd quadrants).
inline int split_quadrant(double eps1, double& t_folded) {
  const double e = std::clamp(eps1, 0.0, 1.0) * 4.0;
  const int k = std::min(3, static_cast<int>(e));
  const double t = std::clamp(e - k, 0.0, 1.0);
  t_folded = (k & 1) ? 1.0 - t : t;
  return k;
}
inline double join_quadrant(int k, double t_folded) {
  const double t = (k & 1) ? 1.0 - t_folded : t_folded;
  return (k + t) * 0.25;
}

struct RadialMap {
  MapGeometry g;
  double pdf = 0.0;

  static RadialMap make(const Vec3& center, const Vec3& normal, double radius, const Vec3& o) {
    RadialMap m;
    m.g = MapGeometry::make(center, normal, radius, o);
    m.pdf = m.g.empty ? 0.0 : 1.0 / m.g.omega;
    return m;
  }
  bool valid() const { return !g.empty; }
  RadialQuadrant quadrant() const { return RadialQuadrant{&g}; }

  EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    if (g.empty) return {};
    double t;
    const int k = split_quadrant(u.x, t);
    const RadialQuadrant q = quadrant();
    const double s = q.solve_s(t, iterations);
    return finish_sample(g, q.local_point(k, s, std::clamp(u.y, 0.0, 1.0)), pdf);
  }

  // Direction -> (eps1, eps2); no root finding (eq. 19 evaluated forwards).
  Point2 invert_local(const Vec3& l) const {
    if (g.empty) return {};
    int k;
    const Point2 te = quadrant().invert_local(l, k);
    return {join_quadrant(k, te.x), te.y};
  }
  Point2 invert(const Vec3& direction) const { return invert_local(g.to_local(direction)); }
};

}  // namespace disklab::ellipse
