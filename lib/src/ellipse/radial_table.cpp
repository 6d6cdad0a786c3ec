// Construction of the tabulated radial map's table (Guillén et al. 2017, Sec. 4.1).
#include <cmath>

#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/tabulated.h"
#include "disklab/math/constants.h"

namespace disklab::ellipse {

namespace {

// A disk of radius 1 seen from the origin at distance D = 1 / tan(alpha_ref) and view angle theta
// from its normal; its beta / alpha decreases from 1 (theta = 0) to 0 (theta -> pi/2).
MapGeometry scene(double alpha_ref, double theta) {
  const double D = 1.0 / std::tan(alpha_ref);
  const Vec3 c(D * std::sin(theta), 0.0, D * std::cos(theta));
  return MapGeometry::make(Disk{c, Vec3(0, 0, -1), 1.0, false}, Vec3::Zero());
}

// The scene whose beta / alpha equals `ratio` (bisection on the view angle; not a hot path).
MapGeometry scene_with_ratio(double alpha_ref, double ratio) {
  double lo = 0.0, hi = math::kHalfPi;
  MapGeometry g = scene(alpha_ref, 0.0);
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    g = scene(alpha_ref, mid);
    if (g.empty || g.beta / g.alpha < ratio) {
      hi = mid;
    } else {
      lo = mid;
    }
  }
  return scene(alpha_ref, lo);
}

}  // namespace

RadialTable RadialTable::build(int n_beta, int n_eps, double alpha_ref) {
  RadialTable t;
  t.n_beta = std::max(2, n_beta);
  t.n_eps = std::max(1, n_eps);
  t.alpha_ref = alpha_ref;
  t.phi.assign(static_cast<std::size_t>(t.n_beta) * (t.n_eps + 1), 0.0);
  for (int k = 0; k < t.n_beta; ++k) {
    double* row = t.phi.data() + static_cast<std::size_t>(k) * (t.n_eps + 1);
    const double bp = static_cast<double>(k) / (t.n_beta - 1);
    row[t.n_eps] = math::kHalfPi;
    if (k == 0) continue;  // beta' -> 0: the quadrant's area sits at phi = 0 (the rows' limit)
    const MapGeometry g = scene_with_ratio(alpha_ref, bp);
    if (g.empty) continue;
    const RadialQuadrant q{&g};
    for (int j = 1; j < t.n_eps; ++j) {
      const double frac = static_cast<double>(j) / t.n_eps;
      const double s = q.solve_s(frac);
      row[j] = std::atan2(g.b * std::sin(s), g.a * std::cos(s));
    }
  }
  return t;
}

const RadialTable& RadialTable::shared() {
  static const RadialTable table = build(kDefaultBeta, kDefaultEps, kDefaultAlphaRef);
  return table;
}

}  // namespace disklab::ellipse
