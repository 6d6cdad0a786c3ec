#pragma once
// Uniform sampling of the solid angle of a planar rectangle (Ureña, Fajardo, King 2013,
// "An Area-Preserving Parametrization for Spherical Rectangles"), the proposal of Gamito's disk
// sampler. Written from the paper's construction: the rectangle is put in a local frame with the
// shading point at the origin and the rectangle in the plane z = z0 < 0; the first coordinate
// fixes the azimuthal slice by the solid angle of the spherical quad it cuts off (its angle sum
// minus 2 pi, Girard's theorem, inverted for the slice's edge in closed form), the second
// interpolates the slice's cylindrical height linearly (Ureña et al. 2013, the parametrization's
// two coordinates).
#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include "disklab/math/constants.h"

#include "disklab/types.h"

namespace disklab::ellipse {

struct SphericalRectangle {
  Vec3 x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();  // local frame (origin at o)
  double z0 = 0.0, x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
  double b0 = 0.0, b1 = 0.0, k = 0.0;
  double S = 0.0;  // solid angle of the rectangle seen from o
  bool valid = false;

  // Rectangle with corner s and edges ex, ey (orthogonal), seen from o.
  static SphericalRectangle make(const Vec3& o, const Vec3& s, const Vec3& ex, const Vec3& ey) {
    SphericalRectangle q;
    const double exl = ex.norm(), eyl = ey.norm();
    if (!(exl > 0.0) || !(eyl > 0.0) || !std::isfinite(exl) || !std::isfinite(eyl)) return q;
    q.x = ex / exl;
    q.y = ey / eyl;
    q.z = q.x.cross(q.y);
    const Vec3 d = s - o;
    q.z0 = d.dot(q.z);
    // The construction needs the rectangle below the origin (z0 < 0): flip the normal if not.
    if (q.z0 > 0.0) {
      q.z = -q.z;
      q.z0 = -q.z0;
    }
    if (!(q.z0 < 0.0)) return q;  // o in the rectangle's plane: nothing subtended
    q.x0 = d.dot(q.x);
    q.y0 = d.dot(q.y);
    q.x1 = q.x0 + exl;
    q.y1 = q.y0 + eyl;
    // Normals of the four planes through o and an edge; the quad's interior angles follow.
    const Vec3 n0 = Vec3(0.0, q.z0, -q.y0).normalized();
    const Vec3 n1 = Vec3(-q.z0, 0.0, q.x1).normalized();
    const Vec3 n2 = Vec3(0.0, -q.z0, q.y1).normalized();
    const Vec3 n3 = Vec3(q.z0, 0.0, -q.x0).normalized();
    const double g0 = std::acos(std::clamp(-n0.dot(n1), -1.0, 1.0));
    const double g1 = std::acos(std::clamp(-n1.dot(n2), -1.0, 1.0));
    const double g2 = std::acos(std::clamp(-n2.dot(n3), -1.0, 1.0));
    const double g3 = std::acos(std::clamp(-n3.dot(n0), -1.0, 1.0));
    q.b0 = n0.z();
    q.b1 = n2.z();
    q.k = math::kTwoPi - g2 - g3;
    // Girard: the quad's area is its angle sum minus 2 pi. This subtraction loses relative
    // accuracy for tiny quads (distant rectangles); Gamito's sampler only uses S as a proposal.
    q.S = g0 + g1 - q.k;
    q.valid = q.S > 0.0 && std::isfinite(q.S);
    return q;
  }

  // The point on the rectangle for (u, v) in [0,1]^2, uniform in solid angle from o (the
  // point the rectangle was made for).
  Vec3 sample_point(const Vec3& o, double u, double v) const {
    const double au = u * S + k;
    const double fu = (std::cos(au) * b0 - b1) / std::sin(au);
    double cu = (fu > 0.0 ? 1.0 : -1.0) / std::sqrt(fu * fu + b0 * b0);
    if (!std::isfinite(cu)) cu = fu > 0.0 ? 1.0 : -1.0;
    cu = std::clamp(cu, -1.0, 1.0);
    double xu = -(cu * z0) / std::sqrt(std::max(0.0, 1.0 - cu * cu));
    xu = std::isfinite(xu) ? std::clamp(xu, x0, x1) : (cu > 0.0 ? x1 : x0);
    const double dist = std::sqrt(xu * xu + z0 * z0);
    const double h0 = y0 / std::sqrt(dist * dist + y0 * y0);
    const double h1 = y1 / std::sqrt(dist * dist + y1 * y1);
    const double hv = h0 + v * (h1 - h0);
    const double hv2 = hv * hv;
    double yv = y1;
    if (hv2 < 1.0) yv = hv * dist / std::sqrt(1.0 - hv2);
    yv = std::isfinite(yv) ? std::clamp(yv, y0, y1) : y1;
    return o + xu * x + yv * y + z0 * z;
  }
};

}  // namespace disklab::ellipse
