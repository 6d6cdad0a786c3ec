#pragma once
// Solid angle of a disk and the cumulative solid angles of the radial and parallel maps as
// functions of their azimuths (Guillén et al. 2017, eqs. 8-12, 16-20).
//
// WHY NOT THE PRINTED FORMS. Eq. (19) at phi = pi/2 subtracts two numbers close to pi/2 to get a
// quadrant of area ~pi a b / 4, and eq. (11) subtracts F from (1 - n) Pi with a difference of
// order b_t^2: both lose about two digits per decade of distance (docs/design.md section 3). They
// are kept here (`*_printed`) to measure that loss. The production forms below have no
// cancellation:
//
//  - Total solid angle. Eq. (19) at pi/2, with the complete-integral relation
//    Pi(n|m) + Pi(m/n|m) = K(m) + (pi/2) sqrt(n / ((1-n)(n-m)))  (DLMF 19.7.8; here
//    sqrt(...) = 1/C, m/n = a^2), becomes Omega_r(pi/2) = C (Pi(a^2|m) - K(m)), i.e.
//        Omega = (4/3) a^2 C R_J(0, 1 - m, 1, 1 - a^2),   C = b (1 - a^2) / (a sqrt(1 - b^2)) = a h
//        / r,
//    one Carlson integral with positive arguments times positive factors.
//  - Radial sector (eq. 16). With the tangent ellipse's parametric angle vphi (eq. 20) the planar
//    sector element r_t^2 dphi = a_t b_t dvphi and 1 - h_r = r_t^2 / (w (1 + w)), w = sqrt(1 +
//    r_t^2), give  Omega_r = a_t b_t int_0^vphi dt / (w(t) (1 + w(t))),  w^2 = 1 + a_t^2 cos^2 t +
//    b_t^2 sin^2 t. The integrand is positive and analytic; where r_t^2 <= 3 its nearest
//    singularity (w = 0) stays far enough from the interval for a 20-point Gauss-Legendre rule to
//    reach ~1e-16 relative at every eccentricity. Where r_t^2 > 3 (only near the disk) eq. (19)
//    itself is used: there 1/r_t^2 exceeds the integrand by at most a factor 2, so its subtraction
//    loses at most one bit. The split point is fixed per shading point
//    (SphericalEllipse::radial_split).
//  - Parallel half sector (eq. 11). (1 - n) Pi - F with n = -b_t^2 < 0 is evaluated as two
//    positive terms (math::ellint_one_minus_n_pi_minus_f): no cancellation.
#include <cmath>

#include "disklab/ellipse/geometry.h"
#include "disklab/math/constants.h"
#include "disklab/math/elliptic.h"

namespace disklab::ellipse {

// -------------------------------------------------------------------------------------------
// Total solid angle.

// Production value (cancellation-free, see above); 0 for an empty ellipse.
inline double solid_angle(const SphericalEllipse& se) {
  return se.omega;
}
// Convenience: builds the ellipse (throws std::invalid_argument on invalid input).
double solid_angle(const Disk& disk, const Vec3& o);

// The cancellation-free closed form from the shape (what make_spherical_ellipse stores).
inline double solid_angle_stable(const SphericalEllipse& se) {
  if (se.empty) return 0.0;
  const double rj = math::carlson_rj(0.0, se.one_minus_m, 1.0, se.one_minus_a2);
  return 4.0 / 3.0 * se.a * se.a * se.radial_coefficient * rj;
}

// On-axis closed form 2 pi (1 - d / sqrt(d^2 + r^2)) for a point at distance d > 0 on the axis,
// computed as 2 pi r^2 / (L (d + L)), L = sqrt(d^2 + r^2): no cancellation far away.
inline double solid_angle_on_axis(double d, double r) {
  if (!(d > 0.0) || !(r > 0.0)) return 0.0;
  const double L = std::hypot(d, r);
  return math::kTwoPi * (r / L) * (r / (d + L));
}

// Eq. (19) as printed, at phi_r = pi/2, times 4: 4 (pi/2 - C Pi(n; pi/2|m)). Loses ~2 digits per
// decade of distance (kept to measure it).
inline double solid_angle_radial_printed(const SphericalEllipse& se) {
  if (se.empty) return 0.0;
  return 4.0 *
         (math::kHalfPi - se.radial_coefficient * math::ellint_pi(se.n_r, math::kHalfPi, se.m));
}

// Eq. (11) as printed at phi_p = beta (varphi_p = pi/2), doubled by eq. (7):
// 2 (2 c_t / b_t) [(1 - n) Pi(n; pi/2|m) - F(pi/2|m)], n = -b_t^2. Cancels for small b_t.
inline double solid_angle_parallel_printed(const SphericalEllipse& se) {
  if (se.empty) return 0.0;
  const double n = se.n_p();
  const double bracket =
      (1.0 - n) * math::ellint_pi(n, math::kHalfPi, se.m) - math::ellint_f(math::kHalfPi, se.m);
  return 2.0 * (2.0 * se.a / se.b_t) * bracket;
}

// -------------------------------------------------------------------------------------------
// Radial map (Sec. 3.3): functions of the azimuth phi in [0, pi/2] of the first quadrant
// (measured from x_e towards y_e). All return 0 for an empty ellipse.

// Eq. (20): the tangent ellipse's parametric angle, tan vphi = (a_t / b_t) tan phi.
inline double radial_parametric_angle(const SphericalEllipse& se, double phi) {
  return std::atan2(se.a_t * std::sin(phi), se.b_t * std::cos(phi));
}
// Inverse of eq. (20): tan phi = (b_t / a_t) tan vphi.
inline double radial_azimuth(const SphericalEllipse& se, double vphi) {
  return std::atan2(se.b_t * std::sin(vphi), se.a_t * std::cos(vphi));
}

// Eq. (18) squared, r^2(phi) = a^2 b^2 / (a^2 sin^2 phi + b^2 cos^2 phi), and its complement
// 1 - r^2 = (a^2 cos^2(beta) sin^2 phi + b^2 cos^2(alpha) cos^2 phi) / (same), formed from
// positive terms so that h_r = sqrt(1 - r^2) keeps full accuracy when r -> 1.
struct RadialRadius {
  double r2 = 0.0, one_minus_r2 = 1.0;
};
inline RadialRadius radial_radius2(const SphericalEllipse& se, double s, double c) {
  const double as = se.a * s, bc = se.b * c;
  const double den = as * as + bc * bc;
  RadialRadius out;
  if (!(den > 0.0)) return out;
  out.r2 = (se.a * se.b) * (se.a * se.b) / den;
  out.one_minus_r2 = (as * as * se.one_minus_b2 + bc * bc * se.one_minus_a2) / den;
  return out;
}
inline RadialRadius radial_radius2(const SphericalEllipse& se, double phi) {
  return radial_radius2(se, std::sin(phi), std::cos(phi));
}

// Eq. (17): h_r(phi) = sqrt(1 - r^2(phi)), the lower end of the radial map's segment.
inline double h_r(const SphericalEllipse& se, double phi) {
  if (se.empty) return 1.0;
  return std::sqrt(radial_radius2(se, phi).one_minus_r2);
}
// 1 - h_r(phi) = r^2 / (1 + sqrt(1 - r^2)): the integrand of eq. (16) and dOmega_r/dphi, exact
// for Newton. (1 - sqrt(1 - r^2) would cancel for small r.)
inline double one_minus_h_r(const SphericalEllipse& se, double sin_phi, double cos_phi) {
  if (se.empty) return 0.0;
  const RadialRadius rr = radial_radius2(se, sin_phi, cos_phi);
  return rr.r2 / (1.0 + std::sqrt(std::max(0.0, rr.one_minus_r2)));
}
inline double one_minus_h_r(const SphericalEllipse& se, double phi) {
  return one_minus_h_r(se, std::sin(phi), std::cos(phi));
}

namespace detail {

// The low part of pi/2: kHalfPi + kHalfPiLo = pi/2 to ~1e-33, for complements pi/2 - t that
// must keep their relative accuracy near pi/2.
inline constexpr double kHalfPiLo = 6.123233995736766036e-17;

// Gauss-Legendre, 20 points on [-1, 1]: the positive nodes and their weights (computed at 40
// digits; the rule is symmetric).
inline constexpr double kGL20x[10] = {0.993128599185094924786, 0.963971927277913791268,
                                      0.912234428251325905868, 0.839116971822218823395,
                                      0.746331906460150792614, 0.636053680726515025453,
                                      0.510867001950827098004, 0.373706088715419560673,
                                      0.22778585114164507808,  0.0765265211334973337546};
inline constexpr double kGL20w[10] = {0.0176140071391521183119, 0.040601429800386941331,
                                      0.0626720483341090635695, 0.0832767415767047487248,
                                      0.101930119817240435037,  0.118194531961518417312,
                                      0.131688638449176626898,  0.142096109318382051329,
                                      0.149172986472603746788,  0.152753387130725850698};

// w^2 = 1 + a_t^2 cos^2 t + b_t^2 sin^2 t from t (when t <= pi/4) or from its complement
// pi/2 - t (above): positive terms, cos t near pi/2 formed as sin(pi/2 - t) with full relative
// accuracy. (With cos 2t, w^2 = mean + amp cos 2t cancels to an absolute error ~eps a_t^2, of the
// order of w^2 itself where the point is near the plane of the disk's rim and a_t ~ sqrt(r/h).)
inline double radial_w2(double at2, double bt2, double t, double comp) {
  const bool low = t <= 0.25 * math::kPi;
  const double c = low ? std::cos(t) : std::sin(comp), s = low ? std::sin(t) : std::cos(comp);
  return 1.0 + at2 * c * c + bt2 * s * s;
}

// a_t b_t int_{t0}^{t1} dt / (w (1 + w)), w^2 = 1 + a_t^2 cos^2 t + b_t^2 sin^2 t, by GL20.
// Where a_t^2 - b_t^2 <= 2 (every point but those near the disk), w^2 is written with cos(2t), one
// cosine per node, its absolute error ~eps (a_t^2 - b_t^2) below eps w^2. Elsewhere the integrand
// varies on a scale ~1/a_t next to pi/2, so the nodes are placed by their complements pi/2 - t
// (an absolute error eps pi in a node near pi/2 would move it by eps a_t of that scale) and w^2
// comes from radial_w2.
// c0, c1 are the complements pi/2 - t0, pi/2 - t1 to full relative accuracy (the interval's
// width is taken from them: near pi/2 they carry the digits t0 and t1 cannot).
inline double radial_gauss(const SphericalEllipse& se, double t0, double t1, double c0, double c1) {
  const double at2 = se.a_t * se.a_t, bt2 = se.b_t * se.b_t;
  const double mean = 1.0 + 0.5 * (at2 + bt2), amp = 0.5 * (at2 - bt2);
  const bool doubled = amp <= 1.0;
  const double mid = t0 + t1;  // in the doubled angle 2t
  const double half = t0 <= 0.25 * math::kPi ? t1 - t0 : c0 - c1;
  const double cmid = 0.5 * (c0 + c1);
  double sum = 0.0;
  for (int i = 0; i < 10; ++i) {
    const double d = half * kGL20x[i];
    double w2m, w2p;
    if (doubled) {
      w2m = mean + amp * std::cos(mid - d);
      w2p = mean + amp * std::cos(mid + d);
    } else {
      w2m = radial_w2(at2, bt2, 0.5 * (mid - d), cmid + 0.5 * d);
      w2p = radial_w2(at2, bt2, 0.5 * (mid + d), cmid - 0.5 * d);
    }
    const double wm = std::sqrt(w2m), wp = std::sqrt(w2p);
    sum += kGL20w[i] * (1.0 / (wm * (1.0 + wm)) + 1.0 / (wp * (1.0 + wp)));
  }
  return se.a_t * se.b_t * (0.5 * half) * sum;
}

// pi/2 - t for a double t in [0, pi/2], to full relative accuracy (kHalfPi - t is exact there
// for t >= pi/4, Sterbenz; the low part of pi/2 carries the rest).
inline double half_pi_complement(double t) {
  return (math::kHalfPi - t) + kHalfPiLo;
}
// The split's complement, from the same a_t^2, b_t^2 as geometry.cpp's split.
inline double radial_split_complement(const SphericalEllipse& se) {
  if (se.radial_split >= math::kHalfPi) return 0.0;
  if (!(se.radial_split > 0.0)) return math::kHalfPi;
  constexpr double kSplit = 3.0;
  const double at2 = se.a_t * se.a_t, bt2 = se.b_t * se.b_t;
  return std::atan2(std::sqrt(kSplit - bt2), std::sqrt(at2 - kSplit));
}

// Eq. (19) at parametric angle vphi with complement cvphi = pi/2 - vphi (n, m with their
// complements, so Pi keeps accuracy near the disk where n -> 1). phi - C Pi subtracts two terms
// whose derivatives in vphi are ~a_t/b_t times the difference's, so both must see the same angle:
// near pi/2 (cvphi < pi/4) sin and cos come from the complement and Pi from them (the portable
// path takes s, c), and phi = atan2(b_t s, a_t c) from the same pair. Elsewhere the double vphi is
// as accurate as its complement, and Pi takes it.
inline double radial_eq19(const SphericalEllipse& se, double vphi, double cvphi) {
  if (cvphi >= 0.25 * math::kPi) {
    const double pi = math::ellint_pi(se.n_r, se.one_minus_n_r, vphi, se.m, se.one_minus_m);
    return std::atan2(se.b_t * std::sin(vphi), se.a_t * std::cos(vphi)) -
           se.radial_coefficient * pi;
  }
  const long double s = std::cos(static_cast<long double>(cvphi));
  const long double c = std::sin(static_cast<long double>(cvphi));
  const double pi = static_cast<double>(math::detail::ellint_pi_portable_sc<double>(
      se.n_r, se.one_minus_n_r, s, c, se.m, se.one_minus_m));
  return std::atan2(se.b_t * static_cast<double>(s), se.a_t * static_cast<double>(c)) -
         se.radial_coefficient * pi;
}

}  // namespace detail

// Omega_r as a function of the parametric angle vphi in [0, pi/2] (eq. 16 in the variable of
// eq. 20), cancellation-free (see the header comment). Monotone increasing; derivative
// (1 - h_r) dphi/dvphi.
// The form with the complement cvphi = pi/2 - vphi given to full relative accuracy (from the
// angle's own construction, e.g. an atan2 with the arguments swapped): near the disk's rim plane
// Omega_r varies on a scale ~1/a_t next to vphi = pi/2, where the double vphi cannot resolve it.
inline double radial_sector_parametric(const SphericalEllipse& se, double vphi, double cvphi) {
  if (se.empty || !(vphi > 0.0)) return 0.0;
  if (!(cvphi > 0.0)) {
    vphi = math::kHalfPi;
    cvphi = 0.0;
  }
  if (vphi <= se.radial_split) return detail::radial_eq19(se, vphi, cvphi);
  const double csplit = detail::radial_split_complement(se);
  const double head =
      se.radial_split > 0.0 ? detail::radial_eq19(se, se.radial_split, csplit) : 0.0;
  return head + detail::radial_gauss(se, se.radial_split, vphi, csplit, cvphi);
}
inline double radial_sector_parametric(const SphericalEllipse& se, double vphi) {
  if (!(vphi < math::kHalfPi)) return radial_sector_parametric(se, math::kHalfPi, 0.0);
  return radial_sector_parametric(se, vphi, detail::half_pi_complement(vphi));
}

// Omega_r(phi), phi in [0, pi/2] (eqs. 16/19): the solid angle of the first-quadrant sector of
// the spherical ellipse between azimuths 0 and phi. Cancellation-free, ~1e-16 relative at every
// distance. dOmega_r/dphi = one_minus_h_r(phi).
inline double radial_sector(const SphericalEllipse& se, double phi) {
  if (se.empty || !(phi > 0.0)) return 0.0;
  if (phi >= math::kHalfPi) return se.quadrant;
  const double sp = std::sin(phi), cp = std::cos(phi);
  return radial_sector_parametric(se, std::atan2(se.a_t * sp, se.b_t * cp),
                                  std::atan2(se.b_t * cp, se.a_t * sp));
}

// Eq. (19) exactly as printed: phi - C Pi(n; vphi|m). Cancels for small ellipses.
inline double radial_sector_printed(const SphericalEllipse& se, double phi) {
  if (se.empty || !(phi > 0.0)) return 0.0;
  const double vphi = radial_parametric_angle(se, std::fmin(phi, math::kHalfPi));
  return std::fmin(phi, math::kHalfPi) -
         se.radial_coefficient * math::ellint_pi(se.n_r, vphi, se.m);
}

// -------------------------------------------------------------------------------------------
// Parallel map (Sec. 3.2): functions of the cylinder angle phi_p in [0, beta] (eq. 7 mirrors
// negative angles). varphi_p is the angle of eq. (12).

// Eq. (12): varphi_p = asin(tan(phi_p) / b_t), clamped to [0, pi/2].
inline double parallel_parametric_angle(const SphericalEllipse& se, double phi_p) {
  if (se.empty || !(phi_p > 0.0)) return 0.0;
  const double s = std::tan(std::fmin(phi_p, se.beta)) / se.b_t;
  return s >= 1.0 ? math::kHalfPi : std::asin(s);
}
// Inverse of eq. (12): phi_p = atan(b_t sin varphi_p).
inline double parallel_azimuth(const SphericalEllipse& se, double varphi_p) {
  return std::atan(se.b_t * std::sin(varphi_p));
}

// Eq. (9) in the variable of eq. (12): h_p = c_t cos(varphi) / sqrt(1 - m sin^2 varphi) (from
// eq. 26 with y = b_t sin varphi), with 1 - m sin^2 = cos^2 + (1 - m) sin^2: no cancellation,
// exact zero at the rim (varphi = pi/2).
inline double h_p_parametric(const SphericalEllipse& se, double varphi_p) {
  if (se.empty) return 0.0;
  const double s = std::sin(varphi_p), c = std::cos(varphi_p);
  const double delta2 = c * c + se.one_minus_m * s * s;
  return se.a * std::fabs(c) / std::sqrt(delta2);
}
// Eq. (9): h_p(phi_p), phi_p in [-beta, beta] (even).
inline double h_p(const SphericalEllipse& se, double phi_p) {
  return h_p_parametric(se, parallel_parametric_angle(se, std::fabs(phi_p)));
}

// Omega_p^+ of eq. (8) as a function of varphi_p in [0, pi/2] (eq. 11), cancellation-free:
// (2 c_t / b_t) [(1 - n) Pi(n; varphi|m) - F(varphi|m)] with the bracket as two positive terms.
// dOmega_p^+/dphi_p = 2 h_p.
inline double parallel_half_sector_parametric(const SphericalEllipse& se, double varphi_p) {
  if (se.empty || !(varphi_p > 0.0)) return 0.0;
  if (varphi_p > math::kHalfPi) varphi_p = math::kHalfPi;
  const double bracket = math::ellint_one_minus_n_pi_minus_f(se.n_p(), 1.0 + se.b_t * se.b_t,
                                                             varphi_p, se.m, se.one_minus_m);
  return 2.0 * se.a / se.b_t * bracket;
}
// Omega_p^+(phi_p), phi_p in [0, beta] (eqs. 8/11). Omega_p^+(beta) = omega / 2.
inline double parallel_half_sector(const SphericalEllipse& se, double phi_p) {
  return parallel_half_sector_parametric(se, parallel_parametric_angle(se, phi_p));
}
// Eq. (11) exactly as printed. Cancels for small b_t.
inline double parallel_half_sector_printed(const SphericalEllipse& se, double phi_p) {
  if (se.empty || !(phi_p > 0.0)) return 0.0;
  const double v = parallel_parametric_angle(se, phi_p);
  const double n = se.n_p();
  return 2.0 * se.a / se.b_t * ((1.0 - n) * math::ellint_pi(n, v, se.m) - math::ellint_f(v, se.m));
}

// -------------------------------------------------------------------------------------------
// Independent reference: the solid angle of the disk by quadrature over its boundary, using no
// ellipse formula. The disk is star-shaped about any interior point q, so it is the union of thin
// wedges (q, p(psi), p(psi + dpsi)) with p(psi) = c + r (cos psi, sin psi) on the rim; by the
// Van Oosterom-Strackee formula (tan(Omega/2) for a triangle, to first order in dpsi) each
// subtends  dOmega = det[R1, R2, p'] dpsi / (L2 (L1 L2 + R1 . R2)),  R1 = q - o, R2 = p - o.
// In coordinates with c at the origin and o = (e, 0, h):
//  - e < r: q = the foot (e, 0, 0) of o. Then R1 = (0, 0, -h), R1 . R2 = h^2 and
//        dOmega/dpsi = r (r - e cos psi) / (L2 (L2 + h)),   L2 = |p - o|;
//  - e >= r: q = c. Then  dOmega/dpsi = h r^2 / (L2 (L0 L2 + R1 . R2)), L0 = |c - o|, and where
//    R1 . R2 < 0 the bracket is |R1 x R2|^2 / (L0 L2 - R1 . R2) = r^2 (h^2 + e^2 sin^2 psi) /
//    (...).
// Every term is positive (no cancellation in double either), and the apex is never under o, so
// the integrand has no peak of width h (it has one only when o is near the rim itself). It is
// smooth, even and 2 pi-periodic: the trapezoidal rule on [0, pi] converges geometrically;
// intervals are doubled until two estimates agree to rel_tol. Templated on Real so the
// reference generator runs it in cpp_bin_float_50.
template <class Real>
struct QuadratureResult {
  Real value = 0;
  Real change = 0;  // |last - previous| estimate
  long intervals = 0;
  bool converged = false;
};

template <class Real>
QuadratureResult<Real> solid_angle_boundary_quadrature(Real h, Real e, Real r, Real rel_tol,
                                                       int max_log2_intervals = 24) {
  using std::atan;
  using std::cos;
  using std::sin;
  using std::sqrt;
  QuadratureResult<Real> out;
  if (!(h > 0) || !(r > 0)) {
    out.converged = true;
    return out;
  }
  const Real pi = 4 * atan(Real(1));
  const Real A = h * h + e * e, L0 = sqrt(A);
  const Real er = e * r, emr = e - r;
  const bool apex_at_foot = e < r;
  auto f = [&](const Real& psi) -> Real {
    const Real sh = sin(psi / 2), ch = cos(psi / 2);
    const Real s = 2 * sh * ch, c = 1 - 2 * sh * sh;
    // L2^2 = r^2 - 2 e r cos psi + e^2 + h^2, written without cancellation near the rim.
    const Real L2 = sqrt(emr * emr + h * h + 4 * er * sh * sh);
    if (apex_at_foot) return r * (r - e * c) / (L2 * (L2 + h));
    const Real dot = A - er * c;
    const Real bracket =
        dot >= 0 ? L0 * L2 + dot : r * r * (h * h + e * e * s * s) / (L0 * L2 - dot);
    return h * r * r / (L2 * bracket);
  };
  // Trapezoid on [0, pi], then times 2 (even integrand). The running sum is compensated
  // (Neumaier): it accumulates up to millions of terms across levels, and plain summation would
  // drift by ~N eps, which the stopping test would mistake for a lack of convergence.
  Real sum = 0, comp = 0;
  auto add = [&](const Real& x) {
    using std::abs;
    const Real t = sum + x;
    comp += abs(sum) >= abs(x) ? (sum - t) + x : (x - t) + sum;
    sum = t;
  };
  long n = 8;
  add(f(Real(0)) / 2);
  add(f(pi) / 2);
  for (long k = 1; k < n; ++k)
    add(f(pi * Real(k) / Real(n)));
  Real estimate = 2 * pi / Real(n) * (sum + comp);
  for (int level = 3; level < max_log2_intervals; ++level) {
    for (long k = 1; k < 2 * n; k += 2)
      add(f(pi * Real(k) / Real(2 * n)));
    n *= 2;
    const Real next = 2 * pi / Real(n) * (sum + comp);
    using std::abs;
    out.change = abs(next - estimate);
    estimate = next;
    // At least 64 intervals before a small change counts: coarse rules can agree by accident.
    if (n >= 64 && out.change <= rel_tol * abs(next)) {
      out.converged = true;
      break;
    }
  }
  out.value = estimate;
  out.intervals = n;
  return out;
}

}  // namespace disklab::ellipse
