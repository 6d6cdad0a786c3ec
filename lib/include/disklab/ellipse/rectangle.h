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
  double h = 0.0, y0 = 0.0, y1 = 0.0;  // depth and y range, in radii
  double S = 0.0;                      // solid angle of the rectangle seen from o
  bool valid = false;

  using W = long double;

  // D(X) = h1(X) - h0(X) (see the header comment) and L0, L1.
  W height_range(W X) const {
    const W hh = W(h) * h, xx = X * X;
    const W L0 = std::sqrt(xx + W(y0) * y0 + hh), L1 = std::sqrt(xx + W(y1) * y1 + hh);
    if (y0 >= 0.0)
      return (W(y1) - y0) * (W(y1) + y0) * (xx + hh) / (L0 * L1 * (W(y1) * L0 + W(y0) * L1));
    return W(y1) / L1 - W(y0) / L0;
  }
  // G(X): the solid angle of [0, X] x [y0, y1] (signed).
  W G(W X) const {
    const W hh = W(h) * h, xx = X * X;
    const W L0 = std::sqrt(xx + W(y0) * y0 + hh), L1 = std::sqrt(xx + W(y1) * y1 + hh);
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
    q.y0 = e_over_r - 1.0;
    q.y1 = e_over_r + 1.0;
    q.S = static_cast<double>(2 * q.G(1));
    q.valid = q.S > 0.0 && std::isfinite(q.S);
    return q;
  }

  // The point (X, Y) on the square, in radii, for (u, v) in [0, 1]^2: uniform in solid angle.
  void sample(double u, double v, double& X, double& Y) const {
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
    const W L0 = std::sqrt(dist2 + W(y0) * y0), L1 = std::sqrt(dist2 + W(y1) * y1);
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
    Y = static_cast<double>(std::clamp(y, W(y0), W(y1)));
  }
};

}  // namespace disklab::ellipse
