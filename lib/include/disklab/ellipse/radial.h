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
// Evaluation cap of the root solves (as math::safeguarded_newton's): never reached in practice,
// the bisection fallback halves the bracket each time.
inline constexpr int kRadialMaxEvaluations = 64;

// Omega_r(s) as a short trigonometric series, built once per shading point (the hot path of the
// exact maps; beyond the paper). In the parametric angle s the integrand of eq. (16) is
//     dOmega_r/ds = a b / (1 + h_r(s)),  h_r^2 = A cos^2 s + B sin^2 s = p + q cos 2s,
// A = cos^2 alpha <= B = cos^2 beta, p = (A + B)/2, q = -(a^2 - b^2)/2. As a function of
// x = cos 2s it is analytic on [-1, 1] except for the branch point x* = -p/q = (A + B)/(a^2 - b^2)
// > 1, so its Chebyshev coefficients a_k decay like rho^-k, rho = x* + sqrt(x*^2 - 1) (Bernstein
// ellipse), and integrating term by term gives
//     Omega_r(s) = a_0 s + sum_k a_k sin(2 k s) / (2 k),   Omega_r(pi/2) = a_0 pi / 2,
// with every term O(ab): no cancellation at any distance. The degree N (8..64) is the smallest
// with rho^-N <= 2^-60, so truncation and aliasing stay below ~1e-18 relative to a_0 (the
// coefficients are sampled exactly by a DCT-I on N + 1 Chebyshev-Lobatto nodes). Near disks with
// rho^-64 > 2^-60 (the point close to the disk's rim plane, h_r -> 0 somewhere) get n == 0 and
// the maps fall back to the elliptic-integral form of solid_angle.h.
struct RadialSeries {
  static constexpr int kMaxDegree = 64;
  // Relative size of the dropped tail: 1e-17, a tenth of the rounding of the sum itself.
  static constexpr double kSeriesDrop = 1e-17;
  int n = 0;                      // degree; 0: not available, use solid_angle.h
  double a0 = 0.0;                // mean of the integrand (constant term)
  double quadrant = 0.0;          // a_0 pi / 2
  double b[kMaxDegree + 1] = {};  // b_k = a_k / (2k), k = 1..n

  static RadialSeries make(const MapGeometry& g) {
    if (g.empty) return {};
    const double A = g.one_minus_a2, B = g.one_minus_b2;
    const double diff = g.a2_minus_b2;  // B - A = a^2 - b^2
    const double ab = g.a * g.b;
    // log rho = acosh(x*), x* - 1 = 2A / (B - A).
    const double log_rho = diff > 0.0 ? acosh1p(2.0 * A / diff) : HUGE_VAL;
    // The DCT runs on dg_j = g_j - g_0, formed without cancellation (h_0 = cos(alpha)):
    //   g_j - g_0 = -a b (B - A) sin^2 s_j / ((h_0 + h_j)(1 + h_0)(1 + h_j)),
    // so the coefficients k >= 1 (where the constant g_0 contributes exactly nothing) carry
    // rounding relative to their own size, not to a b: for distant disks they are O(a^2 - b^2)
    // and would otherwise drown in the rounding of g_j.
    const double h0 = g.cos_alpha, g0 = ab / (1.0 + h0);
    return fit(log_rho, g0, [&](double c2, double s2) {
      const double hj = std::sqrt(A * c2 + B * s2);
      return -ab * diff * s2 / ((h0 + hj) * (1.0 + h0) * (1.0 + hj));
    });
  }

  // acosh(1 + e) for e >= 0 without cancellation.
  static double acosh1p(double e) { return std::log1p(e + std::sqrt(e * (2.0 + e))); }

  // The series of int_0^s G(cos 2s') ds' for an integrand whose Chebyshev coefficients decay at
  // least like exp(-k log_rho): degree N (8..64) with N log_rho >= 60 log 2 (n = 0 if none
  // suffices), coefficients by a DCT-I on N + 1 Chebyshev-Lobatto nodes s_j = j pi / (2N) of
  // dg(cos^2 s_j, sin^2 s_j) = G_j - g0 (g0 = G at s = 0), trailing terms dropped.
  template <class DG>
  static RadialSeries fit(double log_rho, double g0, DG&& dg_at) {
    RadialSeries out;
    const double need = 60.0 * 0.6931471805599453 / log_rho;
    if (!(need <= kMaxDegree) || !std::isfinite(g0)) return out;
    int n = 8;
    while (n < need)
      n *= 2;
    const auto& tab = tables();
    const int step = kMaxDegree / n;  // table stride for this degree
    double dg[kMaxDegree + 1];
    for (int j = 0; j <= n; ++j)
      dg[j] = dg_at(tab.cos2_half[j * step], tab.sin2_half[j * step]);
    // DCT-I: a_k = (2/n) sum'' dg_j cos(j k pi / n); a_0 and a_n halved once more. For k >= 1
    // the constant g0 contributes sum'' cos(j k pi / n) = 0.
    double coef[kMaxDegree + 1];
    for (int k = 0; k <= n; ++k) {
      double sum = 0.5 * (dg[0] + ((k & 1) ? -dg[n] : dg[n]));
      // cos(j k pi / n) from the table at index (j k mod 2n) * step, kept by increments (no
      // integer division in the O(n^2) loop).
      // Four partial sums: the loop is bound by the latency of the additions, not their count.
      const int wrap = 2 * kMaxDegree, inc = (k * step) % wrap;
      int idx = 0;
      double part[4] = {0.0, 0.0, 0.0, 0.0};
      for (int j = 1; j < n; ++j) {
        idx += inc;
        if (idx >= wrap) idx -= wrap;
        part[j & 3] += dg[j] * tab.cos_pi[idx];
      }
      sum += (part[0] + part[1]) + (part[2] + part[3]);
      coef[k] = sum * (2.0 / n);
    }
    coef[0] = g0 + 0.5 * coef[0];
    coef[n] *= 0.5;
    out.n = n;
    out.a0 = coef[0];
    for (int k = 1; k <= n; ++k)
      out.b[k] = coef[k] / (2.0 * k);
    out.quadrant = out.a0 * math::kHalfPi;
    // Drop the trailing terms whose sum stays below kSeriesDrop * quadrant (|sin| <= 1 bounds
    // their contribution): N was sized for the worst decay, most ellipses need fewer terms.
    double tail = 0.0;
    while (out.n > 1 && tail + std::abs(out.b[out.n]) <= kSeriesDrop * out.quadrant) {
      tail += std::abs(out.b[out.n]);
      out.b[out.n--] = 0.0;
    }
    for (int k = 1; k <= out.n; ++k)
      if (!std::isfinite(out.b[k])) return {};
    if (!(out.quadrant > 0.0) || !std::isfinite(out.quadrant)) return {};
    return out;
  }

  // Omega_r(s) from cos s and sin s (and s itself): Clenshaw's recurrence for the sine series in
  // theta = 2s. Near theta = 0 or pi the recurrence's rounding is multiplied by sin(theta), as
  // the sum itself, so the relative accuracy of a_0 s + sum holds there too.
  double omega(double s, double cs, double ss) const {
    const double cos2 = (cs - ss) * (cs + ss), sin2 = 2.0 * ss * cs;
    const double two_c = 2.0 * cos2;
    double y1 = 0.0, y2 = 0.0;
    for (int k = n; k >= 1; --k) {
      const double y = b[k] + two_c * y1 - y2;
      y2 = y1;
      y1 = y;
    }
    return a0 * s + y1 * sin2;
  }

 private:
  struct Tables {
    double cos_pi[2 * kMaxDegree];     // cos(m pi / 64), m = 0..127
    double cos2_half[kMaxDegree + 1];  // cos^2(j pi / 128), j = 0..64
    double sin2_half[kMaxDegree + 1];  // sin^2(j pi / 128)
  };
  static const Tables& tables() {
    static const Tables t = [] {
      Tables r;
      for (int m = 0; m < 2 * kMaxDegree; ++m)
        r.cos_pi[m] = std::cos(m * math::kPi / kMaxDegree);
      for (int j = 0; j <= kMaxDegree; ++j) {
        const double c = std::cos(j * math::kHalfPi / kMaxDegree);
        const double sn = std::sin(j * math::kHalfPi / kMaxDegree);
        r.cos2_half[j] = c * c;
        r.sin2_half[j] = sn * sn;
      }
      return r;
    }();
    return t;
  }
};

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

  // 1 - h_r and the planar radius^2 at parametric angle s.
  double one_minus_hr_s(double cs, double ss) const {
    const double r2 = g->a * g->a * cs * cs + g->b * g->b * ss * ss;
    const double one_minus_r2 = g->one_minus_a2 * cs * cs + g->one_minus_b2 * ss * ss;
    return r2 / (1.0 + std::sqrt(std::max(0.0, one_minus_r2)));
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
      const double one_minus_r2 = g->one_minus_a2 * cs * cs + g->one_minus_b2 * ss * ss;
      const double deriv = ab / (1.0 + std::sqrt(std::max(0.0, one_minus_r2)));
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
  struct Angle {
    double s, cs, ss;
  };

  // solve_s with the series (when available) and a Newton loop that skips the confirming
  // evaluation when it can prove it unnecessary: after a step delta from s the residual is
  // Omega(s + delta) - target = (1/2) Omega''(xi) delta^2 exactly (Taylor; the linear part is
  // what the step cancels), so M delta^2 <= tol, with M >= max |Omega''| on the step, bounds it
  // by tol/2 without evaluating. Omega'' = -ab h_r' / (1 + h_r)^2, h_r' = (B - A) sin s cos s /
  // h_r, and |sin|, |cos| grow by at most |delta| over the step while h_r >= cos(alpha): M below.
  // Same bracket and bisection fallback as math::safeguarded_newton; `iterations` counts
  // evaluations of Omega_r.
  Angle solve(double t, int* iterations = nullptr, double s0 = -1.0) const {
    if (!use_series()) {
      const double s = solve_s(t, iterations, s0);
      return {s, std::cos(s), std::sin(s)};
    }
    if (iterations) *iterations = 0;
    if (!(t > 0.0)) return {0.0, 1.0, 0.0};
    if (!(t < 1.0)) return {math::kHalfPi, std::cos(math::kHalfPi), 1.0};
    const RadialSeries& S = *series;
    const double target = t * S.quadrant, tol = kRadialNewtonTol * S.quadrant;
    const double ab = g->a * g->b, A = g->one_minus_a2, B = g->one_minus_b2;
    const double diff = g->a2_minus_b2;  // B - A
    const double h_min = g->cos_alpha;
    const double curvature = ab * diff / (h_min * (1.0 + h_min) * (1.0 + h_min));
    double lo = 0.0, hi = math::kHalfPi;
    double s = (s0 >= 0.0 && s0 <= math::kHalfPi) ? s0 : t * math::kHalfPi;
    double cs = std::cos(s), ss = std::sin(s);
    for (int it = 1; it <= kRadialMaxEvaluations; ++it) {
      const double h = std::sqrt(std::max(0.0, A * cs * cs + B * ss * ss));
      const double d1 = ab / (1.0 + h);
      const double value = S.omega(s, cs, ss) - target;
      if (iterations) *iterations = it;
      if (!(std::abs(value) > tol)) return {s, cs, ss};
      if (value < 0.0)
        lo = s;
      else
        hi = s;
      const double delta = -value / d1;
      const double next = s + delta;
      if (next > lo && next < hi) {
        const double ad = std::abs(delta);
        const double M = curvature * (std::abs(ss) + ad) * (std::abs(cs) + ad);
        if (M * delta * delta <= tol) {
          // Converged without another evaluation. For |delta| <= 1e-6 the sine and cosine follow
          // from those at s by Taylor to second order (the cubic term, < 2e-19, is below rounding).
          if (ad <= 1e-6) {
            const double q = 0.5 * delta * delta;
            return {next, cs - ss * delta - cs * q, ss + cs * delta - ss * q};
          }
          return {next, std::cos(next), std::sin(next)};
        }
        s = next;
      } else {
        s = 0.5 * (lo + hi);
      }
      cs = std::cos(s);
      ss = std::sin(s);
      if (!(lo < hi) || std::nextafter(lo, hi) >= hi) break;
    }
    return {s, cs, ss};
  }

  // Local-frame direction for quadrant k, parametric angle s and eps2 (eq. 22, reversed).
  Vec3 local_point(int k, double s, double eps2) const {
    return local_point(k, Angle{s, std::cos(s), std::sin(s)}, eps2);
  }
  Vec3 local_point(int k, const Angle& ang, double eps2) const {
    const double cs = ang.cs, ss = ang.ss;
    const double px = g->a * cs, py = g->b * ss;
    // |(px, py)|: plain sqrt unless the squares could underflow (a < ~1e-145).
    const double r2 = px * px + py * py;
    const double r = r2 > 1e-290 ? std::sqrt(r2) : std::hypot(px, py);
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
    const double t = std::clamp(sector_s(s) / quadrant_solid_angle(), 0.0, 1.0);
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
  RadialSeries series;  // Omega_r(s) for the root solves (falls back to solid_angle.h if n == 0)
  double pdf = 0.0;

  static RadialMap make(const Disk& disk, const Vec3& o) {
    RadialMap m;
    m.g = MapGeometry::make(disk, o);
    m.pdf = m.g.empty ? 0.0 : 1.0 / m.g.omega;
    m.series = RadialSeries::make(m.g);
    return m;
  }
  bool valid() const { return !g.empty; }
  RadialQuadrant quadrant() const { return RadialQuadrant{&g, &series}; }

  EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    if (g.empty) return {};
    double t;
    const int k = split_quadrant(u.x, t);
    const RadialQuadrant q = quadrant();
    return finish_sample(g, q.local_point(k, q.solve(t, iterations), std::clamp(u.y, 0.0, 1.0)),
                         pdf);
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
