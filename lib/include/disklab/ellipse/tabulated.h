#pragma once
// Tabulated radial map (Guillén et al. 2017, Sec. 4.1), made unbiased.
//
// The table holds the radial map's azimuth phi_r as a function of the quadrant fraction t on a
// grid over beta' = beta/alpha (rows) and t (columns), computed with the exact radial map at a
// reference semi-arc alpha_ref (the paper drops alpha because the fraction varies little with
// it; alpha_ref = 1e-3 is the far-field limit, where the fraction depends on b/a ~ beta' only).
// Per sample, bilinear interpolation gives the cell [phi_j, phi_j+1] of eps1; within the cell the
// proposal is the cylindrical sector phi in [phi_j, phi_j+1], 1 - h in [0, 1 - h_r(phi_j)],
// sampled uniformly in solid angle by the Hat-Box theorem (eps2 = 0 at the centre). 1 - h_r
// decreases on the first quadrant, so the sector covers the ellipse's part of the cell; points
// outside the ellipse are rejected.
//
// Unbiasedness: the cells are chosen with probability 1/n (the table's), not in proportion to
// their proposal areas, so "loop until accepted with pdf 1/Omega" would be biased here. Instead
// the sample reports the PROPOSAL density 1 / (4 n dphi_j (1 - h_r(phi_j))) and a rejected
// candidate is returned with valid = false (weight zero). Since the proposal covers the
// ellipse, E[f 1_accepted / pdf] = int f exactly, whatever the table's error. The table's error
// only costs rejections and stratification quality. The authors' variant (pdf 1/Omega, zero on
// rejection) is available as `biased` for the tests that detect it.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "disklab/ellipse/map_geometry.h"
#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/sampler.h"

namespace disklab::ellipse {

struct RadialTable {
  int n_beta = 0;  // rows: beta' = k / (n_beta - 1)
  int n_eps = 0;   // cells per quadrant; columns t = j / n_eps, j = 0..n_eps
  double alpha_ref = 0.0;
  std::vector<double> phi;  // n_beta x (n_eps + 1), row-major

  static constexpr double kDefaultAlphaRef = 1e-3;
  static constexpr int kDefaultBeta = 256;
  static constexpr int kDefaultEps = 256;

  // Builds a table (cost: n_beta * n_eps root solves).
  static RadialTable build(int n_beta, int n_eps, double alpha_ref = kDefaultAlphaRef);
  // The library's default table, built on first use (thread-safe).
  static const RadialTable& shared();

  const double* row(int k) const { return phi.data() + static_cast<std::size_t>(k) * (n_eps + 1); }
};

struct TabulatedMap {
  MapGeometry g;
  const RadialTable* table = nullptr;
  const double* row0 = nullptr;
  const double* row1 = nullptr;
  double w = 0.0;            // interpolation weight between rows
  double pdf_uniform = 0.0;  // 1/Omega (for the biased variant and for reference)
  bool biased = false;       // the authors' estimator: pdf 1/Omega, zero on rejection

  static TabulatedMap make(const Disk& disk, const Vec3& o,
                           const RadialTable& table = RadialTable::shared()) {
    TabulatedMap m;
    m.g = MapGeometry::make(disk, o);
    m.table = &table;
    if (m.g.empty) return m;
    m.pdf_uniform = 1.0 / m.g.omega;
    const double bp = std::clamp(m.g.beta / m.g.alpha, 0.0, 1.0);
    const double x = bp * (table.n_beta - 1);
    const int k = std::min(table.n_beta - 2, static_cast<int>(x));
    m.w = x - k;
    m.row0 = table.row(k);
    m.row1 = table.row(k + 1);
    return m;
  }
  bool valid() const { return !g.empty; }

  double phi_at(int j) const { return row0[j] + w * (row1[j] - row0[j]); }

  EllipseSample sample(Point2 u) const {
    if (g.empty || !in_unit_square(u)) return {};
    double t;
    const int k = split_quadrant(u.x, t);
    const int n = table->n_eps;
    const double x = t * n;
    const int j = std::min(n - 1, static_cast<int>(x));
    const double f = x - j;
    const double phi_j = phi_at(j), phi_j1 = phi_at(j + 1);
    const double dphi = phi_j1 - phi_j;
    const double phi = phi_j + f * dphi;
    const double bound_j = g.one_minus_hr(phi_j);  // max of 1 - h_r over the cell
    const double omh = std::clamp(u.y, 0.0, 1.0) * bound_j;
    const double cp = std::cos(phi), sp = std::sin(phi);
    const double bound = g.one_minus_hr(sp, cp);
    const double rho = std::sqrt(std::max(0.0, omh * (2.0 - omh)));
    const double proposal = 1.0 / (4.0 * n * dphi * bound_j);
    if (!(proposal < HUGE_VAL)) return {};  // a cell of zero width: nothing to propose
    EllipseSample out =
        finish_sample(g, unfold_direction(k, rho * cp, rho * sp, 1.0 - omh), proposal);
    out.valid = omh <= bound;
    if (biased) out.pdf = pdf_uniform;
    return out;
  }

  // The table cell j of a first-quadrant azimuth: phi_at(j) <= phi < phi_at(j + 1) (binary
  // search).
  int cell_of(double phi) const {
    int lo = 0, hi = table->n_eps;
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      if (phi_at(mid) <= phi)
        lo = mid;
      else
        hi = mid;
    }
    return lo;
  }

  // Density of a direction as an accepted candidate: the proposal density of its cell inside the
  // disk's solid angle, 0 outside (it integrates to the acceptance rate). The biased variant
  // reports 1/Omega, as its samples do.
  double pdf(const Vec3& direction) const {
    if (!g.contains(direction)) return 0.0;
    if (biased) return pdf_uniform;
    const FoldedDirection fd = fold_direction(g.to_local(unit_vector(direction)));
    const int j = cell_of(std::atan2(fd.y, fd.x));
    const double proposal =
        1.0 / (4.0 * table->n_eps * (phi_at(j + 1) - phi_at(j)) * g.one_minus_hr(phi_at(j)));
    return proposal < HUGE_VAL ? proposal : 0.0;
  }

  // Direction -> (eps1, eps2) of this table (binary search of the cell; no root finding).
  Point2 invert_local(const Vec3& l) const {
    if (g.empty) return {};
    const FoldedDirection fd = fold_direction(l);
    const double phi = std::atan2(fd.y, fd.x);
    const int n = table->n_eps;
    const int lo = cell_of(phi);
    const double dphi = phi_at(lo + 1) - phi_at(lo);
    const double f = dphi > 0.0 ? std::clamp((phi - phi_at(lo)) / dphi, 0.0, 1.0) : 0.0;
    const double omh = one_minus_z(l);
    const double bound_j = g.one_minus_hr(phi_at(lo));
    return {join_quadrant(fd.k, (lo + f) / n),
            bound_j > 0.0 ? std::clamp(omh / bound_j, 0.0, 1.0) : 0.0};
  }
  Point2 invert(const Vec3& direction) const { return invert_local(g.to_local(direction)); }
};

}  // namespace disklab::ellipse
