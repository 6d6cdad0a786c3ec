#pragma once
// The published radial method of Guillén et al. 2017, re-implemented from the paper's text as a
// cost baseline for bench_maps (issue 16): what a renderer gets from the authors' approach,
// measured in the same run as disklab's maps.
//
//  - PublishedRadial<Policy>: eq. (19) evaluated as printed with Boost's ellint_3 (Policy: Boost's
//    default, which promotes double to long double, or promote_double<false>); the planar
//    ellipse's answer as the initial guess; Newton on eq. (21) in the azimuth phi with the
//    derivative dOmega_r/dphi = 1 - h_r(phi) of eq. (16), clamped to [0, pi/2] and stopped when
//    |Omega_r(phi) - t Omega_r(pi/2)| < 1e-5 sr (absolute); the direction by eq. (22).
//  - PublishedTabulated: Sec. 4.1's tabulation, a 1024 x 1024 table of the quadrant fraction
//    Omega_r(phi) / Omega_r(pi/2) over beta' = beta / alpha (rows) and phi (columns, uniform);
//    per sample a binary search of t in the nearest row gives the cell, phi is interpolated in
//    it, and the cell's cap sector (1 - h uniform in [0, 1 - h_r(phi_j)], phi_j the cell's
//    start) is the proposal; points outside the ellipse are rejected with zero weight and every
//    sample reports pdf 1/Omega, as the paper's production renderer does (biased: see
//    docs/design.md, "Rejection must stay unbiased"). Omega comes from eq. (19) with Boost.
//
// Both use disklab's ellipse_shape (closed forms of Sec. 3) for alpha, beta, a, b, n, m and its
// eps1 quadrant convention, so that their samples can be compared with the exact map's.
#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/special_functions/ellint_3.hpp>

#include "disklab/ellipse/geometry.h"
#include "disklab/ellipse/quadrant.h"
#include "disklab/ellipse/sampler.h"
#include "disklab/math/constants.h"
#include "disklab/math/frame.h"

namespace disklab::bench {

namespace bm = boost::math;
using DoublePolicy = bm::policies::policy<bm::policies::promote_double<false>>;
using DefaultPolicy = bm::policies::policy<>;

// The paper's stopping tolerance and an iteration cap (the clamp keeps Newton in [0, pi/2], so
// the cap only bounds a pathological oscillation).
inline constexpr double kPublishedTolerance = 1e-5;
inline constexpr int kPublishedMaxIterations = 20;

// Per-shading-point geometry shared by both published variants.
struct PublishedGeometry {
  math::Frame frame;  // ellipse frame R_e (x_e along the major axis, z_e the ellipse centre)
  Vec3 o = Vec3::Zero(), center = Vec3::Zero(), normal = Vec3::UnitZ();
  double height = 0.0;  // of o above the disk's plane
  double a = 0, b = 0, a_t = 0, b_t = 0, alpha = 0, beta = 0;
  double k = 0, n = 0, C = 0;  // Boost's modulus sqrt(m), characteristic, eq. (19)'s coefficient
  double quadrant = 0.0, pdf = 0.0;
  bool valid = false;

  template <class Policy>
  static PublishedGeometry make(const ellipse::Disk& disk, const Vec3& o) {
    PublishedGeometry g;
    const Vec3 n = disk.normal.normalized();
    const Vec3 v = disk.center - o;
    const double h = -v.dot(n);
    if (!(h > 0.0) || !(disk.radius > 0.0)) return g;
    const Vec3 zd = -n;
    const Vec3 xd_raw = zd.cross(v);
    const double e = xd_raw.norm();
    const ellipse::EllipseShape s = ellipse::ellipse_shape(h, e, disk.radius);
    const Vec3 xd = e > 0.0 ? Vec3(xd_raw / e) : math::Frame::from_z(zd).x;
    const Vec3 yd = zd.cross(xd);
    g.frame.x = xd;
    g.frame.z = (s.ze_y * yd + s.ze_z * zd).normalized();
    g.frame.y = g.frame.z.cross(g.frame.x);
    g.o = o;
    g.center = disk.center;
    g.normal = n;
    g.height = h;
    g.a = s.a;
    g.b = s.b;
    g.a_t = s.a_t;
    g.b_t = s.b_t;
    g.alpha = s.alpha;
    g.beta = s.beta;
    g.k = std::sqrt(s.m);
    g.n = s.n_r;
    g.C = s.radial_coefficient;
    // Eq. (19) at phi = pi/2 as printed.
    g.quadrant = math::kHalfPi - g.C * bm::ellint_3(g.k, g.n, math::kHalfPi, Policy());
    g.pdf = 1.0 / (4.0 * g.quadrant);
    g.valid = g.quadrant > 0.0 && std::isfinite(g.pdf);
    return g;
  }

  // Eq. (18) squared and eq. (17): h_r(phi).
  double h_r(double sin_phi, double cos_phi) const {
    const double as = a * sin_phi, bc = b * cos_phi;
    const double r2 = (a * b) * (a * b) / (as * as + bc * bc);
    return std::sqrt(std::max(0.0, 1.0 - r2));
  }

  // Eq. (22) with eps2 = 0 at the centre (docs/design.md), unfolded into quadrant k, and the hit.
  ellipse::EllipseSample finish(int k, double phi, double hr, double eps2) const {
    const double h = 1.0 - eps2 * (1.0 - hr);
    const double rho = std::sqrt(std::max(0.0, 1.0 - h * h));
    ellipse::EllipseSample out;
    out.local = ellipse::unfold_direction(k, rho * std::cos(phi), rho * std::sin(phi), h);
    out.direction = frame.to_world(out.local);
    const double den = -out.direction.dot(normal);
    out.point = o + (height / den) * out.direction;
    out.pdf = pdf;
    out.valid = true;
    return out;
  }
};

template <class Policy>
struct PublishedRadial {
  PublishedGeometry g;

  static PublishedRadial make(const ellipse::Disk& disk, const Vec3& o) {
    return {PublishedGeometry::make<Policy>(disk, o)};
  }
  bool valid() const { return g.valid; }

  // Eq. (19): Omega_r(phi) = phi - C Pi(n; varphi_r | m), tan varphi_r = (a_t / b_t) tan phi.
  double sector(double phi) const {
    const double vphi = std::atan2(g.a_t * std::sin(phi), g.b_t * std::cos(phi));
    return phi - g.C * bm::ellint_3(g.k, g.n, vphi, Policy());
  }

  ellipse::EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    if (iterations) *iterations = 0;
    if (!g.valid || !ellipse::in_unit_square(u)) return {};
    double t;
    const int k = ellipse::split_quadrant(u.x, t);
    // The planar ellipse's sector area is linear in its parametric angle s: s = t pi/2, and
    // tan phi = (b / a) tan s.
    const double s0 = t * math::kHalfPi;
    double phi = std::atan2(g.b * std::sin(s0), g.a * std::cos(s0));
    const double target = t * g.quadrant;
    for (int i = 0; i < kPublishedMaxIterations; ++i) {
      const double f = sector(phi) - target;
      if (iterations) ++*iterations;
      if (std::abs(f) < kPublishedTolerance) break;
      const double deriv = 1.0 - g.h_r(std::sin(phi), std::cos(phi));  // eq. (16)
      phi = std::clamp(phi - f / deriv, 0.0, math::kHalfPi);
    }
    return g.finish(k, phi, g.h_r(std::sin(phi), std::cos(phi)), std::clamp(u.y, 0.0, 1.0));
  }
};

// Sec. 4.1's table: quadrant fractions over beta' (rows) and phi (uniform columns).
struct PublishedTable {
  static constexpr int kRows = 1024, kCells = 1024;
  static constexpr double kAlphaRef = 1e-3;  // the fraction is taken as independent of alpha
  std::vector<double> cdf;                   // kRows x (kCells + 1)

  const double* row(int i) const { return cdf.data() + static_cast<std::size_t>(i) * (kCells + 1); }
  std::size_t bytes() const { return cdf.size() * sizeof(double); }

  // Each row integrates 1 - h_r(phi) (eq. 16) by Simpson's rule on 8 panels per cell.
  static const PublishedTable& shared() {
    static const PublishedTable table = [] {
      PublishedTable t;
      t.cdf.assign(static_cast<std::size_t>(kRows) * (kCells + 1), 0.0);
      const double a = std::sin(kAlphaRef);
      constexpr int kPanels = 8;
      const double dphi = math::kHalfPi / kCells, hstep = dphi / kPanels;
      for (int i = 0; i < kRows; ++i) {
        const double b = std::sin(kAlphaRef * i / (kRows - 1));
        auto f = [a, b](double phi) {
          const double as = a * std::sin(phi), bc = b * std::cos(phi);
          const double den = as * as + bc * bc;
          const double r2 = den > 0.0 ? (a * b) * (a * b) / den : 0.0;
          return r2 / (1.0 + std::sqrt(1.0 - r2));
        };
        double* r = t.cdf.data() + static_cast<std::size_t>(i) * (kCells + 1);
        double acc = 0.0;
        for (int j = 0; j < kCells; ++j) {
          const double p0 = j * dphi;
          double cell = 0.0;
          for (int p = 0; p < kPanels; ++p) {
            const double x = p0 + p * hstep;
            cell += hstep / 6.0 * (f(x) + 4.0 * f(x + 0.5 * hstep) + f(x + hstep));
          }
          acc += cell;
          r[j + 1] = acc;
        }
        for (int j = 1; j <= kCells; ++j)
          r[j] = acc > 0.0 ? r[j] / acc : double(j) / kCells;
      }
      return t;
    }();
    return table;
  }
};

struct PublishedTabulated {
  PublishedGeometry g;
  const double* row = nullptr;

  static PublishedTabulated make(const ellipse::Disk& disk, const Vec3& o,
                                 const PublishedTable& table = PublishedTable::shared()) {
    PublishedTabulated m;
    m.g = PublishedGeometry::make<DoublePolicy>(disk, o);
    if (!m.g.valid) return m;
    const double bp = std::clamp(m.g.beta / m.g.alpha, 0.0, 1.0);
    m.row = table.row(static_cast<int>(std::lround(bp * (PublishedTable::kRows - 1))));
    return m;
  }
  bool valid() const { return g.valid; }

  ellipse::EllipseSample sample(Point2 u) const {
    if (!g.valid || !ellipse::in_unit_square(u)) return {};
    double t;
    const int k = ellipse::split_quadrant(u.x, t);
    constexpr int n = PublishedTable::kCells;
    const int j = std::clamp(
        static_cast<int>(std::upper_bound(row + 1, row + n + 1, t) - (row + 1)), 0, n - 1);
    const double dphi = math::kHalfPi / n;
    const double w = row[j + 1] > row[j] ? (t - row[j]) / (row[j + 1] - row[j]) : 0.0;
    const double phi = (j + std::clamp(w, 0.0, 1.0)) * dphi;
    // The cap sector of the cell: 1 - h_r is largest at the cell's start (it decreases on the
    // first quadrant), so the sector from there covers the ellipse's part of the cell.
    const double hr_start = g.h_r(std::sin(j * dphi), std::cos(j * dphi));
    ellipse::EllipseSample out = g.finish(k, phi, hr_start, std::clamp(u.y, 0.0, 1.0));
    if (out.local.z() < g.h_r(std::sin(phi), std::cos(phi))) {
      out.valid = false;  // outside the ellipse: zero weight, pdf still 1/Omega (the paper's)
      out.point = Vec3::Zero();
    }
    return out;
  }
};

}  // namespace disklab::bench
