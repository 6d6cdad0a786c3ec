#pragma once
// The projected solid angle P = int max(0, w . n_o) dw of a disk seen from a point, at 50 digits,
// by a quadrature over the disk that shares nothing with ellipse/projected.h (no spherical
// ellipse, no Stokes form). Shared by the reference generator (projected.cpp, which writes
// reference/projected_P.csv) and the in-test check of property_tests/ellipse/projected_test.cpp.
//
// P = int_disk max(0, cos_o) cos_l / d^2 dA in the disk's own coordinates (u, v), formed in 50
// digits from the double inputs, with u along the in-plane offset of the point (its foot is at
// (e, 0)). For each u the integral over the chord v in [-Y, Y] (Y = sqrt(R^2 - u^2)), clipped
// where the receiver's cosine changes sign (a line in the disk's plane), is closed-form,
//   int (n2 v + beta) / (v^2 + k)^2 dv = -n2 / (2 (v^2 + k))
//       + beta (v / (2 k (v^2 + k)) + atan(v / sqrt k) / (2 k^(3/2))),
// evaluated as differences that do not cancel; u = R sin(theta) is integrated by tanh-sinh,
// split where the clipping line meets the rim and at geometric distances h 10^j from the foot
// (the integrand's width there is ~h).
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <vector>

namespace disklab::reference_generate {

struct ProjectedQuadrature {
  using Real = boost::multiprecision::cpp_bin_float_50;
  Real value = 0;          // P; exactly 0 where the point sees nothing above its horizon
  Real error = 0;          // sum of tanh-sinh's error estimates over the pieces (absolute)
  Real l1 = 0;             // sum of the pieces' L1 norms (the integrand is >= 0: equals value)
  bool visible = false;    // the point is on a lit side of the disk
  bool straddles = false;  // the receiver's horizon plane cuts the disk
  int pieces = 0;          // tanh-sinh intervals
};

// `tolerance`: tanh-sinh's level-to-level stop, relative; 1e-40 leaves every digit of a 45-digit
// print but the last few (its error falls doubly exponentially per level).
inline ProjectedQuadrature projected_solid_angle_quadrature(
    const double center[3], const double normal[3], double radius, bool two_sided,
    const double point[3], const double receiver_normal[3],
    const ProjectedQuadrature::Real& tolerance = ProjectedQuadrature::Real(1e-40)) {
  using Real = ProjectedQuadrature::Real;
  using boost::multiprecision::abs;
  using boost::multiprecision::asin;
  using boost::multiprecision::atan2;
  using boost::multiprecision::cos;
  using boost::multiprecision::sin;
  using boost::multiprecision::sqrt;
  auto dot = [](const Real* x, const Real* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  auto rmax = [](const Real& x, const Real& y) -> Real { return x > y ? x : y; };
  auto rmin = [](const Real& x, const Real& y) -> Real { return x < y ? x : y; };
  ProjectedQuadrature out;
  Real nd[3], q[3], no[3];
  for (int i = 0; i < 3; ++i) {
    nd[i] = normal[i];
    q[i] = Real(point[i]) - Real(center[i]);  // exact: 166 bits hold the difference of doubles
    no[i] = receiver_normal[i];
  }
  const Real nd_len = sqrt(dot(nd, nd)), no_len = sqrt(dot(no, no));
  if (!(nd_len > 0) || !(no_len > 0) || !(radius > 0)) return out;
  for (int i = 0; i < 3; ++i) {
    nd[i] /= nd_len;
    no[i] /= no_len;
  }
  const Real h = dot(q, nd), R = radius;
  if (!(h > 0) && !(two_sided && h < 0)) return out;
  out.visible = true;
  // e1 along the in-plane offset q - h nd (any in-plane unit vector on the axis), e2 = nd x e1.
  Real e1[3], e2[3];
  for (int i = 0; i < 3; ++i)
    e1[i] = q[i] - h * nd[i];
  Real e = sqrt(dot(e1, e1));
  if (e > 0) {
    for (Real& x : e1)
      x /= e;
  } else {
    const int k = abs(nd[0]) < Real(0.9) ? 0 : 1;  // the axis least aligned with nd
    Real t[3] = {0, 0, 0};
    t[k] = 1;
    const Real along = dot(t, nd);
    for (int i = 0; i < 3; ++i)
      e1[i] = t[i] - along * nd[i];
    const Real len = sqrt(dot(e1, e1));
    for (Real& x : e1)
      x /= len;
  }
  e2[0] = nd[1] * e1[2] - nd[2] * e1[1];
  e2[1] = nd[2] * e1[0] - nd[0] * e1[2];
  e2[2] = nd[0] * e1[1] - nd[1] * e1[0];
  const Real q1 = dot(q, e1) /* = e */, n1 = dot(no, e1), n2 = dot(no, e2), n3 = dot(no, nd);
  // With x = (u, v, 0) a disk point and d = x - q: cos_o d = n1 (u - q1) + n2 v - n3 h and
  // cos_l d = |h|, so the integrand is |h| (n2 v + beta) / (v^2 + k)^2 where positive.
  auto chord = [&](const Real& u) -> Real {
    const Real Y = sqrt(rmax(Real(0), R * R - u * u));
    const Real beta = n1 * (u - q1) - n3 * h, k = (u - q1) * (u - q1) + h * h;
    Real lo = -Y, hi = Y;
    if (n2 > 0) {
      lo = rmax(lo, -beta / n2);
    } else if (n2 < 0) {
      hi = rmin(hi, -beta / n2);
    } else if (!(beta > 0)) {
      return 0;
    }
    if (!(hi > lo)) return 0;
    const Real s_hi = hi * hi + k, s_lo = lo * lo + k, width = hi - lo, sk = sqrt(k);
    // -n2 / (2 s) and v / (2 k s) differenced over [lo, hi] in factored form; atan(hi / sqrt k) -
    // atan(lo / sqrt k) as one atan2 (in (0, pi) since hi > lo).
    return n2 * width * (hi + lo) / (2 * s_hi * s_lo) +
           beta * (width * (k - hi * lo) / (2 * k * s_hi * s_lo) +
                   atan2(width * sk, k + hi * lo) / (2 * k * sk));
  };
  auto integrand = [&](const Real& theta) -> Real {
    return abs(h) * chord(R * sin(theta)) * R * cos(theta);
  };
  const Real half_pi = boost::math::constants::half_pi<Real>();
  std::vector<Real> cuts{-half_pi, half_pi};
  // Where the line n1 u + n2 v = cst (the receiver's horizon in the disk's plane) meets the rim.
  const Real cst = n1 * q1 + n3 * h, nn = n1 * n1 + n2 * n2;
  if (nn > 0) {
    const Real dist = cst / sqrt(nn);
    if (abs(dist) < R) {
      out.straddles = true;
      const Real along = sqrt(R * R - dist * dist);
      const Real ux = n1 / sqrt(nn), uy = n2 / sqrt(nn);
      for (int sgn : {-1, 1}) {
        const Real u = dist * ux - sgn * along * uy;
        cuts.push_back(asin(rmin(Real(1), rmax(Real(-1), u / R))));
      }
    }
  }
  // The integrand peaks within ~|h| of the foot (u = q1): cuts at q1 +- |h| 10^j inside the disk.
  if (abs(q1) < R) cuts.push_back(asin(q1 / R));
  for (Real step = abs(h); step < 2 * R; step *= 10)
    for (int sgn : {-1, 1}) {
      const Real u = q1 + sgn * step;
      if (abs(u) < R) cuts.push_back(asin(u / R));
    }
  std::sort(cuts.begin(), cuts.end());
  boost::math::quadrature::tanh_sinh<Real> ts(15);
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const Real a = cuts[i], width = cuts[i + 1] - cuts[i];
    if (!(width > 0)) continue;
    // Over [0, 1] in the piece's own variable: on a piece far narrower than its distance from 0
    // (the sliver where a nearly radial horizon line crosses the chords), tanh-sinh on [a, b]
    // itself returned error estimates far above the piece's value.
    auto local = [&](const Real& t) -> Real { return integrand(a + width * t) * width; };
    Real error = 0, l1 = 0;
    out.value += ts.integrate(local, Real(0), Real(1), tolerance, &error, &l1);
    out.error += error;
    out.l1 += l1;
    ++out.pieces;
  }
  return out;
}

}  // namespace disklab::reference_generate
