// Construction of the tabulated radial map's table (Guillén et al. 2017, Sec. 4.1).
#include <cmath>

#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/tabulated.h"
#include "disklab/math/constants.h"

namespace disklab::ellipse {

RadialTable RadialTable::build(int n_beta, int n_eps, double alpha_ref) {
  RadialTable t;
  t.n_beta = std::max(2, n_beta);
  t.n_eps = std::max(1, n_eps);
  t.alpha_ref = alpha_ref;
  t.phi.assign(static_cast<std::size_t>(t.n_beta) * (t.n_eps + 1), 0.0);
  for (int k = 0; k < t.n_beta; ++k) {
    double* row = t.phi.data() + static_cast<std::size_t>(k) * (t.n_eps + 1);
    const double bp = static_cast<double>(k) / (t.n_beta - 1);
    if (k == 0) {  // beta' -> 0: the quadrant's area sits at phi = 0 (limit of the other rows)
      for (int j = 0; j < t.n_eps; ++j)
        row[j] = 0.0;
      row[t.n_eps] = math::kHalfPi;
      continue;
    }
    const MapGeometry g = MapGeometry::from_arcs(alpha_ref, bp * alpha_ref);
    const RadialQuadrant q{&g};
    double s_prev = 0.0;
    for (int j = 0; j <= t.n_eps; ++j) {
      const double frac = static_cast<double>(j) / t.n_eps;
      const double s =
          q.solve_s(frac, nullptr, j == 0 ? -1.0 : std::max(s_prev, frac * math::kHalfPi));
      s_prev = s;
      row[j] = std::atan2(g.b * std::sin(s), g.a * std::cos(s));
    }
    row[0] = 0.0;
    row[t.n_eps] = math::kHalfPi;
  }
  return t;
}

const RadialTable& RadialTable::shared() {
  static const RadialTable table = build(kDefaultBeta, kDefaultEps, kDefaultAlphaRef);
  return table;
}

}  // namespace disklab::ellipse
