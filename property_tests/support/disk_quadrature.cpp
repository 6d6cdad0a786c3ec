#include "support/disk_quadrature.h"

#include "reference_csv.h"

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cstdlib>
#include <stdexcept>

namespace disklab::test {
namespace {

using Real = boost::multiprecision::cpp_bin_float_50;

struct ShapeReal {
  Real a, b, a_t, b_t;
};

// Guillén et al. 2017, eqs. (3)-(5), as printed (with the frame fix: y along the tilt). Disk
// centre at (0, y_c, h) in R_d with y_c = -e; boundary points y0, y1 = y_c -/+ r on the y axis.
ShapeReal printed_shape_real(const Real& h, const Real& e, const Real& r) {
  const Real y_c = -e, y0 = y_c - r, y1 = y_c + r;
  const Real L0 = sqrt(y0 * y0 + h * h), L1 = sqrt(y1 * y1 + h * h);
  const Real yp0 = y0 / L0, zp0 = h / L0, yp1 = y1 / L1, zp1 = h / L1;
  const Real yph = (yp0 + yp1) / 2, zph = (zp0 + zp1) / 2;  // centre z_e ~ (0, y'_h, z'_h)
  const Real y_h = h * yph / zph;                           // z_e re-projected on the disk
  const Real dy = y_h - y_c;
  const Real x1 = sqrt(r * r - dy * dy);  // chord x0 x1 through y_h
  ShapeReal s;
  s.a = x1 / sqrt(x1 * x1 + y_h * y_h + h * h);  // eq. (4): a = x'_1
  s.b = sqrt((yp1 - yp0) * (yp1 - yp0) + (zp1 - zp0) * (zp1 - zp0)) / 2;
  s.a_t = s.a / sqrt(1 - s.a * s.a);  // tan(asin a)
  s.b_t = s.b / sqrt(1 - s.b * s.b);
  return s;
}

}  // namespace

std::filesystem::path solid_angle_table_path() {
  return std::filesystem::path(DISKLAB_REFERENCE_DIR) / "solid_angle.csv";
}

std::vector<SolidAngleRow> load_solid_angle_table() {
  std::vector<SolidAngleRow> rows;
  for (const reference::SolidAngleRow& t :
       reference::read_solid_angle_table(solid_angle_table_path())) {
    SolidAngleRow row;
    row.id = t.id;
    row.category = t.category;
    row.center = Vec3(t.center[0], t.center[1], t.center[2]);
    row.normal = Vec3(t.normal[0], t.normal[1], t.normal[2]);
    row.radius = t.radius;
    row.point = Vec3(t.point[0], t.point[1], t.point[2]);
    row.two_sided = t.two_sided;
    row.distance = t.distance;
    row.omega_text = t.omega_text;
    row.omega = t.omega;
    rows.push_back(row);
  }
  return rows;
}

SceneScalars scene_scalars(const Vec3& center, const Vec3& normal, double radius, const Vec3& o,
                           bool two_sided) {
  Real n[3], w[3], nn2 = 0;
  for (int i = 0; i < 3; ++i) {
    n[i] = normal[i];
    w[i] = Real(o[i]) - Real(center[i]);
    nn2 += n[i] * n[i];
  }
  const Real nn = sqrt(nn2);
  Real h = (w[0] * n[0] + w[1] * n[1] + w[2] * n[2]) / nn;
  const Real cx = w[1] * n[2] - w[2] * n[1], cy = w[2] * n[0] - w[0] * n[2],
             cz = w[0] * n[1] - w[1] * n[0];
  const Real e = sqrt(cx * cx + cy * cy + cz * cz) / nn;
  if (h < 0 && two_sided) h = -h;
  SceneScalars s;
  s.h = static_cast<double>(h);
  s.e = static_cast<double>(e);
  s.r = radius;
  s.visible = h > 0 && radius > 0;
  return s;
}

PrintedShape printed_shape(double h, double e, double r) {
  const ShapeReal s = printed_shape_real(Real(h), Real(e), Real(r));
  return {static_cast<double>(s.a), static_cast<double>(s.b), static_cast<double>(s.a_t),
          static_cast<double>(s.b_t)};
}

double radial_sector_reference(double h, double e, double r, double phi) {
  const ShapeReal s = printed_shape_real(Real(h), Real(e), Real(r));
  const Real a2 = s.a * s.a, b2 = s.b * s.b;
  // 1 - h_r = r^2 / (1 + sqrt(1 - r^2)), r^2 = a^2 b^2 / (a^2 sin^2 + b^2 cos^2) (eqs. 17-18).
  auto f = [&](const Real& t) -> Real {
    const Real sn = sin(t), cs = cos(t);
    const Real r2 = a2 * b2 / (a2 * sn * sn + b2 * cs * cs);
    return r2 / (1 + sqrt(1 - r2));
  };
  Real error;
  const Real value = boost::math::quadrature::gauss_kronrod<Real, 31>::integrate(
      f, Real(0), Real(phi), 25, Real(1e-30), &error);
  return static_cast<double>(value);
}

double parallel_half_sector_reference(double h, double e, double r, double phi_p) {
  const ShapeReal s = printed_shape_real(Real(h), Real(e), Real(r));
  // Eqs. (24)-(25): y = tan phi', x = a_t sqrt(1 - (y/b_t)^2), h_p = x / sqrt(x^2 + y^2 + 1).
  auto hp = [&](const Real& t) -> Real {
    const Real y = tan(t);
    const Real q = 1 - (y / s.b_t) * (y / s.b_t);
    if (!(q > 0)) return Real(0);
    const Real x = s.a_t * sqrt(q);
    return 2 * x / sqrt(x * x + y * y + 1);
  };
  const Real beta = atan(s.b_t);
  const Real upper = std::min(Real(phi_p), beta);
  if (!(upper > 0)) return 0.0;
  // Integrate over s = t / upper in [0, 1]: tanh-sinh scales its smallest abscissa offset by the
  // interval length, which underflows for the tiny beta of lights ~1e8 radii away (Boost asserts
  // on it in Debug builds). The substitution is exact.
  auto scaled = [&](const Real& s) -> Real { return upper * hp(upper * s); };
  boost::math::quadrature::tanh_sinh<Real> ts(15);
  return static_cast<double>(ts.integrate(scaled, Real(0), Real(1), Real(1e-30)));
}

}  // namespace disklab::test
