#pragma once
// Table-seeded exact radial map (beyond the paper): a table gives the parametric angle s of eps1
// to ~1e-9, one safeguarded Newton evaluation (radial.h, RadialQuadrant::solve) finishes to the
// exact map's tolerance (kRadialNewtonTol), usually without a confirming second evaluation. Same
// outputs and inverse as RadialMap; only the start differs.
//
// The table is per shading point: s(t) at kSeedIntervals + 1 equally spaced quadrant fractions t
// (solved exactly at set-up), with its first two derivatives in closed form,
//     s'(t) = Q / Omega'(s),   s''(t) = -Q^2 Omega''(s) / Omega'(s)^3,
//     Omega'(s) = a b / (1 + h_r),   Omega''(s) = -a b h_r' / (1 + h_r)^2   (eq. 16 in s),
// joined by quintic Hermite pieces (error ~ H^6 |s^(6)| / 46080, H = 1/16). The shared far-field
// table of the tabulated map (Sec. 4.1) is too coarse for this: at the table's alpha_ref its rows
// are the planar map to O(alpha^2), so in s they add nothing to the planar start t pi/2. It is
// still the seed when the radial series is unavailable (RadialSeries::n == 0, rare near disks).
#include <algorithm>
#include <cmath>

#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/tabulated.h"

namespace disklab::ellipse {

struct RadialFastMap {
  static constexpr int kSeedIntervals = 16;

  RadialMap radial;
  TabulatedMap table;                   // the shared-table seed, built only when `hermite` is false
  bool hermite = false;                 // the per-shading-point seed below is in use
  double poly[kSeedIntervals][6] = {};  // s on [j/M, (j+1)/M] as a quintic in the local x

  static RadialFastMap make(const Disk& disk, const Vec3& o,
                            const RadialTable& t = RadialTable::shared()) {
    RadialFastMap m;
    m.radial = RadialMap::make(disk, o);
    if (!m.radial.valid()) return m;
    if (m.radial.series.n > 0) {
      m.build_hermite();
    } else {
      m.table = TabulatedMap::make(disk, o, t);
    }
    return m;
  }
  bool valid() const { return radial.valid(); }
  double pdf() const { return radial.pdf; }

  // The shared table's seed: its phi for t, converted to the parametric angle s of radial.h.
  double seed_s(double t) const {
    if (table.table == nullptr || table.g.empty) return t * math::kHalfPi;
    const int n = table.table->n_eps;
    const double x = t * n;
    const int j = std::min(n - 1, static_cast<int>(x));
    const double phi_j = table.phi_at(j);
    const double phi = phi_j + (x - j) * (table.phi_at(j + 1) - phi_j);
    const MapGeometry& g = radial.g;
    return std::atan2(g.a * std::sin(phi), g.b * std::cos(phi));
  }

  // The per-shading-point seed (Horner on the piece of t).
  double hermite_seed(double t) const {
    const double x = t * kSeedIntervals;
    const int j = std::clamp(static_cast<int>(x), 0, kSeedIntervals - 1);
    const double f = x - j;
    const double* c = poly[j];
    return c[0] + f * (c[1] + f * (c[2] + f * (c[3] + f * (c[4] + f * c[5]))));
  }

  EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    if (!radial.valid()) return {};
    double t;
    const int k = split_quadrant(u.x, t);
    const RadialQuadrant q = radial.quadrant();
    const double s0 = hermite ? hermite_seed(t) : seed_s(t);
    return finish_sample(radial.g,
                         q.local_point(k, q.solve(t, iterations, s0), std::clamp(u.y, 0.0, 1.0)),
                         radial.pdf);
  }
  Point2 invert_local(const Vec3& l) const { return radial.invert_local(l); }
  Point2 invert(const Vec3& direction) const { return radial.invert(direction); }

 private:
  void build_hermite() {
    const MapGeometry& g = radial.g;
    const RadialQuadrant q = radial.quadrant();
    const double Q = radial.series.quadrant, ab = g.a * g.b;
    const double A = g.one_minus_a2, B = g.one_minus_b2, diff = g.a2_minus_b2;
    constexpr int M = kSeedIntervals;
    constexpr double H = 1.0 / M;
    double s[M + 1], d1[M + 1], d2[M + 1];
    for (int j = 0; j <= M; ++j) {
      const RadialQuadrant::Angle a = q.solve(static_cast<double>(j) / M);
      const double h = std::sqrt(std::max(0.0, A * a.cs * a.cs + B * a.ss * a.ss));
      const double w1 = ab / (1.0 + h);                          // Omega'
      const double hp = h > 0.0 ? diff * a.ss * a.cs / h : 0.0;  // h_r'
      const double w2 = -ab * hp / ((1.0 + h) * (1.0 + h));      // Omega''
      s[j] = a.s;
      d1[j] = Q / w1;
      d2[j] = -Q * Q * w2 / (w1 * w1 * w1);
      if (!std::isfinite(d1[j]) || !std::isfinite(d2[j])) return;  // keep the table seed
    }
    for (int j = 0; j < M; ++j) {
      const double p0 = s[j], p1 = s[j + 1], dp = p1 - p0;
      const double m0 = H * d1[j], m1 = H * d1[j + 1];
      const double c0 = H * H * d2[j], c1 = H * H * d2[j + 1];
      double* c = poly[j];
      c[0] = p0;
      c[1] = m0;
      c[2] = 0.5 * c0;
      c[3] = 10.0 * dp - 6.0 * m0 - 4.0 * m1 - 1.5 * c0 + 0.5 * c1;
      c[4] = -15.0 * dp + 8.0 * m0 + 7.0 * m1 + 1.5 * c0 - c1;
      c[5] = 6.0 * dp - 3.0 * m0 - 3.0 * m1 - 0.5 * c0 + 0.5 * c1;
    }
    hermite = true;
  }
};

}  // namespace disklab::ellipse
