#pragma once
// Independent references for the spherical-ellipse geometry and solid-angle suites:
//  - the committed 50-digit solid-angle table (reference/solid_angle.csv);
//  - the shape (a, b) by the construction of Guillén et al. 2017, eqs. (3)-(5), step by step as
//    printed (projections of y0, y1, the centre, the chord), in cpp_bin_float_50;
//  - the radial sector Omega_r(phi) (eq. 16) and parallel half sector Omega_p^+(phi_p) (eq. 8)
//    by adaptive quadrature of their defining integrals in the azimuth, in cpp_bin_float_50.
// None of these uses the closed forms or elliptic integrals of the library.
#include <filesystem>
#include <string>
#include <vector>

#include "disklab/types.h"

namespace disklab::test {

struct SolidAngleRow {
  int id = 0;
  std::string category;
  Vec3 center, normal, point;
  double radius = 0.0;
  bool two_sided = false;
  double distance = 0.0;  // |o - c| / r
  double omega = 0.0;     // reference (rounded from 45 digits)
  std::string omega_text;
};

// Reads reference/solid_angle.csv (DISKLAB_REFERENCE_DIR). Throws std::runtime_error if the
// table is missing or malformed, so a test that uses it fails.
std::vector<SolidAngleRow> load_solid_angle_table();
std::filesystem::path solid_angle_table_path();

// Scene scalars at 50 digits from double inputs: height h above the lit face (mirrored for a
// two-sided disk; <= 0 means invisible), in-plane offset e, radius r, rounded to double on output.
struct SceneScalars {
  double h = 0.0, e = 0.0, r = 0.0;
  bool visible = false;
};
SceneScalars scene_scalars(const Vec3& center, const Vec3& normal, double radius, const Vec3& o,
                           bool two_sided);

// a and b of eqs. (3)-(5) by the printed construction, at 50 digits, from h, e, r (doubles taken
// exactly). Also returns a_t, b_t.
struct PrintedShape {
  double a = 0.0, b = 0.0, a_t = 0.0, b_t = 0.0;
};
PrintedShape printed_shape(double h, double e, double r);

// Omega_r(phi) = int_0^phi (1 - sqrt(1 - r^2(phi'))) dphi' (eqs. 16-18) with a, b from
// printed_shape, by adaptive Gauss-Kronrod in cpp_bin_float_50. phi in [0, pi/2].
double radial_sector_reference(double h, double e, double r, double phi);

// Omega_p^+(phi_p) = int_0^phi_p 2 h_p dphi' with h_p from eqs. (24)-(25) (tangent-ellipse point
// (x, tan phi', 1) projected on the sphere), by tanh-sinh in cpp_bin_float_50. phi_p in
// [0, beta].
double parallel_half_sector_reference(double h, double e, double r, double phi_p);

}  // namespace disklab::test
