#pragma once
// Seeded exact radial map (beyond the paper): the exact radial map of radial.h, started from a
// per-shading-point seed of its inverse instead of the planar answer s = t pi/2. The seed is a
// short sine series in tau = t pi/2,
//     s(t) ~ tau + sum_k c_k sin(2 k tau),
// the form of the inverse of Omega_r(s) = a_0 s + sum_k b_k sin(2 k s) (radial_series.h); its
// coefficients follow from exact solves at t_j = j/N by a sine transform (DST-I, N = 8 or 16),
// and it lives in the capacity the radial series leaves free, so the sampler stays small. Seeds
// are made accurate enough that Newton's first step provably meets the tolerance (the curvature
// bound of RadialQuadrant::solve), so one evaluation of Omega_r per sample usually suffices.
// Same outputs and inverse as RadialMap up to the root tolerance; only the start differs.
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

  RadialMap radial;

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

  EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    if (iterations) *iterations = 0;
    if (!radial.valid() || !in_unit_square(u)) return {};
    double t;
    const int k = split_quadrant(u.x, t);
    const RadialQuadrant q = radial.quadrant();
    const ParametricAngle s = q.solve_from(t, radial.series.seed(t), iterations);
    return finish_sample(radial.g, q.local_point(k, s, std::clamp(u.y, 0.0, 1.0)),
                         radial.uniform_pdf);
  }
  Point2 invert_local(const Vec3& l) const { return radial.invert_local(l); }
  Point2 invert(const Vec3& direction) const { return radial.invert(direction); }

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
    if (!(curvature > 0.0)) return;  // a circle: s = tau exactly
    // Newton's step delta is final when M delta^2 <= tol, M <= curvature / 2 (sin s cos s <= 1/2).
    const double tol = kRadialNewtonTol * q.quadrant_solid_angle();
    const double target = kSeedMargin * std::sqrt(tol / (0.5 * curvature));
    if (!(target > 0.0) || !std::isfinite(target)) return;
    // From a_0 s + B(s) = a_0 tau, |s - tau| <= sum |b_k| / a_0: the planar start may suffice.
    if (series.n > 0) {
      double sum = 0.0;
      for (int k = 0; k < series.n; ++k)
        sum += std::abs(series.b[k]);
      if (sum <= target * series.a0) return;
    }
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
    for (int j = 2; j < kSeedNodes; j += 2)
      sample_node(j);
    int nodes = kSeedNodes / 2;
    transform(nodes);
    // Undecayed last terms mean the 8-node transform aliases: refine with the odd nodes.
    if (std::abs(c[nodes - 2]) + std::abs(c[nodes - 3]) > 0.25 * target) {
      for (int j = 1; j < kSeedNodes; j += 2)
        sample_node(j);
      nodes = kSeedNodes;
      transform(nodes);
    }
    int count = nodes - 1;
    double dropped = 0.0;
    while (count > 0 && dropped + std::abs(c[count - 1]) <= 0.5 * target)
      dropped += std::abs(c[--count]);
    for (int k = 0; k < count; ++k)
      if (!std::isfinite(c[k])) return;
    // A seed longer than the free capacity is cut there (still a better start than tau).
    series.set_seed(c, std::min(count, series.seed_capacity()));
  }
};

}  // namespace disklab::ellipse
