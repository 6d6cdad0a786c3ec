#pragma once
// Uniform sampling of the solid angle of a planar rectangle (Ureña, Fajardo, King 2013,
// "An Area-Preserving Parametrization for Spherical Rectangles"), the proposal of Gamito's disk
// sampler: the first coordinate fixes the slice x = X by the solid angle of the sub-rectangle
// it cuts off, the second interpolates the slice's cylindrical height linearly (the paper's
// two coordinates).
//
// The rectangle here is the square circumscribing a disk, in the disk frame R_d (geometry.h) and
// in units of the radius: with o at the origin, x in [-1, 1] along x_d, y in [y0, y1] =
// [e - 1, e + 1] along -y_d, in the plane at depth h (e, h: the disk centre's in-plane offset and
// o's height, over r). It is symmetric in x, which the formulas below use.
//
// CANCELLATION-FREE FORMS (instead of the paper's spherical-quad angles, whose Girard sum
// g0 + g1 + g2 + g3 - 2 pi and slice angle u S + k lose everything for a rectangle far away or
// seen edge-on). The solid angle of [X0, X] x [y0, y1] is G(X) - G(X0) with
//     G(X) = atan(X y1 / (h L1)) - atan(X y0 / (h L0)),  L_i = sqrt(X^2 + y_i^2 + h^2),
// (the standard rectangle formula), evaluated as one atan2: atan A - atan B = arg(1 + AB + i(A-B)),
// A - B = (X / h) D, D = y1/L1 - y0/L0 = h1 - h0 (the slice's height range), where for y0 >= 0
//     D = (y1 - y0)(y1 + y0)(X^2 + h^2) / (L0 L1 (y1 L0 + y0 L1))       (no cancellation),
// and dG/dX = h D / (X^2 + h^2). G is odd, so S = 2 G(1) and the slice of u solves
// G(X) = (u - 1/2) S (safeguarded Newton), from the closed-form slice below. The height:
// h_v = h0 + v D, and 1 - h_v^2 = (1 - h0^2) + v D (-h0 - h_v) for h_v < 0, (1 - h1^2) + (1 - v)
// D (h1 + h_v) for h_v >= 0: positive terms, so Y = h_v dist / sqrt(1 - h_v^2), dist =
// sqrt(X^2 + h^2), keeps its accuracy when the rectangle lies near the horizon. Everything runs
// in long double, whose exponent range keeps the squares of lengths from 1e-300 to 1e300 radii
// representable.
//
// THE SLICE IN CLOSED FORM (the paper's analytic inversion, restated): with Theta = atan(X / h)
// the angle of the slice's plane about the y axis and b_i = atan2(y_i, h) the elevations of the
// edges y = y_i at X = 0, integrating dOmega = cos(beta) dbeta dTheta over the slice gives
// G = asin(sin b1 sin Theta) - asin(sin b0 sin Theta). Solved for G = t,
//     tan Theta = sin t / sqrt((cos t - cos(b1 - b0)) (cos t + cos(b1 + b0)))
//               = s c / sqrt((P^2 - s^2) (Q^2 - s^2)),
// s, c = sin, cos of t/2, P = sin((b1 - b0) / 2), Q = cos((b1 + b0) / 2) (c^2 - sin^2((b1 + b0)
// / 2) = Q^2 - s^2, whose terms are small where those are near 1: a square far to the side).
// With rho_i = sqrt(y_i^2 + h^2) and pp = rho0 rho1, in positive terms: for y0 >= 0, P^2 = 2 h^2
// / (pp (pp + y0 y1 + h^2)) and Q^2 = (h^2 + h^2 (y0^2 + y1^2 + h^2) / (pp + y0 y1)) / (2 pp); for
// y0 < 0, P^2 = (pp - h^2 - y0 y1) / (2 pp) with pp - h^2 = (h^2 (y0^2 + y1^2) + y0^2 y1^2) /
// (pp + h^2), and Q^2 = (pp + h^2 - y0 y1) / (2 pp). P^2 - s^2 cancels as t nears b1 - b0 (the
// strip's whole solid angle: u near 0 or 1 on a square seen edge-on), so the closed form starts
// the Newton solve, which keeps its tolerance, instead of replacing it.
#include <algorithm>
#include <cmath>
#include <limits>

#include "disklab/math/roots.h"

namespace disklab::ellipse {

// Newton stops when |G(X) - target| <= kRectangleNewtonTol * S.
inline constexpr double kRectangleNewtonTol = 1e-15;

struct SphericalRectangle {
  double h = 0.0, yc = 0.0;   // depth and the square's centre in y, in radii (y0, y1 = yc -+ 1)
  double S = 0.0;             // solid angle of the rectangle seen from o
  double p2 = 0.0, q2 = 0.0;  // P^2 and Q^2 of the closed-form slice (header comment)

  using W = long double;

  bool valid() const { return S > 0.0 && std::isfinite(S); }

  // The ends in W: y1 - y0 = 2 and y1 + y0 = 2 yc are used as such where they matter (for a
  // square far to the side, yc -+ 1 may round to the same double).
  W y0() const { return W(yc) - 1; }
  W y1() const { return W(yc) + 1; }

  // The slice at X: L0, L1 and its height range D = h1 - h0 (header comment).
  struct Slice {
    W L0, L1, D;
  };
  Slice slice(W X) const {
    const W hh = W(h) * h, xx = X * X, y0 = this->y0(), y1 = this->y1();
    Slice sl;
    sl.L0 = std::sqrt(xx + y0 * y0 + hh);
    sl.L1 = std::sqrt(xx + y1 * y1 + hh);
    sl.D = yc >= 1.0 ? 4 * W(yc) * (xx + hh) / (sl.L0 * sl.L1 * (y1 * sl.L0 + y0 * sl.L1))
                     : y1 / sl.L1 - y0 / sl.L0;
    return sl;
  }
  // G(X): the solid angle of [0, X] x [y0, y1] (signed), from the slice at X.
  W G(W X, const Slice& sl) const {
    const W A = X * y1() / (h * sl.L1), B = X * y0() / (h * sl.L0);
    return std::atan2((X / h) * sl.D, 1 + A * B);
  }
  W G(W X) const { return G(X, slice(X)); }

  // The slice X of target G(X) = t in closed form (header comment); NaN where it breaks down.
  double slice_start(W t) const {
    const W s = std::sin(t / 2), c = std::cos(t / 2), ss = s * s;
    return static_cast<double>(W(h) * s * c / std::sqrt((p2 - ss) * (q2 - ss)));
  }

  // The square [-1, 1] x [e - 1, e + 1] at depth h, in radii (h > 0).
  static SphericalRectangle make(double h_over_r, double e_over_r) {
    SphericalRectangle q;
    if (!(h_over_r > 0.0) || !std::isfinite(h_over_r) || !(e_over_r >= 0.0) ||
        !std::isfinite(e_over_r))
      return q;
    q.h = h_over_r;
    q.yc = e_over_r;
    q.S = static_cast<double>(2 * q.G(1));
    if (!q.valid()) {
      q.S = 0.0;
      return q;
    }
    const W hh = W(q.h) * q.h, y0 = q.y0(), y1 = q.y1(), y01 = y0 * y1;
    const W pp = std::sqrt(y0 * y0 + hh) * std::sqrt(y1 * y1 + hh);
    if (y0 >= 0) {
      q.p2 = static_cast<double>(2 * hh / (pp * (pp + y01 + hh)));
      q.q2 = static_cast<double>((hh + hh * (y0 * y0 + y1 * y1 + hh) / (pp + y01)) / (2 * pp));
    } else {
      const W pp_minus_hh = (hh * (y0 * y0 + y1 * y1) + y01 * y01) / (pp + hh);
      q.p2 = static_cast<double>((pp_minus_hh - y01) / (2 * pp));
      q.q2 = static_cast<double>((pp + hh - y01) / (2 * pp));
    }
    return q;
  }

  // The point on the square for (u, v) in [0, 1]^2, uniform in solid angle: X, Y in radii and
  // dy = Y - yc, the offset from the centre, formed without cancellation: with Y(h) = dist h /
  // sqrt(1 - h^2) and Y(h0) = y0, Y - y0 = dist (h_v^2 - h0^2) / (sqrt(q_v q0) (h_v sqrt(q0) +
  // h0 sqrt(q_v))) and h_v^2 - h0^2 = v D (h_v + h0), positive terms where h0 >= 0.
  void sample(double u, double v, double& X, double& Y, double& dy) const {
    const W target = (W(u) - 0.5L) * S;
    // The slice of the last evaluation, which is usually the result (the closed-form start
    // mostly meets the tolerance at once): its lengths serve the height below.
    double last_x = std::numeric_limits<double>::quiet_NaN();
    Slice last;
    auto eval = [&](double x) {
      last = slice(x);
      last_x = x;
      const W deriv = W(h) * last.D / (W(x) * x + W(h) * h);
      return std::pair<double, double>(static_cast<double>(G(x, last) - target),
                                       static_cast<double>(deriv));
    };
    if (u <= 0.0) {
      X = -1.0;
    } else if (u >= 1.0) {
      X = 1.0;
    } else {
      const double start = slice_start(target);
      X = math::safeguarded_newton(
              eval, -1.0, 1.0, std::isfinite(start) ? std::clamp(start, -1.0, 1.0) : 2.0 * u - 1.0,
              kRectangleNewtonTol * S, 1e-17, 200)
              .x;
    }
    const W xx = W(X) * X, hh = W(h) * h, dist2 = xx + hh;
    const W y0 = this->y0(), y1 = this->y1();
    const Slice sl = X == last_x ? last : slice(X);
    const W L0 = sl.L0, L1 = sl.L1, D = sl.D;
    const W h0 = y0 / L0, h1 = y1 / L1;
    const W q0 = dist2 / (L0 * L0), q1 = dist2 / (L1 * L1);  // 1 - h_i^2
    W hv, q;
    if (v <= 0.5) {
      hv = h0 + W(v) * D;
      q = hv < 0 ? q0 + W(v) * D * (-h0 - hv) : q1 + (1 - W(v)) * D * (h1 + hv);
    } else {
      hv = h1 - (1 - W(v)) * D;
      q = hv < 0 ? q0 + W(v) * D * (-h0 - hv) : q1 + (1 - W(v)) * D * (h1 + hv);
    }
    const W y = hv * std::sqrt(dist2) / std::sqrt(q);
    W from_y0;  // Y - y0
    if (h0 >= 0) {
      from_y0 = std::sqrt(dist2) * W(v) * D * (hv + h0) /
                (std::sqrt(q * q0) * (hv * std::sqrt(q0) + h0 * std::sqrt(q)));
    } else {
      from_y0 = y - y0;
    }
    from_y0 = std::clamp(from_y0, W(0), W(2));
    Y = static_cast<double>(y0 + from_y0);
    dy = static_cast<double>(from_y0 - 1);
  }
};

}  // namespace disklab::ellipse
