#pragma once
// Projected-solid-angle (cosine-weighted) sampling of an oriented disk (beyond both papers):
// density p(w) = max(0, w . n_o) / P over the disk's spherical ellipse, n_o the receiver's
// normal and P = int max(0, w . n_o) dw (P / pi is the point-to-disk form factor). For an
// unoccluded Lambertian receiver f / p is constant: zero variance.
//
// Construction, in the ellipse frame R_e (Guillén et al. 2017, Sec. 3) with n = n_o in R_e:
//  - directions w = (sin t cos phi, sin t sin phi, cos t) around the ellipse's centre z_e; the
//    rim at the planar parametric angle s (tan s = (a/b) tan phi) is w_r(s) = (a cos s, b sin s,
//    h_r(s)), t_r = atan2(r, h_r), r^2 = a^2 cos^2 s + b^2 sin^2 s;
//  - along a meridian, the cosine A sin t + n_z cos t (A = n_x cos phi + n_y sin phi) has the
//    antiderivative F(t) = A S(t) + n_z sin^2(t) / 2 in dw = sin t dt dphi, S(t) = (t - sin t
//    cos t) / 2; the meridian's part above the horizon is [t_lo, t_hi] (t_h the horizon angle);
//  - eps1 = C(s) / P with C the projected solid angle of the sector [0, s], by Stokes
//    (int_R w dw = (1/2) oint w x dw on the unit sphere): the rim contributes
//    n . (w_r x w_r') = -n_x b cos^2(alpha) cos s / h_r - n_y a cos^2(beta) sin s / h_r + n_z a b,
//    whose antiderivative is elementary (asinh, asin), the meridians (1/2) (t_hi - t_lo) B(phi)
//    with B = n_y cos phi - n_x sin phi, the horizon (a great circle) its arc length. Unclipped,
//    C(2 pi) = P = pi a b n_z: the projected solid angle of a spherical ellipse is the area of
//    its planar projection times the cosine of its centre.
//  - eps2: F(t) = F(t_lo) + eps2 (F(t_hi) - F(t_lo)) on the meridian.
// Both solves are safeguarded Newton with exact derivatives (2 dC/ds = 2 (F(t_hi) - F(t_lo))
// a b / r^2, and dF/dt = sin t (A sin t + n_z cos t)). Continuous in u, so stratified input
// stays stratified. Unclipped sectors of ellipses the series can hold use a Chebyshev series
// of S(t_r) / r^3 in cos 2s (the radial series' machinery). Otherwise, and wherever the disk
// straddles the receiver's horizon (the turn split at the rim's horizon crossings), C comes from
// the reduced boundary form (piece_part): the same Stokes integral with w - z_e in place of w,
// whose every term is as small as P, so that no O(a) terms cancel down to P ~ a^3 for a small
// straddling ellipse; and n_z, O(a) there, is compensated from the exact inputs (make).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>

#include "disklab/ellipse/map_geometry.h"
#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/radial_series.h"
#include "disklab/ellipse/sampler.h"
#include "disklab/math/constants.h"
#include "disklab/math/roots.h"
#include "disklab/math/rotation.h"
#include "disklab/types.h"

namespace disklab::ellipse {

// Both root solves stop at this residual relative to their total (P, or the meridian's F range).
inline constexpr double kProjectedNewtonTol = 1e-15;

namespace projected_detail {

// S(t) = (t - sin t cos t) / 2 = (2t - sin 2t) / 4 for t < 0.5 (where the difference would
// cancel) by its Taylor series sum_{k>=1} (-1)^(k+1) (2t)^(2k+1) / (4 (2k+1)!) =
// (x^3 / 4) sum_{k>=1} (-1)^(k+1) y^(k-1) / (2k+1)!, x = 2t, y = x^2 < 1. The sum is
// alternating and above 0.158: K terms leave a remainder below y^K / (2K+3)! / 0.158, under
// 1.1e-16 with K = 3 for y < 1e-4, K = 5 for y < 1e-2 and K = 8 up to y = 1. Estrin's scheme:
// the altitude solve evaluates it per iterate. Finite (and unused) beyond t = 0.5.
inline double S_series(double t) {
  const double x = 2.0 * t, y = x * x, y2 = y * y;
  constexpr double c0 = 1.0 / 6, c1 = -1.0 / 120, c2 = 1.0 / 5040, c3 = -1.0 / 362880,
                   c4 = 1.0 / 39916800, c5 = -1.0 / 6227020800, c6 = 1.0 / 1307674368000,
                   c7 = -1.0 / 355687428096000;
  double p;
  if (y < 1e-4) {
    p = (c0 + c1 * y) + y2 * c2;
  } else if (y < 1e-2) {
    p = (c0 + c1 * y) + y2 * ((c2 + c3 * y) + y2 * c4);
  } else {
    const double y4 = y2 * y2;
    p = ((c0 + c1 * y) + y2 * (c2 + c3 * y)) + y4 * ((c4 + c5 * y) + y2 * (c6 + c7 * y));
  }
  return 0.25 * x * y * p;
}
inline double S(double t) {
  return t < 0.5 ? S_series(t) : 0.25 * (2.0 * t - std::sin(2.0 * t));
}

// G(r) = S(asin r) / r^3 as a function of r^2 < 1 (S'(r) = r^2 / sqrt(1 - r^2)): below r^2 = 1/4
// by its Maclaurin series sum_k c_k r^2k, c_k = C(2k, k) 4^-k / (2k + 3), above by the closed
// form, whose difference loses about 1.5 eps / r^2 relative.
inline constexpr int kGSeriesTerms = 40;
inline constexpr std::array<double, kGSeriesTerms> kGSeries = [] {
  std::array<double, kGSeriesTerms> c{};
  double binomial = 1.0;  // C(2k, k) 4^-k
  for (int k = 0; k < kGSeriesTerms; ++k) {
    c[static_cast<std::size_t>(k)] = binomial / (2.0 * k + 3.0);
    binomial *= (2.0 * k + 1.0) / (2.0 * k + 2.0);
  }
  return c;
}();
// The degree of the series for every r^2 <= max_r2 < 1/4: the terms fall by at least r^2, so
// the tail after degree K is below c_{K+1} r^2(K+1) / (1 - r^2) <= 4/3 of its first term, kept
// below 2^-60: 2^-58 of G >= 1/3.
inline int g_series_degree(double max_r2) {
  std::size_t k = 0;
  double term = kGSeries[1] * max_r2;
  while (k + 2 < kGSeries.size() && term > 0x1p-60) {
    ++k;
    term *= max_r2 * (kGSeries[k + 1] / kGSeries[k]);
  }
  return static_cast<int>(k);
}
// The series to degree K by Horner's rule (no divisions: the set-up's fit evaluates it at every
// node of its DCT).
inline double g_series(double r2, int degree) {
  double sum = kGSeries[static_cast<std::size_t>(degree)];
  for (int k = degree - 1; k >= 0; --k)
    sum = sum * r2 + kGSeries[static_cast<std::size_t>(k)];
  return sum;
}
inline double G(double r2) {
  if (r2 < 0.25) return g_series(r2, g_series_degree(r2));
  const double r = std::sqrt(r2), h = std::sqrt(std::max(0.0, 1.0 - r2));
  return (std::atan2(r, h) - r * h) / (2.0 * r * r2);
}

// n . (c - o) to a few ulps of the result, which may be far smaller than |n| |c - o|: c - o is
// formed exactly (two-sum) and the dot product compensated (Ogita, Rump and Oishi 2005, Dot2).
inline double dot_of_difference(const Vec3& n, const Vec3& c, const Vec3& o) {
  double sum = 0.0, err = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double d = c[i] - o[i], bd = d - c[i];
    const double dl = (c[i] - (d - bd)) + (-o[i] - bd);
    const double p = n[i] * d, pl = std::fma(n[i], d, -p);
    const double t = sum + p, bt = t - sum;
    const double tl = (sum - (t - bt)) + (p - bt);
    sum = t;
    err += pl + tl + n[i] * dl;
  }
  return sum + err;
}

// T(t) = t - sin t = 4 S(t / 2): the meridian's and the horizon's terms of the reduced form.
inline double T(double t) {
  return 4.0 * S(0.5 * t);
}

// asinh(x) / x - 1 (-x^2/6 + ...), by its series below x^2 = 1/4 where the difference cancels:
// sum_{k>=1} (-1)^k C(2k, k) 4^-k x^2k / (2k + 1), terms falling by at least x^2.
inline double asinh_ratio_m1(double x) {
  const double y = x * x;
  if (y < 0.25) {
    double c = 1.0, p = 1.0, sum = 0.0;
    for (int k = 1; k < 64; ++k) {
      c *= -(2.0 * k - 1.0) / (2.0 * k);
      p *= y;
      const double term = c * p / (2.0 * k + 1.0);
      sum += term;
      if (std::abs(term) <= 1e-18 * std::abs(sum)) break;
    }
    return sum;
  }
  return std::asinh(x) / x - 1.0;
}

// J = (asin p - asin(p q)) / p - (1 - q), p in [0, 1] with sp = sqrt(1 - p^2), q = cos s,
// omq = 1 - q and ss = sin s, each given without cancellation. Below p^2 = 1/4 by asin's series,
// sum_k C(2k, k) 4^-k p^(2k+1) / (2k + 1), whose k-th term minus the same at p q is (1 - q) (1 + q
// + ... + q^2k) times it: J = (1 - q) sum_{k>=1} C(2k, k) 4^-k p^2k (1 + ... + q^2k) / (2k + 1);
// above, the difference of the arcsines as one atan2 (no cancellation), divided by p.
inline double asin_difference_m1(double p, double sp, double q, double omq, double ss) {
  const double y = p * p;
  if (y < 0.25) {
    double c = 1.0, pk = 1.0, geo = 1.0, qpow = 1.0, sum = 0.0;
    for (int k = 1; k < 64; ++k) {
      c *= (2.0 * k - 1.0) / (2.0 * k);
      pk *= y;
      const double q1 = qpow * q, q2 = q1 * q;
      geo += q1 + q2;
      qpow = q2;
      const double term = c * pk * geo / (2.0 * k + 1.0);
      sum += term;
      if (std::abs(term) <= 1e-18 * std::abs(sum)) break;
    }
    return omq * sum;
  }
  const double pq = p * q;
  const double sq = std::sqrt(std::max(0.0, 1.0 - pq * pq));
  // sin(asin p - asin pq) = p D, D = sq - q sp = (1 - q^2) / (sq + q sp) for q >= 0; at p = 1
  // (sp = 0: the hemisphere's limit) and s = 0 that quotient is 0 / 0 for the limit D = 0.
  const double dq = sq + q * sp;
  const double D = q >= 0.0 ? (dq > 0.0 ? ss * ss / dq : 0.0) : sq - q * sp;
  const double angle = std::atan2(p * D, sp * sq + p * pq);
  return angle / p - omq;
}

}  // namespace projected_detail

struct ProjectedMap {
  // One meridian: its azimuth's cosine and sine, A and B, and the part above the horizon.
  struct Meridian {
    double cs = 1.0, ss = 0.0;  // cos s, sin s
    double r2 = 0.0, r = 0.0;   // planar radius of the rim point
    double hr = 1.0;            // h_r: (r, h_r) are the rim's sin t_r and cos t_r
    double cos_phi = 1.0, sin_phi = 0.0;
    double A = 0.0, B = 0.0;
    double t_r = 0.0;               // rim angle from z_e
    double t_lo = 0.0, t_hi = 0.0;  // the part above the horizon (t_lo == t_hi: none)
    double sin_lo = 0.0, cos_lo = 1.0;
    int kind = 0;  // 0 empty, 1 rim over apex, 2 horizon over apex, 3 rim over horizon
    // G(x) = F(t_lo + x) - F(t_lo) = ga S(x) + gb sin^2(x) / 2 + gc (x - S(x)) (see G()).
    double ga = 0.0, gb = 0.0, gc = 0.0;
  };

  // A great circle meets the rim at most 4 times: at most 5 pieces of the turn.
  static constexpr int kMaxPieces = 5;
  // Pieces of the turn between the rim's horizon crossings (clipped configurations).
  struct Pieces {
    int count = 0;
    int kind[kMaxPieces] = {};
    // s at the ends, edge[count] = edge[0] + 2 pi (unwrapped: the turn may start at a crossing)
    double edge[kMaxPieces + 1] = {};
    double cum[kMaxPieces + 1] = {};  // 2 C(edge[i])
  };
  // Unclipped: G(r(s)) = sum_m g_m cos 2ms, g_0 = g0, g_m = g[m - 1] (n == 0: elementary form).
  // 12 terms hold every ellipse up to a ~ 0.3 (sizes the sampler under any_map.h's 512 bytes);
  // beyond, the elementary form's rounding (~eps / a relative) is no larger than the series'.
  static constexpr int kSeriesCapacity = 12;
  // 1 / (2j + 1) for the series' odd harmonics.
  static constexpr double kInverseOdd[kSeriesCapacity + 1] = {
      1.0,      1.0 / 3,  1.0 / 5,  1.0 / 7,  1.0 / 9,  1.0 / 11, 1.0 / 13,
      1.0 / 15, 1.0 / 17, 1.0 / 19, 1.0 / 21, 1.0 / 23, 1.0 / 25};
  struct Series {
    int n = 0;
    int n_model = 0;  // the model: the first n_model terms (0: none; see solve_s)
    double g0 = 0.0;
    double inv_nz = 0.0;                 // 1 / n_z (reverted_start)
    double g[kSeriesCapacity + 1] = {};  // g[k - 1] = g_k; g[n] = 0 (the loops read it)
  };
  // The model's truncation, relative to the total 2 P, and the least strength of the first
  // harmonic (relative to n_z) for which solve_s takes the model's step first: below it, the
  // start is already close enough for a single evaluation of the full series.
  static constexpr double kModelTruncation = 1e-7;
  static constexpr double kModelFirstHarmonic = 1e-3;

  MapGeometry g;           // the shape only: omega and quadrant are 0 (not needed)
  Vec3 n = Vec3::UnitZ();  // the receiver normal (unit) in R_e
  double P = 0.0;          // projected solid angle
  bool clipped = false;
  union {
    Series series;  // unclipped
    Pieces pieces;  // clipped
  };

  ProjectedMap() : series() {}

  // The map for `disk` seen from `o` with the receiver normal `receiver_normal` (any non-zero
  // length). Degenerate input, or a disk wholly below the receiver's horizon, give !valid().
  static ProjectedMap make(const Disk& disk, const Vec3& o, const Vec3& receiver_normal) noexcept {
    ProjectedMap m;
    m.g = MapGeometry::make_shape(disk, o);  // the solid angle is not needed
    const double len = receiver_normal.norm();
    if (m.g.empty || !(len > 0.0) || !std::isfinite(len)) {
      m.g.empty = true;
      return m;
    }
    m.n = m.g.to_local(receiver_normal / len);
    // n_z = n_o . z_e places the horizon in the ellipse. Where the horizon crosses a small
    // ellipse it is O(a), but the rotation to R_e leaves it an absolute error ~eps, i.e. ~eps / a
    // relative in P. From c - o = l_y y_e + l_z z_e (center_local, a few ulps per component):
    // n_z = (n_o . (c - o) - n_y l_y) / l_z with n_o . (c - o) compensated from the exact inputs.
    // Its error, ~eps (|c - o| + |l_y|) / l_z, is no larger than the rotation's where
    // |l_y| <= l_z (the centre within 45 degrees of z_e: every distant disk).
    const Vec3 l = m.g.center_local();
    const double nz_accurate =
        (projected_detail::dot_of_difference(receiver_normal, m.g.center, m.g.origin) / len -
         m.n.y() * l.y()) /
        l.z();
    if (std::abs(l.y()) <= l.z() && std::abs(nz_accurate) <= 1.0) m.n.z() = nz_accurate;
    const double a = m.g.a, b = m.g.b, nz = m.n.z();
    const double lateral = std::hypot(m.n.x() * a, m.n.y() * b);
    // |n_x a cos s + n_y b sin s| <= lateral and h_r >= cos(alpha) bound w_r . n on the rim.
    if (nz > 0.0 && nz * m.g.cos_alpha > lateral) {
      m.make_unclipped();
    } else if (nz < 0.0 && -nz * m.g.cos_alpha >= lateral) {
      m.g.empty = true;  // wholly below the horizon
      return m;
    } else {
      m.make_clipped();
    }
    // As MapGeometry::finish_totals for Omega: below the smallest normal double, 1 / P overflows.
    if (!(m.P >= std::numeric_limits<double>::min()) || !std::isfinite(m.P)) m.g.empty = true;
    return m;
  }
  // Without a receiver normal: the cosine about the ellipse's centre direction z_e (a density
  // positive on the whole ellipse, so f / pdf stays unbiased for any f).
  static ProjectedMap make(const Disk& disk, const Vec3& o) noexcept {
    const MapGeometry geo = MapGeometry::make_shape(disk, o);
    return make(disk, o, geo.empty ? Vec3::UnitZ() : geo.frame.z);
  }

  bool valid() const { return !g.empty; }
  double projected_solid_angle() const { return valid() ? P : 0.0; }
  // The disk's solid angle Omega, computed on demand (g holds the shape only).
  double solid_angle() const {
    if (!valid()) return 0.0;
    MapGeometry full = g;
    full.finish_totals(0.0);
    return full.omega;
  }

  // The meridian at s; `kind` >= 0 takes its range as in a piece of that kind (the limit from
  // inside the piece, for the meridians at a piece's ends), -1 classifies it.
  Meridian meridian(double s, int kind = -1) const {
    return meridian(std::cos(s), std::sin(s), kind);
  }
  Meridian meridian(double cs, double ss, int kind) const {
    Meridian md;
    md.cs = cs;
    md.ss = ss;
    const double px = g.a * cs, py = g.b * ss;
    md.r2 = px * px + py * py;
    md.r = std::sqrt(md.r2);
    const double inv_r = 1.0 / md.r;  // one division for both
    md.cos_phi = px * inv_r;
    md.sin_phi = py * inv_r;
    md.A = n.x() * md.cos_phi + n.y() * md.sin_phi;
    md.B = n.y() * md.cos_phi - n.x() * md.sin_phi;
    const double hr = g.hr_parametric(cs, ss);
    md.hr = hr;
    // t_r = atan2(r, h_r) by asin of the smaller of the two (r^2 + h_r^2 = 1 to rounding).
    md.t_r = md.r <= hr ? std::asin(md.r) : math::kHalfPi - std::asin(hr);
    const double nz = n.z();
    if (kind < 0) {
      if (nz > 0.0)
        kind = std::atan2(nz, -md.A) < md.t_r ? 2 : 1;
      else
        kind = md.A > 0.0 && std::atan2(-nz, md.A) < md.t_r ? 3 : 0;
    }
    md.kind = kind;
    double& sin_lo = md.sin_lo;
    double& cos_lo = md.cos_lo;
    switch (kind) {
      case 1:  // the whole meridian
        md.t_hi = md.t_r;
        break;
      case 2:  // n_z > 0: above the horizon for t < t_h = atan2(n_z, -A) in (0, pi)
        md.t_hi = std::min(md.t_r, std::atan2(nz, -md.A));
        break;
      case 3: {  // n_z <= 0: above it for t > t_h = atan2(-n_z, A) in [0, pi/2) (A >= 0)
        const double ap = std::max(0.0, md.A), th = std::atan2(-nz, ap);
        md.t_hi = md.t_r;
        // sin and cos of t_lo from its own arguments (t_r = atan2(r, h_r), r^2 + h_r^2 = 1).
        if (th < md.t_r) {
          const double rr = std::hypot(nz, ap);
          md.t_lo = th, sin_lo = -nz / rr, cos_lo = ap / rr;
        } else {
          md.t_lo = md.t_r, sin_lo = md.r, cos_lo = hr;
        }
        break;
      }
      default:
        break;
    }
    // About t_lo the cosine is R' sin x + H cos x, x = t - t_lo (H its value at t_lo, 0 on the
    // horizon), and sin t = sin t_lo cos x + cos t_lo sin x: their product integrates to G.
    const double H = md.A * sin_lo + nz * cos_lo, Rp = md.A * cos_lo - nz * sin_lo;
    md.ga = Rp * cos_lo;
    md.gb = Rp * sin_lo + H * cos_lo;
    md.gc = H * sin_lo;
    return md;
  }

  // int_{t_lo}^{t_lo + x} (A sin t + n_z cos t) sin t dt: the projected solid angle along the
  // meridian from its lower end (per unit azimuth). On the horizon's meridians (kind 3), where
  // F(t) itself is much larger than its rise from t_lo, every term is non-negative: ga = A cos^2
  // + (-n_z) sin cos, gb = R' sin t_lo, gc = 0; from the apex (t_lo = 0) it is A S(x) + n_z
  // sin^2(x) / 2, whose terms differ in sign only below the horizon angle (a bounded loss).
  // With sin x and cos x given; S(x) = (x - sin x cos x) / 2 above the series' range.
  double G(const Meridian& md, double x, double sx, double cx) const {
    // Both forms, then a choice: iterates fall on either side of 0.5 at random, a branch would
    // be mispredicted (the series' own tiers follow the meridian's range: predictable).
    const double series = projected_detail::S_series(x), closed = 0.5 * (x - sx * cx);
    const double sxx = x < 0.5 ? series : closed;
    return md.ga * sxx + 0.5 * md.gb * sx * sx + md.gc * (x - sxx);
  }
  double G(const Meridian& md, double x) const { return G(md, x, std::sin(x), std::cos(x)); }
  double G_range(const Meridian& md) const { return G(md, md.t_hi - md.t_lo); }
  // 2 dC/ds.
  double density_s(const Meridian& md) const {
    if (md.kind == 0) return 0.0;
    const double ab = g.a * g.b;
    if (!clipped)
      return ab * (n.z() +
                   2.0 * (n.x() * g.a * md.cs + n.y() * g.b * md.ss) * projected_detail::G(md.r2));
    return 2.0 * G_range(md) * ab / md.r2;
  }

  // 2 C(s), s in [0, 2 pi] (clipped: [edge[0], edge[0] + 2 pi]).
  double twice_c(double s) const {
    if (!clipped) return twice_c_unclipped(s, meridian(s, 1));
    const int i = piece_of(s);
    return pieces.cum[i] + piece_part(i, pieces.edge[i], s, meridian(s, pieces.kind[i]));
  }
  double twice_c_unclipped(double s, const Meridian& md) const {
    if (series.n > 0) return series_twice_c(s, md.cs, md.ss);
    return n.y() * projected_detail::T(g.alpha) - meridian_term(md) + rim_reduced(s, md.cs, md.ss);
  }
  int piece_of(double s) const {
    int i = 0;
    while (i + 1 < pieces.count && s > pieces.edge[i + 1])
      ++i;
    return i;
  }

  // 2 x the projected solid angle of piece i between s_a (its start) and s.
  double piece_part(int i, double s_a, double s, const Meridian& md) const {
    const int kind = pieces.kind[i];
    if (kind == 0) return 0.0;
    const Meridian ma = meridian(s_a, kind);
    double v = meridian_term(ma) - meridian_term(md);
    if (kind == 1 || kind == 3) v += rim_reduced(s, md.cs, md.ss) - rim_reduced(s_a, ma.cs, ma.ss);
    if (kind == 2 || kind == 3) v += horizon_reduced(kind, ma, md);
    return v;
  }

  // The reduced form. Every sector's boundary is closed, so the Stokes integrand n . (w x dw)
  // may be replaced by n . ((w - z_e) x dw) (they differ by the exact form d(n . (z_e x w))).
  // Each piece of the boundary then contributes O(a^3) for an ellipse of size a, with no O(a)
  // terms left to cancel where a small ellipse straddles the horizon (P ~ a^3):
  //  - a meridian from t_lo out to t_hi: (w - z_e) x dw = (1 - cos t) (z_e x e_phi) dt, so
  //    B (T(t_hi) - T(t_lo)), T(t) = t - sin t;
  //  - the rim: the rim's term minus n . (z_e x dw_r), i.e. minus (-n_x b sin s + n_y a cos s),
  //    which leaves cos^2(alpha) Ic - sin s and cos^2(beta) Is - (1 - cos s), both O(a^2);
  //  - the horizon, a great circle about n: w(psi) = cos psi p + sin psi q with p the horizon
  //    point nearest z_e and q = n x p; then n . (w x dw) = d psi and n . (z_e x dw) =
  //    sqrt(1 - n_z^2) d sin psi, leaving T(psi) + n_z^2 / (1 + sqrt(1 - n_z^2)) sin psi.
  double meridian_term(const Meridian& md) const {
    if (md.kind == 0) return 0.0;
    return md.B * (projected_detail::T(md.t_hi) - projected_detail::T(md.t_lo));
  }
  // int_0^s n . ((w_r - z_e) x w_r') ds' (the rim's term of the reduced form).
  double rim_reduced(double s, double cs, double ss) const {
    const double ca = g.cos_alpha, cb = g.cos_beta, c = std::sqrt(g.a2_minus_b2);
    const double omq = cs >= 0.0 ? ss * ss / (1.0 + cs) : 1.0 - cs;
    // cos^2(alpha) Ic - sin s, Ic = asinh(c sin s / cos(alpha)) / c = int_0^s cos / h_r:
    // sin s ((cos(alpha) - 1)(1 + E) + E), E = asinh(x) / x - 1.
    const double e = projected_detail::asinh_ratio_m1(c * ss / ca);
    const double xterm = ss * (e - g.a * g.a / (1.0 + ca) * (1.0 + e));
    // cos^2(beta) Is - (1 - cos s), Is = (asin p - asin(p cos s)) / c = int_0^s sin / h_r,
    // p = c / cos(beta) = sqrt(m), sqrt(1 - p^2) = sqrt(1 - m) from the geometry's complement
    // (1 - p^2 would round to 0 near the hemisphere): (cos(beta) - 1)(1 - cos s) + cos(beta) J.
    const double j =
        projected_detail::asin_difference_m1(std::sqrt(g.m), std::sqrt(g.one_minus_m), cs, omq, ss);
    const double yterm = cb * j - g.b * g.b / (1.0 + cb) * omq;
    return -n.x() * g.b * xterm - n.y() * g.a * yterm + n.z() * g.a * g.b * s;
  }
  // psi of a meridian's point at t: atan2(w . q, w . p), both scaled by sqrt(1 - n_z^2).
  double horizon_psi(const Meridian& md, double t) const {
    const double st = std::sin(t), ct = std::cos(t), nz = n.z();
    return std::atan2(st * md.B, (1.0 - nz * nz) * ct - nz * md.A * st);
  }
  // The horizon's term between two meridians' horizon points, in the boundary's direction (a
  // piece of kind 2 runs from m1 to m2 along it, one of kind 3 from m2 back to m1).
  double horizon_reduced(int kind, const Meridian& m1, const Meridian& m2) const {
    double p1, p2;
    if (kind == 2) {
      p1 = horizon_psi(m1, m1.t_hi);
      p2 = horizon_psi(m2, m2.t_hi);
    } else {
      p1 = horizon_psi(m2, m2.t_lo);
      p2 = horizon_psi(m1, m1.t_lo);
    }
    // The arc runs forward (about n) and is shorter than pi (a convex region in a hemisphere).
    if (p2 - p1 < -math::kPi) p2 += math::kTwoPi;
    const double nz = n.z(), k = std::sqrt(std::max(0.0, 1.0 - nz * nz));
    return projected_detail::T(p2) - projected_detail::T(p1) +
           nz * nz / (1.0 + k) * (std::sin(p2) - std::sin(p1));
  }

  // 2 C(s) by the series: a b [n_z s + 2 n_x a Jc(s) + 2 n_y b Js(s)] with Jc = int cos G,
  // Js = int sin G, G = sum_m g_m cos 2ms.
  double series_twice_c(double s, double cs, double ss) const {
    return series_twice_c_derivatives(s, cs, ss).g;
  }
  // The same with its first three derivatives (2 dC/ds = a b [n_z + 2 n_x a Jc' + 2 n_y b Js'],
  // Jc' = sum c_j cos (2j+1)s, Js' = sum d_j sin (2j+1)s, differentiated term by term). Each
  // harmonic k = 2j + 1 enters through p = 2 n_x a c_j and q = 2 n_y b d_j: the value takes
  // (p sin ks + q (1 - cos ks)) / k, the derivatives u = p cos ks + q sin ks (first; -k^2 u the
  // third) and k (q cos ks - p sin ks) (second).
  // The first `terms` terms only (the model; all by default).
  math::Derivatives3 series_twice_c_derivatives(double s, double cs, double ss,
                                                int terms = -1) const {
    const int nt = series.n, last = terms < 0 ? nt : std::min(nt, terms - 1);
    // cos, sin of k s, k = 2j + 1, by the rotation (cos 2s, sin 2s), and 1 - cos ks by the same
    // rotation, 1 - cos(k + 2)s = (1 - cos ks) cos 2s + 2 sin^2 s + sin ks sin 2s, whose terms
    // are all positive for small s (no 1 - cos cancellation, no division).
    const double c2 = cs * cs - ss * ss, s2 = 2.0 * cs * ss, two_ss2 = 2.0 * ss * ss;
    double ck = cs, sk = ss, omc = cs >= 0.0 ? ss * ss / (1.0 + cs) : 1.0 - cs;
    // harmonic(j) with g_j carried from one term to the next (one load per term).
    const double kx = n.x() * g.a, ky = n.y() * g.b;
    double g_hi = series.g[0];
    auto [p, q] = harmonic_pq(kx, ky, 2.0 * series.g0, g_hi);
    double v = 0.0, d1 = 0.0, d2 = 0.0, d3 = 0.0, k = 1.0;
    for (int j = 0;; ++j) {
      const double u = p * ck + q * sk;
      v += (p * sk + q * omc) * kInverseOdd[j];
      d1 += u;
      d2 += k * (q * ck - p * sk);
      d3 -= k * k * u;
      if (j == last) break;
      const double g_lo = g_hi;
      g_hi = series.g[j + 1];
      std::tie(p, q) = harmonic_pq(kx, ky, g_lo, g_hi);
      k += 2.0;
      omc = omc * c2 + two_ss2 + sk * s2;
      const double cn = ck * c2 - sk * s2;
      sk = sk * c2 + ck * s2;
      ck = cn;
    }
    const double ab = g.a * g.b;
    return {ab * (n.z() * s + v), ab * (n.z() + d1), ab * d2, ab * d3};
  }

  // Term j's p = 2 n_x a c_j and q = 2 n_y b d_j, c_j = (g_j + g_{j+1}) / 2 and d_j = (g_j -
  // g_{j+1}) / 2, each with g_0 / 2 more for j = 0 (g[n] = 0 ends the series).
  std::pair<double, double> harmonic(int j) const {
    const double ga = j == 0 ? 2.0 * series.g0 : series.g[j - 1], gb = series.g[j];
    return harmonic_pq(n.x() * g.a, n.y() * g.b, ga, gb);
  }
  // The same from kx = n_x a, ky = n_y b, g_lo = g_j (2 g_0 for j = 0) and g_hi = g_{j+1}.
  static std::pair<double, double> harmonic_pq(double kx, double ky, double g_lo, double g_hi) {
    return {kx * (g_lo + g_hi), ky * (g_lo - g_hi)};
  }
  // From x0 = 2 pi u.x, the root of n_z s + h(s) = n_z x0 for the first harmonic h alone, by
  // Lagrange's inversion to third order: s = x0 - r (1 - r1 + r1^2 + r r2 / 2) with r, r1, r2
  // = h, h', h'' at x0 over n_z; its error is O(e^4), e = |(p_0, q_0)| / n_z. x0 itself where
  // e > 1/2 (the series converges for e below about 0.66) or e < kModelFirstHarmonic (x0 is
  // then close enough).
  math::AngleCosSin reverted_start(const math::AngleCosSin& at, double lo, double hi) const {
    const auto [p0, q0] = harmonic(0);  // 2 C = a b (n_z s + p_0 sin s + q_0 (1 - cos s) + ...)
    const double nz = n.z();
    const double e2 = p0 * p0 + q0 * q0;
    if (!(e2 <= 0.25 * nz * nz) || e2 < kModelFirstHarmonic * kModelFirstHarmonic * nz * nz)
      return at;
    // 1 - cos s directly: its cancellation near s = 0 costs ~1e-16 absolute, nothing for a start.
    const double omc = 1.0 - at.cs;
    const double inv_nz = series.inv_nz;
    const double r = (p0 * at.ss + q0 * omc) * inv_nz, r1 = (p0 * at.cs + q0 * at.ss) * inv_nz;
    const double r2 = (q0 * at.cs - p0 * at.ss) * inv_nz;
    const double delta = -r * (1.0 - r1 + r1 * r1 + 0.5 * r * r2);
    return math::moved_to(at, std::clamp(at.s + delta, lo, hi));
  }

  // u.x -> s, with its cosine and sine.
  math::AngleCosSin solve_s(double u1, int* iterations) const {
    const double total = 2.0 * P, target = std::clamp(u1, 0.0, 1.0) * total;
    double lo = 0.0, hi = math::kTwoPi, base = 0.0;
    int piece = -1;
    if (clipped) {
      piece = 0;
      while (piece + 1 < pieces.count &&
             (target > pieces.cum[piece + 1] || pieces.kind[piece] == 0))
        ++piece;
      lo = pieces.edge[piece];
      hi = pieces.edge[piece + 1];
      base = pieces.cum[piece];
    }
    // The fraction of the piece's part of 2 P (unclipped: u.x itself, without a division).
    const double span = (clipped ? pieces.cum[piece + 1] - base : total);
    const double frac = !clipped     ? std::clamp(u1, 0.0, 1.0)
                        : span > 0.0 ? std::clamp((target - base) / span, 0.0, 1.0)
                                     : 0.0;
    const double x0 = lo + frac * (hi - lo), f_tol = kProjectedNewtonTol * total;
    math::RootResult root;
    if (!clipped && series.n > 0) {
      // The series gives C's derivatives for Halley's step; each iterate's cosine and sine
      // follow from the last one's (math::moved_to). The start reverts the first harmonic
      // (reverted_start); where that harmonic is strong, one Halley step of the model (the
      // first few harmonics: cheaper) takes it to within the model's truncation of the root,
      // where one evaluation of the full series usually ends the solve.
      math::AngleCosSin at = reverted_start(math::turn_sincos(x0), lo, hi);  // x0 in [0, 2 pi]
      double start = at.s;
      int evaluations = 0;
      if (series.n_model > 0) {
        const math::Derivatives3 e = series_twice_c_derivatives(at.s, at.cs, at.ss, series.n_model);
        evaluations = 1;
        if (e.d1 > 0.0) {
          const double next = at.s + math::halley_step({e.g - target, e.d1, e.d2, e.d3}).delta;
          if (next > lo && next < hi) start = next;
        }
      }
      root = math::safeguarded_halley(
          [&](double s) {
            at = math::moved_to(at, s);
            math::Derivatives3 d = series_twice_c_derivatives(s, at.cs, at.ss);
            d.g -= target;
            return d;
          },
          lo, hi, start, f_tol, 1e-16, kRadialMaxEvaluations);
      if (iterations) *iterations = evaluations + root.iterations;
      return math::moved_to(at, root.x);
    } else {
      auto eval = [&](double s) {
        const Meridian md = meridian(s, clipped ? pieces.kind[piece] : 1);
        const double v = clipped ? base + piece_part(piece, lo, s, md) : twice_c_unclipped(s, md);
        return std::pair<double, double>(v - target, density_s(md));
      };
      // A Newton step below 1e-9 of the bracket is taken without evaluating at its end: the
      // residual there is (C''/2) delta^2, below 1e-18 of the total for the smooth marginal.
      const double final_step = 1e-9 * (hi - lo);
      root = math::safeguarded_newton(
          eval, lo, hi, x0, f_tol, 1e-16, kRadialMaxEvaluations,
          [&](double, double delta) { return std::abs(delta) <= final_step; });
    }
    if (iterations) *iterations = root.iterations;
    return {root.x, std::cos(root.x), std::sin(root.x)};
  }

  // u.y -> x = t - t_lo on the meridian, G(x) = u.y G(t_hi - t_lo), with its cosine and sine.
  math::AngleCosSin solve_x(const Meridian& md, double u2, int* iterations) const {
    const double range = md.t_hi - md.t_lo;
    // From the apex to the rim, sin and cos of the range are the rim's (r, h_r).
    const bool apex_to_rim = md.t_lo == 0.0 && md.t_hi == md.t_r;
    const double sr = apex_to_rim ? md.r : std::sin(range);
    const double cr = apex_to_rim ? md.hr : std::cos(range);
    const double total = G(md, range, sr, cr);
    const double f = std::clamp(u2, 0.0, 1.0), target = f * total;
    // G' = ga sin^2 x + gb sin x cos x + gc cos^2 x, G'' = (ga - gc) sin 2x + gb cos 2x,
    // G''' = 2 (ga - gc) cos 2x - 2 gb sin 2x.
    auto derivatives = [&](double x, double sx, double cx) {
      const double s2x = 2.0 * sx * cx, c2x = (cx - sx) * (cx + sx), d = md.ga - md.gc;
      return math::Derivatives3{G(md, x, sx, cx) - target,
                                md.ga * sx * sx + md.gb * sx * cx + md.gc * cx * cx,
                                d * s2x + md.gb * c2x, 2.0 * (d * c2x - md.gb * s2x)};
    };
    // The start, sin^2 x = u.y sin^2(range): exact where G is gb sin^2(x) / 2 alone (the cosine
    // n_z cos t about the apex), and there sin x and cos x are known without a call (cos^2 x =
    // cos^2(range) + (1 - u.y) sin^2(range), two non-negative terms); the later iterates' follow
    // by rotation (math::moved_to).
    const double f_tol = kProjectedNewtonTol * std::abs(total);
    math::AngleCosSin at;
    if (range <= math::kHalfPi) {
      const double sx = std::sqrt(f) * sr, cx = std::sqrt(cr * cr + (1.0 - f) * sr * sr);
      // The angle from the better conditioned of the two, asin of the smaller (x, sin x and
      // cos x consistent to an ulp; one call and a choice, not a branch: which one is smaller
      // is as random as u.y); asin(sin(range)) may round above range.
      const double w = std::asin(std::min(sx, cx));
      at = {std::min(sx <= cx ? w : math::kHalfPi - w, range), cx, sx};
    } else {
      const double x0 = f * range;
      at = {x0, std::cos(x0), std::sin(x0)};
    }
    const math::RootResult root = math::safeguarded_halley(
        [&](double x) {
          at = math::moved_to(at, x);
          return derivatives(x, at.ss, at.cs);
        },
        0.0, range, at.s, f_tol, 1e-17, kRadialMaxEvaluations);
    if (iterations) *iterations += root.iterations;
    return math::moved_to(at, root.x);
  }

  EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    if (iterations) *iterations = 0;
    if (g.empty || !in_unit_square(u)) return {};
    const math::AngleCosSin s = solve_s(u.x, iterations);
    const Meridian md = meridian(s.cs, s.ss, clipped ? pieces.kind[piece_of(s.s)] : 1);
    if (md.kind == 0 || !(md.t_hi > md.t_lo)) return {};
    // t = t_lo + x: its sine and cosine by the rotation (exact from the apex, t_lo = 0).
    const math::AngleCosSin x = solve_x(md, u.y, iterations);
    const double st = md.sin_lo * x.cs + md.cos_lo * x.ss, ct = md.cos_lo * x.cs - md.sin_lo * x.ss;
    const Vec3 local(st * md.cos_phi, st * md.sin_phi, ct);
    EllipseSample out;
    out.local = local;
    out.direction = renormalized(g.to_world(local));
    // As pdf(direction) computes it, so the two agree exactly.
    const double cosine = g.to_local(out.direction).dot(n);
    // On the horizon itself (measure zero), or so close that cosine / P underflows to 0.
    out.pdf = cosine / P;
    if (!(out.pdf > 0.0)) return {};
    out.point = g.hit(out.direction);
    out.valid = true;
    return out;
  }

  // max(0, w . n_o) / P inside the disk's solid angle, 0 elsewhere.
  double pdf(const Vec3& direction) const {
    if (!g.contains(direction)) return 0.0;
    const double cosine = g.to_local(direction.normalized()).dot(n);
    return cosine > 0.0 ? cosine / P : 0.0;
  }

  // Local direction -> u (no root finding).
  Point2 invert_local(const Vec3& l) const {
    if (g.empty) return {};
    double s = std::atan2(g.a * l.y(), g.b * l.x());
    if (s < 0.0) s += math::kTwoPi;
    if (clipped && s < pieces.edge[0]) s += math::kTwoPi;  // the turn starts at edge[0]
    const Meridian md = meridian(s, clipped ? pieces.kind[piece_of(s)] : 1);
    const double u1 = std::clamp(twice_c(s) / (2.0 * P), 0.0, 1.0);
    const double t = std::atan2(std::hypot(l.x(), l.y()), l.z());
    const double range = md.t_hi - md.t_lo, total = G_range(md);
    const double u2 = total > 0.0
                          ? std::clamp(G(md, std::clamp(t - md.t_lo, 0.0, range)) / total, 0.0, 1.0)
                          : 0.0;
    return {u1, u2};
  }
  std::optional<Point2> invert(const Vec3& direction) const {
    if (pdf(direction) <= 0.0) return std::nullopt;
    return invert_local(g.to_local(direction.normalized()));
  }

 private:
  void make_unclipped() {
    clipped = false;
    P = math::kPi * g.a * g.b * n.z();
    const double a2 = g.a * g.a, b2 = g.b * g.b;
    // G(r(s)) as a Chebyshev series in x = cos 2s, r^2 = p + q x; its branch point r^2 = 1 is at
    // x* = 1 + 2 cos^2(alpha) / (a^2 - b^2).
    const double rho = g.a2_minus_b2 > 0.0
                           ? RadialSeries::bernstein_rho(2.0 * g.one_minus_a2 / g.a2_minus_b2)
                           : HUGE_VAL;
    const double g0 = projected_detail::G(a2);
    // Every node's r^2 is at most a^2: below 1/4, one degree of the series serves them all.
    const int degree = a2 < 0.25 ? projected_detail::g_series_degree(a2) : -1;
    const RadialSeries fit = RadialSeries::fit(rho, g0, [&](double c2, double s2) {
      const double r2 = a2 * c2 + b2 * s2;
      return (degree >= 0 ? projected_detail::g_series(r2, degree) : projected_detail::G(r2)) - g0;
    });
    series = Series{};
    if (fit.n > 0 && fit.n <= kSeriesCapacity) {
      // The fit stores the integral's sine series, b[k - 1] = g_k / (2k).
      series.n = fit.n;
      series.g0 = fit.a0;
      series.inv_nz = 1.0 / n.z();
      for (int k = 1; k <= fit.n; ++k)
        series.g[k - 1] = 2.0 * k * fit.b[k - 1];
      choose_model();
    }
  }

  // The model of solve_s: the fewest leading terms whose dropped tail bounds 2 C's error by
  // kModelTruncation of 2 P (term j's value is a b (p sin ks + q (1 - cos ks)) / k, at most
  // a b (|p| + 2 |q|) / k), kept only if it drops at least two terms and the first harmonic
  // is strong enough for the reverted start to need more than one evaluation.
  void choose_model() {
    const int nt = series.n;
    const double ab = g.a * g.b;
    double bound[kSeriesCapacity + 1];
    for (int j = 0; j <= nt; ++j) {
      const auto [p, q] = harmonic(j);
      bound[j] = ab * (std::abs(p) + 2.0 * std::abs(q)) * kInverseOdd[j];
    }
    series.n_model = 0;
    const auto [p0, q0] = harmonic(0);
    if (!(p0 * p0 + q0 * q0 >= kModelFirstHarmonic * kModelFirstHarmonic * n.z() * n.z())) return;
    const double limit = kModelTruncation * 2.0 * P;
    double tail = 0.0;
    int terms = nt + 1;
    while (terms > 1 && tail + bound[terms - 1] <= limit)
      tail += bound[--terms];
    if (terms + 2 <= nt + 1) {
      series.n_model = terms;
    }
  }

  void make_clipped() {
    clipped = true;
    pieces = Pieces{};
    // Horizon crossings of the rim: sign changes of w_r(s) . n on a grid, refined by bisection.
    constexpr int kGrid = 256;
    auto rim_dot = [&](double s) {
      const double cs = std::cos(s), ss = std::sin(s);
      return n.x() * g.a * cs + n.y() * g.b * ss + n.z() * g.hr_parametric(cs, ss);
    };
    double edges[kMaxPieces + 1];
    int count = 0;
    edges[count++] = 0.0;
    double s0 = 0.0, f0 = rim_dot(0.0);
    for (int j = 1; j <= kGrid && count < kMaxPieces; ++j) {
      const double s1 = math::kTwoPi * j / kGrid, f1 = rim_dot(s1);
      if ((f0 > 0.0) != (f1 > 0.0)) {
        double lo = s0, hi = s1;
        const bool rising = f1 > 0.0;
        for (int it = 0; it < 80 && lo < hi; ++it) {
          const double mid = 0.5 * (lo + hi);
          if (mid <= lo || mid >= hi) break;
          ((rim_dot(mid) > 0.0) == rising ? hi : lo) = mid;
        }
        const double root = 0.5 * (lo + hi);
        if (root > edges[count - 1] && root < math::kTwoPi) edges[count++] = root;
      }
      s0 = s1;
      f0 = f1;
    }
    edges[count] = math::kTwoPi;
    // Where z_e is below the horizon, the meridians through the visible part span an interval
    // of azimuths; the turn then starts at the crossing that begins it, so that u.x runs over
    // the visible part without a jump (and 0 and 1 are its two pinch points).
    double origin = 0.0;
    for (int i = 0; i + 1 < count; ++i) {
      const bool empty = meridian(0.5 * (edges[i] + edges[i + 1])).kind == 0;
      const int next = (i + 1) % count;
      const bool next_full = meridian(0.5 * (edges[next] + edges[next + 1])).kind != 0;
      if (empty && next_full) {
        origin = edges[i + 1];
        break;
      }
    }
    if (origin > 0.0) {
      // Crossings in cyclic order from the origin, unwrapped past 2 pi.
      double cyc[kMaxPieces + 1];
      int m = 0;
      for (int i = 1; i < count; ++i)
        if (edges[i] >= origin) cyc[m++] = edges[i];
      for (int i = 1; i < count; ++i)
        if (edges[i] < origin) cyc[m++] = edges[i] + math::kTwoPi;
      for (int i = 0; i < m; ++i)
        edges[i] = cyc[i];
      edges[m] = origin + math::kTwoPi;
      count = m;
    }
    pieces.count = count;
    double cum = 0.0;
    for (int i = 0; i < count; ++i) {
      pieces.edge[i] = edges[i];
      pieces.cum[i] = cum;
      pieces.kind[i] = meridian(0.5 * (edges[i] + edges[i + 1])).kind;
      cum += piece_part(i, edges[i], edges[i + 1], meridian(edges[i + 1], pieces.kind[i]));
    }
    pieces.edge[count] = edges[count];
    pieces.cum[count] = cum;
    P = 0.5 * cum;
  }
};

}  // namespace disklab::ellipse
