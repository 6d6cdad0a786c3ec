#pragma once
// The parallel map of Guillén et al. 2017 (Sec. 3.2, eqs. 6-15).
//
// eps1 picks the slice angle phi_p in [-beta, beta] by its cumulative solid angle, eqs. (6)-(8)
// and (13); eps2 interpolates the slice's altitude between -h_p and h_p, eq. (14); the point is
// eq. (15) in the frame R_e (the cylinder's axis is x_e). The root of eq. (13) is found by
// safeguarded Newton with the exact derivative dOmega_p/dphi_p = 2 h_p(phi_p), eq. (6); h_p
// vanishes at the rim, where the bracket takes over. Each half is solved from its own end
// (eq. 7), so eps1 near 0 does not subtract two nearly equal halves.
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
  double half = 0.0;  // Omega_p^+(beta) = Omega / 2
  double pdf = 0.0;

  static ParallelMap make(const Vec3& center, const Vec3& normal, double radius, const Vec3& o) {
    ParallelMap m;
    m.g = MapGeometry::make(center, normal, radius, o);
    if (m.g.empty) return m;
    m.half = 0.5 * m.g.omega;
    m.pdf = 1.0 / m.g.omega;
    return m;
  }
  bool valid() const { return !g.empty; }

  // phi_p in [0, beta] with Omega_p^+(phi_p) = f * half, f in [0, 1].
  double solve_half(double f, int* iterations) const {
    if (iterations) *iterations = 0;
    if (!(f > 0.0)) return 0.0;
    if (!(f < 1.0)) return g.beta;
    const double target = f * half;
    auto eval = [this, target](double phi) {
      return std::pair<double, double>(g.parallel_half(phi) - target, 2.0 * g.hp(phi));
    };
    // Start from the slice fraction of a planar ellipse, f = (2/pi)(t sqrt(1-t^2) + asin t)
    // with t = sin(varphi): one Newton step on that cubic-like curve is enough for a seed.
    const double start = f * g.beta;
    const math::RootResult r =
        math::safeguarded_newton(eval, 0.0, g.beta, start, kParallelNewtonTol * g.omega, 1e-17, 64);
    if (iterations) *iterations = r.iterations;
    return r.x;
  }

  EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    if (g.empty) return {};
    const double e1 = std::clamp(u.x, 0.0, 1.0), e2 = std::clamp(u.y, 0.0, 1.0);
    // Eq. (7): eps1 >= 1/2 lies in the positive half, the rest mirrored.
    const bool positive = e1 >= 0.5;
    const double f = positive ? 2.0 * e1 - 1.0 : 1.0 - 2.0 * e1;
    const double phi = solve_half(f, iterations);
    const double phi_p = positive ? phi : -phi;
    const double h = (2.0 * e2 - 1.0) * g.hp(phi);  // eq. (14)
    const double rho = std::sqrt(std::max(0.0, (1.0 - h) * (1.0 + h)));
    const Vec3 local(h, rho * std::sin(phi_p), rho * std::cos(phi_p));  // eq. (15)
    return finish_sample(g, local, pdf);
  }

  Point2 invert_local(const Vec3& l) const {
    if (g.empty) return {};
    const double phi_p = std::atan2(l.y(), l.z());
    const double phi = std::min(std::abs(phi_p), g.beta);
    const double f = std::clamp(g.parallel_half(phi) / half, 0.0, 1.0);
    const double e1 = std::signbit(phi_p) ? 0.5 - 0.5 * f : 0.5 + 0.5 * f;
    const double hp = g.hp(phi);
    const double e2 = hp > 0.0 ? std::clamp(0.5 * (l.x() / hp + 1.0), 0.0, 1.0) : 0.5;
    return {e1, e2};
  }
  Point2 invert(const Vec3& direction) const { return invert_local(g.to_local(direction)); }
};

}  // namespace disklab::ellipse
