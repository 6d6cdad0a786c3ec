#pragma once
// Seeded exact radial map (beyond the paper): the exact radial map of radial.h, with a
// per-shading-point approximation of its inverse. The inverse is a short sine series in
// tau = t pi/2,
//     s(t) ~ tau + sum_k c_k sin(2 k tau),
// the form of the inverse of Omega_r(s) = a_0 s + sum_k b_k sin(2 k s) (radial_series.h), whose
// coefficients decay like the forward series' (the same branch points, mapped); they follow from
// exact solves at t_j = j/N by a sine transform (DST-I, N = 8 or 16), and live in the capacity
// the radial series leaves free, so the sampler stays small. Two modes, chosen at set-up:
//  - direct: where the series reaches the root tolerance within that capacity, and its residual
//    |Omega_r(s(t)) - t Omega_q| checked at the N midpoints t_j + 1/(2N) (where the error of a
//    trigonometric interpolant peaks) is at most kDirectTol of the quadrant, a sample is the
//    series' s with no evaluation of Omega_r at all;
//  - seeded Newton: otherwise the series is cut to a seed accurate enough that Newton's first
//    step provably meets the tolerance (the curvature bound of RadialQuadrant::solve).
// Same outputs and inverse as RadialMap up to the root tolerance; only how s is found differs.
#include <algorithm>
#include <cmath>

#include "disklab/ellipse/radial.h"

namespace disklab::ellipse {

struct RadialFastMap {
  // Largest sine transform of the seed: 15 coefficients.
  static constexpr int kSeedNodes = 16;
  // The seed aims at this fraction of the error below which Newton's first step needs no
  // confirming evaluation.
  static constexpr double kSeedMargin = 0.5;
  // Direct mode's largest residual at the checks, as a fraction of the quadrant: eps1 = (k + t)/4
  // is off by at most 1e-15 there, ten times below the 1e-14 the maps promise (room for what lies
  // between the checks; `RadialFast.DirectModeMeetsItsTolerance` measures it on a dense grid).
  static constexpr double kDirectTol = 4e-15;

  RadialMap radial;  // its series' seed_exact: direct mode

  static RadialFastMap make(const Disk& disk, const Vec3& o) noexcept {
    RadialFastMap m;
    m.radial = RadialMap::make(disk, o);
    if (m.radial.valid()) m.build_seed();
    return m;
  }
  bool valid() const { return radial.valid(); }
  double pdf(const Vec3& direction) const { return radial.pdf(direction); }
  // Terms of the seed (0: the planar start is already good enough, or nothing fits).
  int seed_terms() const { return radial.series.n_seed; }
  // Whether samples take the series' s directly (no evaluation of Omega_r).
  bool is_direct() const { return radial.series.seed_exact; }

  EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    if (iterations) *iterations = 0;
    if (!radial.valid() || !in_unit_square(u)) return {};
    double t;
    const int k = split_quadrant(u.x, t);
    const RadialQuadrant q = radial.quadrant();
    const ParametricAngle s =
        is_direct() ? radial.series.seed(t) : q.solve_from(t, radial.series.seed(t), iterations);
    return finish_sample(radial.g, q.local_point(k, s, std::clamp(u.y, 0.0, 1.0)),
                         radial.uniform_pdf);
  }
  Point2 invert_local(const Vec3& l) const { return radial.invert_local(l); }
  Point2 invert(const Vec3& direction) const { return radial.invert(direction); }

  // Largest |Omega_r(s(t)) - t Omega_q| of the stored seed at the midpoints t = (j + 1/2) / nodes
  // of a transform's nodes (where a trigonometric interpolant's error peaks): direct mode's check.
  double residual_checked(int nodes) const {
    const RadialQuadrant q = radial.quadrant();
    const double quadrant = q.quadrant_solid_angle();
    double worst = 0.0;
    for (int j = 0; j < nodes; ++j) {
      const double t = (j + 0.5) / nodes;
      const ParametricAngle s = radial.series.seed(t);
      const double omega = q.use_series() ? radial.series.omega(s.s, s.cs, s.ss) : q.sector_s(s.s);
      const double r = std::abs(omega - t * quadrant);
      worst = std::isfinite(r) ? std::max(worst, r) : HUGE_VAL;
    }
    return worst;
  }

 private:
  // sin(m pi / 16), m = 0..31: the DST's kernel sin(j k pi / N) for N = 16 (and 8, by stride).
  static const double* sine_table() {
    static const auto table = [] {
      struct T {
        double v[2 * kSeedNodes];
      } t{};
      for (int m = 0; m < 2 * kSeedNodes; ++m)
        t.v[m] = std::sin(m * math::kPi / kSeedNodes);
      return t;
    }();
    return table.v;
  }

  void build_seed() {
    const MapGeometry& g = radial.g;
    RadialSeries& series = radial.series;
    const RadialQuadrant q = radial.quadrant();
    const double h_min = g.cos_alpha;
    const double curvature = g.a * g.b * g.a2_minus_b2 / (h_min * (1.0 + h_min) * (1.0 + h_min));
    if (!(curvature > 0.0)) {  // a circle: s = tau exactly
      series.seed_exact = curvature == 0.0;
      return;
    }
    const double quadrant = q.quadrant_solid_angle();
    // Newton's step delta is final when M delta^2 <= tol, M <= curvature / 2 (sin s cos s <= 1/2).
    const double tol = kRadialNewtonTol * quadrant;
    const double target = kSeedMargin * std::sqrt(tol / (0.5 * curvature));
    // An error ds in s moves Omega_r by at most a b |ds| (its derivative is a b / (1 + h_r)).
    const double direct_target = kDirectTol * quadrant / (g.a * g.b);
    if (!(target > 0.0) || !std::isfinite(target) || !(direct_target > 0.0)) return;
    // From a_0 s + B(s) = a_0 tau, |s - tau| <= sum |b_k| / a_0: the planar start may suffice.
    if (series.n > 0) {
      double sum = 0.0;
      for (int k = 0; k < series.n; ++k)
        sum += std::abs(series.b[k]);
      if (sum <= direct_target * series.a0) {
        series.seed_exact = true;
        return;
      }
    }
    if (series.seed_capacity() == 0) return;  // no room for a series: Newton from tau
    // f_j = s(j / 16) - tau_j on the 16-node grid; the 8-node transform reads the even nodes.
    double f[kSeedNodes] = {};
    auto sample_node = [&](int j) {
      const double t = static_cast<double>(j) / kSeedNodes;
      f[j] = q.solve(t).s - t * math::kHalfPi;
    };
    const double* sine = sine_table();
    double c[kSeedNodes] = {};
    auto transform = [&](int nodes) {
      const std::size_t stride = kSeedNodes / nodes, period = std::size_t{2} * kSeedNodes;
      for (int k = 1; k < nodes; ++k) {
        double sum = 0.0;
        for (std::size_t j = 1; j < static_cast<std::size_t>(nodes); ++j)
          sum += f[j * stride] * sine[(j * static_cast<std::size_t>(k) * stride) % period];
        c[k - 1] = (2.0 / nodes) * sum;
      }
    };
    // Terms kept for an accuracy: trailing terms whose sum stays within half of it are dropped.
    auto terms_for = [&](int nodes, double accuracy) {
      int count = nodes - 1;
      double dropped = 0.0;
      while (count > 0 && dropped + std::abs(c[count - 1]) <= 0.5 * accuracy)
        dropped += std::abs(c[--count]);
      return count;
    };
    auto finite = [&](int nodes) {
      for (int k = 0; k < nodes - 1; ++k)
        if (!std::isfinite(c[k])) return false;
      return true;
    };
    // Direct mode when the series fits and its residual checks pass (the checks decide, since
    // what the transform aliases is not known from its coefficients alone).
    auto try_direct = [&](int nodes) {
      return finite(nodes) && series.set_seed(c, terms_for(nodes, direct_target)) &&
             residual_checked(nodes) <= kDirectTol * quadrant;
    };
    for (int j = 2; j < kSeedNodes; j += 2)
      sample_node(j);
    int nodes = kSeedNodes / 2;
    transform(nodes);
    if (try_direct(nodes)) {
      series.seed_exact = true;
      return;
    }
    // The 8-node transform aliases too much for direct mode: refine with the odd nodes.
    for (int j = 1; j < kSeedNodes; j += 2)
      sample_node(j);
    nodes = kSeedNodes;
    transform(nodes);
    if (try_direct(nodes)) {
      series.seed_exact = true;
      return;
    }
    // A seed longer than the free capacity is cut there (still a better start than tau).
    series.set_seed(c,
                    finite(nodes) ? std::min(terms_for(nodes, target), series.seed_capacity()) : 0);
  }
};

}  // namespace disklab::ellipse
