#pragma once
// The parallel map of Guillén et al. 2017 (Sec. 3.2, eqs. 6-15).
//
// eps1 picks the slice angle phi_p in [-beta, beta] by its cumulative solid angle, eqs. (6)-(8)
// and (13); eps2 interpolates the slice's altitude between -h_p and h_p, eq. (14); the point is
// eq. (15) in the frame R_e (the cylinder's axis is x_e). The root of eq. (13) is found by
// safeguarded Newton with the exact derivative (eq. 6: dOmega_p/dphi_p = 2 h_p), in the angle
// varphi_p of eq. (12) where the cumulative area stays smooth at the rim. Each half is solved from
// its own end (eq. 7), so eps1 near 0 does not subtract two nearly equal halves. The slices next
// to the rim (the last kParallelRimFraction of a half's mass) are solved and inverted by the mass
// beyond them, in closed form (Carlson's R_J), to a relative tolerance: there Omega_p^+ flattens
// (its derivative vanishes at the rim) and an absolute tolerance on it would fix the slice only to
// the cube root of that tolerance.
#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "disklab/ellipse/map_geometry.h"
#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/sampler.h"
#include "disklab/math/elliptic_carlson.h"
#include "disklab/math/roots.h"

namespace disklab::ellipse {

// Newton stops when |Omega_p^+(phi) - target| <= kParallelNewtonTol * Omega: eps1 exact to 1e-15.
inline constexpr double kParallelNewtonTol = 1e-15;
// Slices whose mass beyond them (towards the rim) is below this fraction of the half are solved
// from the rim end. Any fraction works; a small one keeps the dearer R_J solve rare.
inline constexpr double kParallelRimFraction = 1e-3;
// The rim solve's relative tolerance on that mass: R_J and the products around it round to a
// few ulps, so 1e-15 (4.5 ulps) could sit below the evaluation's own noise.
inline constexpr double kParallelRimTol = 4e-15;

struct ParallelMap {
  MapGeometry g;
  double uniform_pdf = 0.0;  // 1/Omega
  // Omega_p^+(varphi) as a sine series (radial.h's RadialSeries, beyond the paper), used by the
  // root solve and the inverse when available (series.n > 0). Its `quadrant` holds the half
  // Omega_p^+(beta) either way: the series' value, or solid_angle.h's when n == 0.
  // The integrand dOmega_p^+/dvarphi = 2 c_t b_t cos^2 v / (Delta (1 + b_t^2 sin^2 v)),
  // Delta^2 = 1 - m sin^2 v, is a function of x = cos 2v with singularities at
  // x = -(1 + 2 (1 - m)/m) (Delta = 0) and x = 1 + 2 / b_t^2: the nearer one sets the decay.
  RadialSeries series;

  static RadialSeries make_series(const SphericalEllipse& se) {
    const double bt2 = se.b_t * se.b_t, k = 2.0 * se.a * se.b_t, om = se.one_minus_m;
    const double rho_b = bt2 > 0.0 ? RadialSeries::bernstein_rho(2.0 / bt2) : HUGE_VAL;
    const double rho_m = se.m > 0.0 ? RadialSeries::bernstein_rho(2.0 * om / se.m) : HUGE_VAL;
    // F/k - 1 = c^2 / (Delta (1 + b_t^2 s^2)) - 1
    //         = -s^2 [(Delta + 1 - m)/(1 + Delta) + Delta b_t^2] / (Delta (1 + b_t^2 s^2)),
    // from 1 - Delta = m s^2 / (1 + Delta): positive terms only.
    return RadialSeries::fit(std::min(rho_b, rho_m), k, [&](double c2, double s2) {
      const double delta = std::sqrt(c2 + om * s2);
      const double inner = (delta + om) / (1.0 + delta) + delta * bt2;
      return -k * s2 * inner / (delta * (1.0 + bt2 * s2));
    });
  }
  bool use_series() const { return series.n > 0; }
  double half_total() const { return series.quadrant; }
  // Omega_p^+(varphi) from v, cos v, sin v.
  double half_sector(double v, double cv, double sv) const {
    return use_series() ? series.omega(v, cv, sv) : parallel_half_sector_parametric(g, v);
  }

  static ParallelMap make(const Disk& disk, const Vec3& o) noexcept {
    ParallelMap m;
    m.g = MapGeometry::make(disk, o);
    if (m.g.empty) return m;
    const double half = parallel_half_sector_parametric(m.g, math::kHalfPi);
    if (!(half > 0.0)) {
      m.g.empty = true;
      return m;
    }
    m.uniform_pdf = 1.0 / m.g.omega;
    m.series = make_series(m.g);
    if (!m.use_series()) m.series.quadrant = half;
    return m;
  }
  bool valid() const { return !g.empty; }

  // k q = 2 c_t b_t / (1 + b_t^2) = 2 a b sqrt(1 - b^2): the scale of the slices' density.
  double kq() const { return 2.0 * g.a * g.b * std::sqrt(g.one_minus_b2); }
  // The mass of the slices beyond varphi_p, Omega_p^+(pi/2) - Omega_p^+(varphi_p), from
  // cv = cos varphi_p and sv = sin varphi_p, to a few ulps relative. With s = cos of the
  // integration angle, the integrand of eq. (6) in varphi_p becomes
  //   k q s^2 / (sqrt(1 - m + m s^2) (1 - b^2 s^2) sqrt(1 - s^2)) ds,  q = 1 / (1 + b_t^2),
  // k = 2 c_t b_t, and int_0^sigma s^2 ds / ((1 - nu s^2) sqrt((1 - s^2)(1 - kappa s^2))) =
  // (sigma^3 / 3) R_J(1 - sigma^2, 1 - kappa sigma^2, 1, 1 - nu sigma^2) (DLMF 19.25.14, with
  // Pi - F written as that integral): all terms positive, no cancellation.
  double rim_mass(double cv, double sv) const {
    const SphericalEllipse& se = g;
    const double q = se.one_minus_b2;
    const double delta2 = cv * cv + se.one_minus_m * sv * sv;
    const double y = delta2 / se.one_minus_m;
    if (std::isfinite(y)) {
      return kq() / std::sqrt(se.one_minus_m) * (cv * cv * cv / 3.0) *
             math::carlson_rj(sv * sv, y, 1.0, sv * sv + q * cv * cv);
    }
    // 1 - m below the normal range: the limit m = 1, where Delta = cos and the integral is
    // (k / b_t) (atan b_t - atan(b_t sv)), written as one atan of positive terms.
    return 2.0 * se.a *
           std::atan(se.b * std::sqrt(q) * cv * cv / ((1.0 + sv) * (q + se.b * se.b * sv)));
  }
  // dOmega_p^+/dvarphi_p (eq. 6 in the variable of eq. 12) from cv, sv, written with
  // q = 1 / (1 + b_t^2) so that no square of b_t can overflow.
  double slice_density(double cv, double sv) const {
    const SphericalEllipse& se = g;
    const double q = se.one_minus_b2;
    const double delta = std::sqrt(cv * cv + se.one_minus_m * sv * sv);
    return kq() * cv * cv / (delta * (q + se.b * se.b * sv * sv));
  }
  // cos and sin of the slice varphi_p whose mass beyond it is r * half (r in (0, 1]), by
  // safeguarded Newton on rim_mass to a relative tolerance. The variable is w = pi/2 - varphi_p
  // where the slice lies within pi/4 of the rim, else varphi_p itself, so that it is resolved
  // where the mass varies (next to the rim, and, for a wide ellipse seen from close by, next to
  // varphi_p = 0 where most of the mass sits). Start in w: the mass is below both
  // k q w^3 / (3 sqrt(1 - m)) and k q w^2 / 2 (its integrand is below k q w^2 / sqrt(1 - m) and
  // k q w), so the larger of those models' roots is below the root.
  std::pair<double, double> solve_rim(double r, int* iterations) const {
    const double target = r * half_total();
    const double f_tol = kParallelRimTol * target;
    constexpr double kQuarter = 0.25 * math::kPi;
    const double c4 = std::sqrt(0.5);  // cos(pi/4) = sin(pi/4), to the rounding of both
    math::RootResult res;
    if (rim_mass(c4, c4) >= target) {
      const double k = kq();
      const double w_cubic = std::cbrt(3.0 * target * std::sqrt(g.one_minus_m) / k);
      const double w_square = std::sqrt(2.0 * target / k);
      const double w0 = std::min(kQuarter, std::max(w_cubic, w_square));
      auto eval = [this, target](double w) {
        const double cv = std::sin(w), sv = std::cos(w);
        return std::pair<double, double>(rim_mass(cv, sv) - target, slice_density(cv, sv));
      };
      res = math::safeguarded_newton(eval, 0.0, kQuarter, w0, f_tol, 0.0, 64);
      if (iterations) *iterations = res.iterations;
      return {std::sin(res.x), std::cos(res.x)};
    }
    auto eval = [this, target](double v) {
      const double cv = std::cos(v), sv = std::sin(v);
      return std::pair<double, double>(target - rim_mass(cv, sv), slice_density(cv, sv));
    };
    res = math::safeguarded_newton(eval, 0.0, kQuarter, 0.5 * kQuarter, f_tol, 0.0, 64);
    if (iterations) *iterations = res.iterations;
    return {std::cos(res.x), std::sin(res.x)};
  }

  // The angle varphi_p of eq. (12) with Omega_p^+ = f * half, f in [0, 1]. Newton runs in
  // varphi_p, where Omega_p^+ is smooth up to the rim: dOmega_p^+/dvarphi = 2 h_p dphi_p/dvarphi
  // = 2 c_t b_t cos^2 v / (Delta (1 + b_t^2 sin^2 v)), Delta^2 = cos^2 v + (1 - m) sin^2 v
  // (eq. 6 with phi_p = atan(b_t sin v)).
  double solve_varphi(double f, int* iterations) const {
    if (iterations) *iterations = 0;
    if (!(f > 0.0)) return 0.0;
    if (!(f < 1.0)) return math::kHalfPi;
    const SphericalEllipse& se = g;
    const double target = f * half_total();
    const double k = 2.0 * se.a * se.b_t, bt2 = se.b_t * se.b_t;
    auto eval = [this, &se, target, k, bt2](double v) {
      const double sv = std::sin(v), cv = std::cos(v);
      const double delta = std::sqrt(cv * cv + se.one_minus_m * sv * sv);
      const double deriv = k * cv * cv / (delta * (1.0 + bt2 * sv * sv));
      return std::pair<double, double>(half_sector(v, cv, sv) - target, deriv);
    };
    // Far-field start: for a small ellipse Omega_p^+ is proportional to the planar slice area,
    // whose fraction is F(v) = (2v + sin 2v) / pi (dF/dv = 4 cos^2 v / pi). Starting from its
    // end asymptotics (F ~ 4v/pi at 0, 1 - F ~ (4/(3 pi)) (pi/2 - v)^3 at the rim), four
    // clamped Newton steps on that cheap function (no elliptic integrals) solve it to ~1 ulp.
    // With the series, the model keeps its first harmonic instead, F(v) = (v + r sin 2v)/(pi/2),
    // r = b_1/a_0 (= 1/2 in the far field), which is closer for near disks.
    const double r1 = use_series() ? series.b[0] / series.a0 : 0.5;
    double v0 =
        f > 0.5 ? math::kHalfPi - std::cbrt(0.75 * math::kPi * (1.0 - f)) : 0.25 * math::kPi * f;
    for (int i = 0; i < 4; ++i) {
      const double c2v = std::cos(2.0 * v0);
      const double d = (1.0 + 2.0 * r1 * c2v) / math::kHalfPi;
      if (!(d > 0.0)) break;
      v0 = std::clamp(v0 - ((v0 + r1 * std::sin(2.0 * v0)) / math::kHalfPi - f) / d, 0.0,
                      math::kHalfPi);
    }
    const math::RootResult r = math::safeguarded_newton(eval, 0.0, math::kHalfPi, v0,
                                                        kParallelNewtonTol * g.omega, 1e-17, 64);
    if (iterations) *iterations = r.iterations;
    return r.x;
  }

  EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    if (iterations) *iterations = 0;
    if (g.empty || !in_unit_square(u)) return {};
    const double e1 = std::clamp(u.x, 0.0, 1.0), e2 = std::clamp(u.y, 0.0, 1.0);
    // Eq. (7): eps1 >= 1/2 lies in the positive half, the rest mirrored.
    const bool positive = e1 >= 0.5;
    // The fraction of the half beyond the slice, exact: 2 (1 - e1) (Sterbenz) or 2 e1.
    const double r = positive ? 2.0 * (1.0 - e1) : 2.0 * e1;
    double cv, sv;  // cos and sin of varphi_p
    if (r < kParallelRimFraction) {
      std::tie(cv, sv) = solve_rim(r, iterations);
    } else {
      const double v = solve_varphi(1.0 - r, iterations);
      cv = std::cos(v);
      sv = std::sin(v);
    }
    const double phi = std::atan(g.b_t * sv);  // inverse of eq. (12)
    const double phi_p = positive ? phi : -phi;
    const double sgn = 2.0 * e2 - 1.0;
    const double delta2 = cv * cv + g.one_minus_m * sv * sv;
    const double hp = g.a * cv / std::sqrt(delta2);  // eq. (9), as h_p_parametric
    const double h = sgn * hp;                       // eq. (14)
    // rho^2 = 1 - h^2 = (1 - sgn^2) + sgn^2 (1 - h_p^2), 1 - sgn^2 = 4 e2 (1 - e2), and from
    // eq. (9), 1 - h_p^2 = (cos^2 v (1 - a^2) + (1 - m) sin^2 v) / Delta^2: positive terms only.
    // (1 - h)(1 + h) cancels at the slice ends (h = -+h_p) when h_p -> 1, i.e. for points close
    // to the disk: the direction then leaves the disk or runs parallel to it.
    const double one_minus_hp2 = (cv * cv * g.one_minus_a2 + g.one_minus_m * sv * sv) / delta2;
    const double rho2 = 4.0 * e2 * (1.0 - e2) + sgn * sgn * one_minus_hp2;
    const double rho = std::sqrt(std::max(0.0, std::min(1.0, rho2)));
    const Vec3 local(h, rho * std::sin(phi_p), rho * std::cos(phi_p));  // eq. (15)
    return finish_sample(g, local, uniform_pdf);
  }
  // Solid-angle density of a direction: 1/Omega inside the disk's solid angle, 0 outside.
  double pdf(const Vec3& direction) const { return g.contains(direction) ? uniform_pdf : 0.0; }

  // Direction -> (eps1, eps2), no root finding.
  Point2 invert_local(const Vec3& l) const {
    if (g.empty) return {};
    const double phi_p = std::atan2(l.y(), l.z());
    double v = parallel_parametric_angle(g, std::min(std::abs(phi_p), g.beta));
    double cv = std::cos(v), sv = std::sin(v);
    double delta2 = cv * cv + g.one_minus_m * sv * sv;
    double hp = g.a * cv / std::sqrt(delta2);  // eq. (9), as h_p_parametric
    // A direction's thin coordinate y carries an absolute error ~eps, i.e. ~eps / b of the
    // ellipse's width, and next to the rim the slice's half-height h_p ~ cos varphi moves by
    // ~sqrt of that: a slice found from y alone may be shorter than |x|. Such a direction lies
    // on the end of the slice that x gives (the longer one, within y's error): from eq. (9),
    // h_p = |x| at cos^2 = x^2 (1 - m) / (a^2 - m x^2), a^2 - m x^2 = (1 - m) a^2 + m (a - x)(a +
    // x).
    const double x = std::abs(l.x());
    if (x > hp) {
      const double den = g.one_minus_m * g.a * g.a + g.m * (g.a - x) * (g.a + x);
      const double c2 = den > 0.0 ? std::min(1.0, x * x * g.one_minus_m / den) : 1.0;
      cv = std::sqrt(c2);
      sv = std::sqrt(1.0 - c2);
      v = std::atan2(sv, cv);
      delta2 = cv * cv + g.one_minus_m * sv * sv;
      hp = g.a * cv / std::sqrt(delta2);
    }
    // The fraction r of the half beyond the slice; near the rim from the mass beyond it, as
    // sample() solves it (the same threshold on the same function, so the two agree).
    double r = 1.0 - std::clamp(half_sector(v, cv, sv) / half_total(), 0.0, 1.0);
    if (r < 2.0 * kParallelRimFraction) {
      const double beyond = rim_mass(cv, sv) / half_total();
      if (beyond < kParallelRimFraction) r = beyond;
    }
    double e1 =
        std::signbit(phi_p) ? std::clamp(0.5 * r, 0.0, 0.5) : std::clamp(1.0 - 0.5 * r, 0.5, 1.0);
    // Next to 1, eps1 carries an absolute eps / 2, coarse next to the rim slices' r: eps2 is
    // then taken on the slice that sample() gives for the rounded eps1, so that the two agree,
    // and where that slice is shorter than |x|, eps1 steps towards the centre (by ulps: each
    // step lengthens the slice by about as much as the rounding shortened it).
    if (!std::signbit(phi_p) && r < kParallelRimFraction) {
      for (int step = 0;; ++step) {
        std::tie(cv, sv) = solve_rim(2.0 * (1.0 - e1), nullptr);
        delta2 = cv * cv + g.one_minus_m * sv * sv;
        hp = g.a * cv / std::sqrt(delta2);
        if (!(hp < x) || step == 4) break;
        e1 = std::nextafter(e1, 0.0);
      }
    }
    const double e2 = hp > 0.0 ? std::clamp(0.5 * (l.x() / hp + 1.0), 0.0, 1.0) : 0.5;
    return {e1, e2};
  }
  Point2 invert(const Vec3& direction) const { return invert_local(g.to_local(direction)); }
};

}  // namespace disklab::ellipse
