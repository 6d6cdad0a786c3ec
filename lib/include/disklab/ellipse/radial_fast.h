#pragma once
// Table-seeded exact radial map (beyond the paper): the tabulated map's table gives the azimuth
// of eps1 to the table's accuracy, safeguarded Newton (radial.h) finishes to the exact map's
// tolerance (kRadialNewtonTol). Same outputs and inverse as RadialMap; only the start differs.
#include <algorithm>
#include <cmath>

#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/tabulated.h"

namespace disklab::ellipse {

struct RadialFastMap {
  RadialMap radial;
  TabulatedMap table;  // only its interpolated rows are used (the seed)

  static RadialFastMap make(const Vec3& center, const Vec3& normal, double radius, const Vec3& o,
                            const RadialTable& t = RadialTable::shared()) {
    RadialFastMap m;
    m.radial = RadialMap::make(center, normal, radius, o);
    m.table = TabulatedMap::make(center, normal, radius, o, t);
    return m;
  }
  bool valid() const { return radial.valid(); }
  double pdf() const { return radial.pdf; }

  // The seed: the table's phi for t, converted to the parametric angle s of radial.h.
  double seed_s(double t) const {
    const int n = table.table->n_eps;
    const double x = t * n;
    const int j = std::min(n - 1, static_cast<int>(x));
    const double phi_j = table.phi_at(j);
    const double phi = phi_j + (x - j) * (table.phi_at(j + 1) - phi_j);
    const MapGeometry& g = radial.g;
    return std::atan2(g.a * std::sin(phi), g.b * std::cos(phi));
  }

  EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    if (!radial.valid()) return {};
    double t;
    const int k = split_quadrant(u.x, t);
    const RadialQuadrant q = radial.quadrant();
    const double s = q.solve_s(t, iterations, seed_s(t));
    return finish_sample(radial.g, q.local_point(k, s, std::clamp(u.y, 0.0, 1.0)), radial.pdf);
  }
  Point2 invert_local(const Vec3& l) const { return radial.invert_local(l); }
  Point2 invert(const Vec3& direction) const { return radial.invert(direction); }
};

}  // namespace disklab::ellipse
