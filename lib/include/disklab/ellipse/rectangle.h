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
// G(X) = (u - 1/2) S (safeguarded Newton). The height: h_v = h0 + v D, and
// 1 - h_v^2 = (1 - h0^2) + v D (-h0 - h_v) for h_v < 0, (1 - h1^2) + (1 - v) D (h1 + h_v) for
// h_v >= 0: positive terms, so Y = h_v dist / sqrt(1 - h_v^2), dist = sqrt(X^2 + h^2), keeps its
// accuracy when the rectangle lies near the horizon. Everything runs in long double, whose
// exponent range keeps the squares of lengths from 1e-300 to 1e300 radii representable.
#include <algorithm>
#include <cmath>

#include "disklab/math/roots.h"

namespace disklab::ellipse {

// Newton stops when |G(X) - target| <= kRectangleNewtonTol * S.
inline constexpr double kRectangleNewtonTol = 1e-15;

struct SphericalRectangle {
  double h = 0.0, yc = 0.0;  // depth and the square's centre in y, in radii (y0, y1 = yc -+ 1)
  double S = 0.0;            // solid angle of the rectangle seen from o
  bool valid = false;

  using W = long double;

  // The ends in W: y1 - y0 = 2 and y1 + y0 = 2 yc are used as such where they matter (for a
  // square far to the side, yc -+ 1 may round to the same double).
  W y0() const { return W(yc) - 1; }
  W y1() const { return W(yc) + 1; }
  // D(X) = h1(X) - h0(X) (see the header comment).
  W height_range(W X) const {
    const W hh = W(h) * h, xx = X * X, y0 = this->y0(), y1 = this->y1();
    const W L0 = std::sqrt(xx + y0 * y0 + hh), L1 = std::sqrt(xx + y1 * y1 + hh);
    if (yc >= 1.0) return 4 * W(yc) * (xx + hh) / (L0 * L1 * (y1 * L0 + y0 * L1));
    return y1 / L1 - y0 / L0;
  }
  // G(X): the solid angle of [0, X] x [y0, y1] (signed).
  W G(W X) const {
    const W hh = W(h) * h, xx = X * X, y0 = this->y0(), y1 = this->y1();
    const W L0 = std::sqrt(xx + y0 * y0 + hh), L1 = std::sqrt(xx + y1 * y1 + hh);
    const W A = X * y1 / (h * L1), B = X * y0 / (h * L0);
    return std::atan2((X / h) * height_range(X), 1 + A * B);
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
    q.valid = q.S > 0.0 && std::isfinite(q.S);
    return q;
  }

  // The point on the square for (u, v) in [0, 1]^2, uniform in solid angle: X, Y in radii and
  // dy = Y - yc, the offset from the centre, formed without cancellation: with Y(h) = dist h /
  // sqrt(1 - h^2) and Y(h0) = y0, Y - y0 = dist (h_v^2 - h0^2) / (sqrt(q_v q0) (h_v sqrt(q0) +
  // h0 sqrt(q_v))) and h_v^2 - h0^2 = v D (h_v + h0), positive terms where h0 >= 0.
  void sample(double u, double v, double& X, double& Y, double& dy) const {
    const W target = (W(u) - 0.5L) * S;
    auto eval = [&](double x) {
      const W d = height_range(x);
      const W deriv = W(h) * d / (W(x) * x + W(h) * h);
      return std::pair<double, double>(static_cast<double>(G(x) - target),
                                       static_cast<double>(deriv));
    };
    X = u <= 0.0   ? -1.0
        : u >= 1.0 ? 1.0
                   : math::safeguarded_newton(eval, -1.0, 1.0, 2.0 * u - 1.0,
                                              kRectangleNewtonTol * S, 1e-17, 200)
                         .x;
    const W xx = W(X) * X, hh = W(h) * h, dist2 = xx + hh;
    const W y0 = this->y0(), y1 = this->y1();
    const W L0 = std::sqrt(dist2 + y0 * y0), L1 = std::sqrt(dist2 + y1 * y1);
    const W h0 = y0 / L0, h1 = y1 / L1, D = height_range(X);
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
