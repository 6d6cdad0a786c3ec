#pragma once
// Per-shading-point sine series of the radial and parallel maps' cumulative solid angles (beyond
// Guillén et al. 2017): the hot path of the exact maps, and the seed of radial-fast.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "disklab/ellipse/map_geometry.h"
#include "disklab/math/constants.h"
#include "disklab/math/rotation.h"

namespace disklab::ellipse {

namespace detail {
// The series' DCT-I kernel cos(j k pi / N) for N = 8, 16, 32, 64 is tabulated in rows
// k = 0..min(N, max_row) of N + 1 entries: only the coefficients a sampler can keep are computed.
constexpr int series_kernel_rows(int n, int max_row) {
  return (n < max_row ? n : max_row) + 1;
}
constexpr std::size_t series_kernel_offset(int n, int max_row) {
  std::size_t o = 0;
  for (int m = 8; m < n; m *= 2)
    o += static_cast<std::size_t>(series_kernel_rows(m, max_row)) * static_cast<std::size_t>(m + 1);
  return o;
}
}  // namespace detail

// A parametric angle s of the radial maps with its cosine and sine (computed once, used twice).
using ParametricAngle = math::AngleCosSin;

// Omega_r(s) as a short trigonometric series, built once per shading point (the hot path of the
// exact maps; beyond the paper). In the parametric angle s the integrand of eq. (16) is
//     dOmega_r/ds = a b / (1 + h_r(s)),  h_r^2 = A cos^2 s + B sin^2 s = p + q cos 2s,
// A = cos^2 alpha <= B = cos^2 beta, p = (A + B)/2, q = -(a^2 - b^2)/2. As a function of
// x = cos 2s it is analytic on [-1, 1] except for the branch point x* = -p/q = (A + B)/(a^2 - b^2)
// > 1, so its Chebyshev coefficients a_k decay like rho^-k, rho = x* + sqrt(x*^2 - 1) (Bernstein
// ellipse), and integrating term by term gives
//     Omega_r(s) = a_0 s + sum_k a_k sin(2 k s) / (2 k),   Omega_r(pi/2) = a_0 pi / 2,
// with every term O(ab): no cancellation at any distance. The degree N (8..64) is the smallest
// with rho^-N <= 2^-60, so truncation and aliasing stay below ~1e-18 relative to a_0 (the
// coefficients are sampled exactly by a DCT-I on N + 1 Chebyshev-Lobatto nodes). Trailing terms
// that do not matter are dropped, and at most kCapacity terms are kept (the sampler stays small
// without allocating): near disks that need more (the point close to the disk's rim plane, h_r
// -> 0 somewhere) get n == 0 and the maps fall back to the elliptic-integral form of
// solid_angle.h.
//
// The capacity the series leaves free may hold a second, shorter series: a seed of the radial
// map's inverse s(t), set by radial-fast (radial_fast.h) and read by seed().
struct RadialSeries {
  static constexpr int kMaxDegree = 64;
  // Terms kept per shading point: 17 holds 99% of the radial series of disks from 1e-3 to 1e4
  // radii in random directions (`ellipse.RadialSeries` prints the distribution), and keeps the
  // largest sampler of any_map.h under 512 bytes.
  static constexpr int kCapacity = 17;
  // Relative size of the dropped tail: 1e-17, a tenth of the rounding of the sum itself.
  static constexpr double kSeriesDrop = 1e-17;
  int n = 0;                 // terms of Omega_r's series; 0: not available, use solid_angle.h
  std::int16_t n_seed = 0;   // terms of the inverse map's seed, stored after them
  bool seed_exact = false;   // the seed is the inverse to radial-fast's tolerance (no Newton)
  double a0 = 0.0;           // mean of the integrand (constant term)
  double quadrant = 0.0;     // a_0 pi / 2
  double b[kCapacity] = {};  // b[k - 1] = a_k / (2k), k = 1..n; then the seed's c_1..c_n_seed

  static RadialSeries make(const MapGeometry& g) {
    if (g.empty) return {};
    const double A = g.one_minus_a2, B = g.one_minus_b2;
    const double diff = g.a2_minus_b2;  // B - A = a^2 - b^2
    const double ab = g.a * g.b;
    // rho = exp(acosh(x*)), x* - 1 = 2A / (B - A).
    const double rho = diff > 0.0 ? bernstein_rho(2.0 * A / diff) : HUGE_VAL;
    // The DCT runs on dg_j = g_j - g_0, formed without cancellation (h_0 = cos(alpha)):
    //   g_j - g_0 = -a b (B - A) sin^2 s_j / ((h_0 + h_j)(1 + h_0)(1 + h_j)),
    // so the coefficients k >= 1 (where the constant g_0 contributes exactly nothing) carry
    // rounding relative to their own size, not to a b: for distant disks they are O(a^2 - b^2)
    // and would otherwise drown in the rounding of g_j.
    const double h0 = g.cos_alpha, g0 = ab / (1.0 + h0);
    return fit(rho, g0, [&](double c2, double s2) {
      const double hj = std::sqrt(A * c2 + B * s2);
      return -ab * diff * s2 / ((h0 + hj) * (1.0 + h0) * (1.0 + hj));
    });
  }

  // rho = exp(acosh(1 + e)) = 1 + e + sqrt(e (2 + e)) for e >= 0: the Bernstein ellipse through
  // a branch point at x = 1 + e, whose Chebyshev coefficients then fall like rho^-k.
  static double bernstein_rho(double e) { return 1.0 + e + std::sqrt(e * (2.0 + e)); }

  // The series of int_0^s G(cos 2s') ds' for an integrand whose Chebyshev coefficients decay at
  // least like rho^-k: degree N (8..64) with rho^N >= 2^60 (n = 0 if none suffices; by squaring,
  // without a logarithm), coefficients by a DCT-I on N + 1 Chebyshev-Lobatto nodes s_j = j pi /
  // (2N) of dg(cos^2 s_j, sin^2 s_j) = G_j - g0 (g0 = G at s = 0), trailing terms dropped.
  template <class DG>
  static RadialSeries fit(double rho, double g0, DG&& dg_at) {
    RadialSeries out;
    if (!std::isfinite(g0)) return out;
    int n = 8;
    double rho_n = rho * rho;
    rho_n *= rho_n;
    rho_n *= rho_n;  // rho^8
    while (!(rho_n >= 0x1p60)) {
      if (n == kMaxDegree) return out;  // also for a NaN rho
      n *= 2;
      rho_n *= rho_n;
    }
    const auto& tab = tables();
    const int step = kMaxDegree / n;  // table stride for this degree
    double dg[kMaxDegree + 1] = {};   // zeroed: GCC cannot see the loop fill dg[0..n]
    for (int j = 0; j <= n; ++j) {
      const auto at = static_cast<std::size_t>(j) * static_cast<std::size_t>(step);
      dg[j] = dg_at(tab.cos2_half[at], tab.sin2_half[at]);
    }
    // DCT-I: a_k = (2/n) sum'' dg_j cos(j k pi / n); a_0 and a_n halved once more. For k >= 1
    // the constant g0 contributes sum'' cos(j k pi / n) = 0.
    const double* kernel = tab.kernel + kernel_offset(n);
    // The kernel's symmetry cos((n - j) k pi / n) = (-1)^k cos(j k pi / n) folds the nodes in
    // pairs, sum_j = sum_{j < n/2} (dg_j +- dg_{n-j}) cos(j k pi / n) + dg_{n/2} cos(k pi / 2):
    // half the products (the dg_j share a sign, so the even fold adds without cancelling).
    const int half = n / 2;
    double fold_even[kMaxDegree / 2] = {}, fold_odd[kMaxDegree / 2] = {};
    for (int j = 1; j < half; ++j) {
      fold_even[j] = dg[j] + dg[n - j];
      fold_odd[j] = dg[j] - dg[n - j];
    }
    auto coefficient = [&](int k) {
      const bool odd = (k & 1) != 0;
      double sum = 0.5 * (dg[0] + (odd ? -dg[n] : dg[n]));
      if (!odd) sum += (k & 2) ? -dg[half] : dg[half];  // cos(k pi / 2) = (-1)^(k/2)
      const double* row = kernel + static_cast<std::size_t>(k) * static_cast<std::size_t>(n + 1);
      const double* fold = odd ? fold_odd : fold_even;
      // Four partial sums: the loop is bound by the latency of the additions, not their count.
      double part[4] = {0.0, 0.0, 0.0, 0.0};
      for (int j = 1; j < half; ++j)
        part[j & 3] += fold[j] * row[j];
      sum += (part[0] + part[1]) + (part[2] + part[3]);
      return sum * (2.0 / n) * (k == n ? 0.5 : 1.0);
    };
    const double a0 = g0 + 0.5 * coefficient(0);
    const double quadrant = a0 * math::kHalfPi;
    // Terms in increasing k, stopping at the first two whose dropped tail is negligible: the
    // coefficients decay at least like rho^-k (one branch point), so after b_k everything sums
    // to at most |b_k| / (1 - 1/rho); below kSeriesDrop * quadrant for b_k and b_k+1 (two, so
    // that a coefficient passing near zero cannot end the series early), b_k and all later terms
    // are dropped. Only the terms kept are computed (the DCT is the cost of the set-up).
    const double tail_factor = 1.0 / (1.0 - 1.0 / rho);  // 1 for rho = inf (a circle)
    const double drop = kSeriesDrop * quadrant;
    auto negligible = [&](double b) { return std::abs(b) * tail_factor <= drop; };
    double bk[kCapacity + 2];
    int kept = 0;
    bool ended = false;
    for (int k = 1; k <= n && k <= kCapacity + 2; ++k) {
      bk[k - 1] = coefficient(k) / (2.0 * k);
      if (!std::isfinite(bk[k - 1])) return out;
      if (k >= 2 && negligible(bk[k - 2]) && negligible(bk[k - 1])) {
        kept = k - 2;
        ended = true;
        break;
      }
    }
    if (!ended) {
      if (n > kCapacity) return out;  // more terms than a sampler keeps
      kept = n;                       // the full degree (sized for 2^-60) is kept
    }
    n = std::max(kept, 1);
    if (!(quadrant > 0.0) || !std::isfinite(quadrant)) return out;
    out.n = n;
    out.a0 = a0;
    out.quadrant = quadrant;
    for (int k = 1; k <= n; ++k)
      out.b[k - 1] = bk[k - 1];
    return out;
  }

  // Omega_r(s) from cos s and sin s (and s itself): Clenshaw's recurrence for the sine series in
  // theta = 2s. Near theta = 0 or pi the recurrence's rounding is multiplied by sin(theta), as
  // the sum itself, so the relative accuracy of a_0 s + sum holds there too.
  double omega(double s, double cs, double ss) const {
    const double cos2 = (cs - ss) * (cs + ss), sin2 = 2.0 * ss * cs;
    return a0 * s + sine_sum(b, n, cos2, sin2);
  }

  // sum_{k=1}^{count} c[k - 1] sin(2 k x) from cos 2x and sin 2x (Clenshaw).
  static double sine_sum(const double* c, int count, double cos2, double sin2) {
    const double two_c = 2.0 * cos2;
    double y1 = 0.0, y2 = 0.0;
    for (int k = count; k >= 1; --k) {
      const double y = c[k - 1] + two_c * y1 - y2;
      y2 = y1;
      y1 = y;
    }
    return y1 * sin2;
  }

  // A start for the inverse, s with Omega_r(s) = a_0 tau (tau = t pi / 2), from the series alone:
  // with beta_k = b_k / a_0, s = tau - sum beta_k sin(2 k s), reverted to second order in the
  // first two harmonics, s ~ tau - beta_1 sin 2tau + (beta_1^2 - beta_2) sin 4tau. Its error is
  // O(beta^3), and beta_1 = O(a^2 - b^2): for all but close, eccentric ellipses one Newton step
  // from it meets the tolerance. Clamped to [0, pi/2] (exact at both ends).
  ParametricAngle reverted_start(const ParametricAngle& base) const {
    if (n == 0) return base;
    const double beta1 = b[0] / a0, beta2 = n > 1 ? b[1] / a0 : 0.0;
    const double cos2 = (base.cs - base.ss) * (base.cs + base.ss), sin2 = 2.0 * base.ss * base.cs;
    const double delta = sin2 * (-beta1 + 2.0 * cos2 * (beta1 * beta1 - beta2));
    return math::moved_to(base, std::clamp(base.s + delta, 0.0, math::kHalfPi));
  }

  // ---- the inverse map's seed (radial-fast) ----
  // s(t) ~ tau + sum_k c_k sin(2 k tau), tau = t pi / 2: the radial map's parametric angle as a
  // function of the quadrant fraction t (the planar ellipse's answer is s = tau exactly).
  int seed_capacity() const { return kCapacity - n; }
  // Stores c_1..c_count after Omega_r's terms (not marked exact); false (nothing stored) when
  // they do not fit.
  bool set_seed(const double* c, int count) {
    if (count < 0 || count > seed_capacity()) return false;
    for (int k = 0; k < count; ++k)
      b[n + k] = c[k];
    n_seed = static_cast<std::int16_t>(count);
    seed_exact = false;
    return true;
  }
  // The seed for t in [0, 1] with its cosine and sine, from those of tau (math::quarter_sincos):
  // s = tau + delta (math::moved_to), clamped to [0, pi/2] (at t = 1 the sines' rounding is not
  // exactly 0).
  [[gnu::always_inline]] ParametricAngle seed(double t) const {
    const double tau = std::clamp(t, 0.0, 1.0) * math::kHalfPi;
    const ParametricAngle base = math::quarter_sincos(tau);
    if (n_seed == 0) return base;
    const double delta =
        sine_sum(b + n, n_seed, (base.cs - base.ss) * (base.cs + base.ss), 2.0 * base.ss * base.cs);
    return math::moved_to(base, std::clamp(tau + delta, 0.0, math::kHalfPi));
  }

 private:
  static constexpr int kernel_rows(int n) { return detail::series_kernel_rows(n, kCapacity + 2); }
  static constexpr std::size_t kernel_offset(int n) {
    return detail::series_kernel_offset(n, kCapacity + 2);
  }
  struct Tables {
    double cos2_half[kMaxDegree + 1];  // cos^2(j pi / 128), j = 0..64
    double sin2_half[kMaxDegree + 1];  // sin^2(j pi / 128)
    double kernel[detail::series_kernel_offset(2 * kMaxDegree, kCapacity + 2)];
  };
  static const Tables& tables() {
    static const Tables t = [] {
      Tables r;
      for (int j = 0; j <= kMaxDegree; ++j) {
        const double c = std::cos(j * math::kHalfPi / kMaxDegree);
        const double sn = std::sin(j * math::kHalfPi / kMaxDegree);
        r.cos2_half[j] = c * c;
        r.sin2_half[j] = sn * sn;
      }
      for (int n = 8; n <= kMaxDegree; n *= 2) {
        double* k_rows = r.kernel + kernel_offset(n);
        for (int k = 0; k < kernel_rows(n); ++k)
          for (int j = 0; j <= n; ++j)  // (j k mod 2n) keeps the argument in [0, 2 pi)
            k_rows[k * (n + 1) + j] = std::cos((j * k % (2 * n)) * math::kPi / n);
      }
      return r;
    }();
    return t;
  }
};

}  // namespace disklab::ellipse
