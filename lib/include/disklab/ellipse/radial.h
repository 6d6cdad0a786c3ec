#pragma once
// The radial map of Guillén et al. 2017 (Sec. 3.3, eqs. 16-22), over the full ellipse.
//
// Conventions (docs/design.md section 3):
//  - eps1 is the cumulative solid-angle fraction of the azimuth, counter-clockwise from +x_e
//    towards +y_e. Quadrant k = floor(4 eps1), local fraction t = 4 eps1 - k, mirrored (1 - t)
//    on odd quadrants, so the map is continuous across the seams;
//  - eps2 = 0 at the ellipse centre: 1 - h = eps2 (1 - h_r(phi)), the analogue of r = sqrt(u)
//    (eq. 22 as printed puts eps2 = 0 on the rim).
// Root finding works in the planar (projected) ellipse's parametric angle s, tan s = (a/b) tan phi
// (not eq. 20's varphi_r, tan varphi_r = (a_t/b_t) tan phi, which solid_angle.h integrates in),
// instead of phi: dOmega_r/ds = (1 - h_r) dphi/ds = a b / (1 + h_r) lies in
// [ab/2, ab], so Omega_r(s) is nearly linear, s0 = t pi/2 is the exact planar-ellipse answer,
// and safeguarded Newton converges in a few steps at every eccentricity. The point is formed
// from (a cos s, b sin s) / r without trigonometric round trips through phi.
#include <algorithm>
#include <cmath>

#include "disklab/ellipse/map_geometry.h"
#include "disklab/ellipse/quadrant.h"
#include "disklab/ellipse/radial_series.h"
#include "disklab/ellipse/sampler.h"
#include "disklab/math/constants.h"
#include "disklab/math/roots.h"
#include "disklab/math/rotation.h"

namespace disklab::ellipse {

// Newton stops when |Omega_r(s) - t Omega_q| <= kRadialNewtonTol * Omega_q: eps1 is then exact
// to 2.5e-16 (eps1 = (k + t)/4), below the 1e-14 the maps promise.
inline constexpr double kRadialNewtonTol = 1e-15;
// Evaluation cap of the root solves (as math::safeguarded_newton's): never reached in practice,
// the bisection fallback halves the bracket each time.
inline constexpr int kRadialMaxEvaluations = 64;

// Quadrant-local part of the radial map, shared by radial, ld-radial, radial4 and radial-fast.
struct RadialQuadrant {
  const MapGeometry* g = nullptr;
  const RadialSeries* series = nullptr;  // when set and available (n > 0): the fast Omega_r(s)

  bool use_series() const { return series != nullptr && series->n > 0; }
  double quadrant_solid_angle() const { return use_series() ? series->quadrant : g->quadrant; }
  // Omega_r(s), by the series or by solid_angle.h; both agree to ~1e-16 relative.
  double sector_s(double s) const {
    return use_series() ? series->omega(s, std::cos(s), std::sin(s)) : g->radial_sector_s(s);
  }

  // s with Omega_r(s) = t Omega_r(pi/2), eq. (21); t in [0, 1]. Starts from s0 when given.
  double solve_s(double t, int* iterations = nullptr, double s0 = -1.0) const {
    if (iterations) *iterations = 0;
    if (!(t > 0.0)) return 0.0;
    if (!(t < 1.0)) return math::kHalfPi;
    const double quadrant = quadrant_solid_angle();
    const double target = t * quadrant;
    const double ab = g->a * g->b;
    const RadialSeries* fast = use_series() ? series : nullptr;
    auto eval = [this, fast, target, ab](double s) {
      const double cs = std::cos(s), ss = std::sin(s);
      const double deriv = ab / (1.0 + g->hr_parametric(cs, ss));
      const double value = fast ? fast->omega(s, cs, ss) : g->radial_sector_s(s);
      return std::pair<double, double>(value - target, deriv);
    };
    const double start = s0 >= 0.0 ? s0 : t * math::kHalfPi;
    const math::RootResult root = math::safeguarded_newton(eval, 0.0, math::kHalfPi, start,
                                                           kRadialNewtonTol * quadrant, 1e-16, 64);
    if (iterations) *iterations = root.iterations;
    return root.x;
  }

  // A solved parametric angle with its cosine and sine (local_point needs no second sincos).
  using Angle = ParametricAngle;

  // solve_s with the series (when available), skipping the confirming evaluation when a bound
  // proves it unnecessary: after a step delta from s the residual is
  // Omega(s + delta) - target = (1/2) Omega''(xi) delta^2 exactly (Taylor; the linear part is
  // what the step cancels), so M delta^2 <= tol, with M >= max |Omega''| on the step, bounds it
  // by tol/2 without evaluating. Omega'' = -ab h_r' / (1 + h_r)^2, h_r' = (B - A) sin s cos s /
  // h_r, and |sin|, |cos| grow by at most |delta| over the step while h_r >= cos(alpha): M below.
  // math::safeguarded_newton's bracket and bisection fallback; `iterations` counts evaluations
  // of Omega_r.
  // Without s0, the start is the series' reversion (RadialSeries::reverted_start) where there
  // is a series, else the planar ellipse's tau = t pi / 2.
  Angle solve(double t, int* iterations = nullptr, double s0 = -1.0) const {
    const bool given = s0 >= 0.0 && s0 <= math::kHalfPi;
    const double s = given ? s0 : std::clamp(t, 0.0, 1.0) * math::kHalfPi;
    const Angle base = math::quarter_sincos(s);
    return solve_from(t, given || !use_series() ? base : series->reverted_start(base), iterations);
  }  // The same from a start with its cosine and sine already known (radial-fast's seed).
  Angle solve_from(double t, Angle start, int* iterations = nullptr) const {
    if (!use_series()) {
      const double s = solve_s(t, iterations, start.s);
      return {s, std::cos(s), std::sin(s)};
    }
    if (iterations) *iterations = 0;
    if (!(t > 0.0)) return {0.0, 1.0, 0.0};
    if (!(t < 1.0)) return {math::kHalfPi, std::cos(math::kHalfPi), 1.0};
    const RadialSeries& S = *series;
    const double target = t * S.quadrant, tol = kRadialNewtonTol * S.quadrant;
    const double ab = g->a * g->b;
    const double diff = g->a2_minus_b2;  // cos^2(beta) - cos^2(alpha)
    const double h_min = g->cos_alpha;
    const double curvature = ab * diff / (h_min * (1.0 + h_min) * (1.0 + h_min));
    if (!(start.s >= 0.0 && start.s <= math::kHalfPi)) {
      start.s = t * math::kHalfPi;
      start.cs = std::cos(start.s);
      start.ss = std::sin(start.s);
    }
    Angle at = start;  // the last evaluated angle, with its cosine and sine
    auto eval = [&](double s) {
      at = math::moved_to(at, s);
      const double h = g->hr_parametric(at.cs, at.ss);
      return std::pair<double, double>(S.omega(s, at.cs, at.ss) - target, ab / (1.0 + h));
    };
    auto final_step = [&](double, double delta) {
      const double ad = std::abs(delta);
      return curvature * (std::abs(at.ss) + ad) * (std::abs(at.cs) + ad) * delta * delta <= tol;
    };
    const math::RootResult root = math::safeguarded_newton(eval, 0.0, math::kHalfPi, start.s, tol,
                                                           0.0, kRadialMaxEvaluations, final_step);
    if (iterations) *iterations = root.iterations;
    return math::moved_to(at, root.x);
  }

  // Local-frame direction for quadrant k, parametric angle s and eps2 (eq. 22, reversed).
  Vec3 local_point(int k, double s, double eps2) const {
    return local_point(k, Angle{s, std::cos(s), std::sin(s)}, eps2);
  }
  [[gnu::always_inline]] Vec3 local_point(int k, const Angle& ang, double eps2) const {
    const double cs = ang.cs, ss = ang.ss;
    const double px = g->a * cs, py = g->b * ss;
    const double hr = g->hr_parametric(cs, ss);
    const double inv = 1.0 / (1.0 + hr);
    const double omh_r = (px * px + py * py) * inv;  // 1 - h_r = r^2 / (1 + h_r), r = |(px, py)|
    const double omh = eps2 * omh_r;                 // 1 - h
    // h = 1 - eps2 (1 - h_r) as h_r + (1 - eps2)(1 - h_r), two non-negative terms: near the rim
    // (eps2 -> 1) of a disk seen from close to its plane h_r is tiny and 1 - omh would cancel to 0,
    // a direction parallel to the disk that never reaches it.
    const double h = hr + (1.0 - eps2) * omh_r;
    // (x, y) = sqrt(1 - h^2) (px, py) / r with sqrt(1 - h^2) = sqrt(omh (2 - omh)) and
    // omh / r^2 = eps2 / (1 + h_r): (x, y) = f (px, py), one square root, and r never formed (its
    // square underflows for a < ~1e-154, where f still holds).
    const double f = std::sqrt(std::max(0.0, eps2 * (2.0 - omh) * inv));
    return unfold_direction(k, f * px, f * py, h);
  }

  // Inverse of local_point within a quadrant: (t', eps2) for a local direction folded into the
  // first quadrant; returns the quadrant index in k.
  Point2 invert_local(const Vec3& l, int& k) const {
    const FoldedDirection f = fold_direction(l);
    k = f.k;
    // tan s = (a/b) tan phi = (a |y|) / (b |x|).
    const double s = std::atan2(g->a * f.y, g->b * f.x);
    const double t = std::clamp(sector_s(s) / quadrant_solid_angle(), 0.0, 1.0);
    const double omh = one_minus_z(l);  // 1 - h
    const double bound = g->one_minus_hr_parametric(std::cos(s), std::sin(s));
    const double eps2 = bound > 0.0 ? std::clamp(omh / bound, 0.0, 1.0) : 0.0;
    return {t, eps2};
  }
};

// The sample of a local direction that is unit up to a few roundings (the radial family's).
[[gnu::always_inline]] inline EllipseSample finish_sample(const MapGeometry& g, const Vec3& local,
                                                          double pdf) {
  EllipseSample out;
  out.local = local;
  out.direction = renormalized(g.to_world(local));
  out.point = g.hit(out.direction);
  out.pdf = pdf;
  out.valid = true;
  return out;
}

struct RadialMap {
  MapGeometry g;
  RadialSeries series;  // Omega_r(s) for the root solves (falls back to solid_angle.h if n == 0)
  double uniform_pdf = 0.0;  // 1/Omega

  static RadialMap make(const Disk& disk, const Vec3& o) noexcept {
    RadialMap m;
    m.g = MapGeometry::make_shape(disk, o);
    m.series = RadialSeries::make(m.g);
    // The series' quadrant a_0 pi / 2 is the total the root solves use; solid_angle.h's only
    // where there is no series.
    m.g.finish_totals(m.series.n > 0 ? m.series.quadrant : 0.0);
    if (m.g.empty) {
      m.series = {};
      return m;
    }
    m.uniform_pdf = 1.0 / m.g.omega;
    return m;
  }
  bool valid() const { return !g.empty; }
  RadialQuadrant quadrant() const { return RadialQuadrant{&g, &series}; }

  EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    if (iterations) *iterations = 0;
    if (g.empty || !in_unit_square(u)) return {};
    double t;
    const int k = split_quadrant(u.x, t);
    const RadialQuadrant q = quadrant();
    return finish_sample(g, q.local_point(k, q.solve(t, iterations), std::clamp(u.y, 0.0, 1.0)),
                         uniform_pdf);
  }
  // Solid-angle density of a direction: 1/Omega inside the disk's solid angle, 0 outside.
  double pdf(const Vec3& direction) const { return g.contains(direction) ? uniform_pdf : 0.0; }

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
