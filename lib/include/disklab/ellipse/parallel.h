#pragma once
// The parallel map of Guillén et al. 2017 (Sec. 3.2, eqs. 6-15).
//
// eps1 picks the slice angle phi_p in [-beta, beta] by its cumulative solid angle, eqs. (6)-(8)
// and (13); eps2 interpolates the slice's altitude between -h_p and h_p, eq. (14); the point is
// eq. (15) in the frame R_e (the cylinder's axis is x_e). The root of eq. (13) is found by
// safeguarded Newton with the exact derivative (eq. 6: dOmega_p/dphi_p = 2 h_p), in the angle
// varphi_p of eq. (12) where the cumulative area stays smooth at the rim. Each half is solved from
// its own end (eq. 7), so eps1 near 0 does not subtract two nearly equal halves.
#include <algorithm>
#include <cmath>

#include "disklab/ellipse/map_geometry.h"
#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/sampler.h"
#include "disklab/math/roots.h"

namespace disklab::ellipse {

// Newton stops when |Omega_p^+(phi) - target| <= kParallelNewtonTol * Omega: eps1 exact to 1e-15.
inline constexpr double kParallelNewtonTol = 1e-15;

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
    const double rho_b = bt2 > 0.0 ? RadialSeries::acosh1p(2.0 / bt2) : HUGE_VAL;
    const double rho_m = se.m > 0.0 ? RadialSeries::acosh1p(2.0 * om / se.m) : HUGE_VAL;
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
    const double f = positive ? 2.0 * e1 - 1.0 : 1.0 - 2.0 * e1;
    const double v = solve_varphi(f, iterations);
    const double phi = parallel_azimuth(g, v);
    const double phi_p = positive ? phi : -phi;
    const double sgn = 2.0 * e2 - 1.0;
    const double hp = h_p_parametric(g, v);
    const double h = sgn * hp;  // eq. (14)
    // rho^2 = 1 - h^2 = (1 - sgn^2) + sgn^2 (1 - h_p^2), 1 - sgn^2 = 4 e2 (1 - e2), and from
    // eq. (9), 1 - h_p^2 = (cos^2 v (1 - a^2) + (1 - m) sin^2 v) / Delta^2: positive terms only.
    // (1 - h)(1 + h) cancels at the slice ends (h = -+h_p) when h_p -> 1, i.e. for points close
    // to the disk: the direction then leaves the disk or runs parallel to it.
    const double cv = std::cos(v), sv = std::sin(v);
    const double delta2 = cv * cv + g.one_minus_m * sv * sv;
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
    const double v = parallel_parametric_angle(g, std::min(std::abs(phi_p), g.beta));
    const double f = std::clamp(half_sector(v, std::cos(v), std::sin(v)) / half_total(), 0.0, 1.0);
    const double e1 = std::signbit(phi_p) ? 0.5 - 0.5 * f : 0.5 + 0.5 * f;
    const double hp = h_p_parametric(g, v);
    const double e2 = hp > 0.0 ? std::clamp(0.5 * (l.x() / hp + 1.0), 0.0, 1.0) : 0.5;
    return {e1, e2};
  }
  Point2 invert(const Vec3& direction) const { return invert_local(g.to_local(direction)); }
};

}  // namespace disklab::ellipse
