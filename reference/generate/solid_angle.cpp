// Reference table of disk solid angles at 50 digits, computed WITHOUT the spherical-ellipse
// formulas: the boundary (wedge) quadrature of disklab::ellipse::solid_angle_boundary_quadrature
// (Van Oosterom-Strackee wedges, trapezoidal rule on the periodic integrand, doubled until two
// estimates agree to 1e-42) run in boost::multiprecision::cpp_bin_float_50. The only inputs it
// takes are the height h of the point above the disk plane, its in-plane offset e and the radius
// r, formed at 50 digits from the double inputs (h = (o - c).n/|n|, e = |(o - c) x n|/|n|).
//
// Rows: on-axis (also checked against the closed form 2 pi (1 - d/sqrt(d^2 + r^2)) at 50 digits),
// far (10 .. 1e8 radii, several tilts), near (1e-6 .. 1e-1 radii above interior points), grazing
// (h/e down to 1e-3), scaled copies (r = 1e-3, 1e3), two-sided from behind, degenerate (behind a
// one-sided disk, in the plane: exactly 0) and random configurations (fixed seed; points closer
// than 0.05 r to the rim are redrawn, since there the integrand is nearly singular).
// Every input is a double printed with %.17g (reads back exactly).
//
// Usage: reference_solid_angle OUT_DIR   (writes OUT_DIR/solid_angle.csv)
#include <array>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "disklab/ellipse/solid_angle.h"

namespace {

using Real = boost::multiprecision::cpp_bin_float_50;

// Level-to-level agreement of the trapezoidal rule. Its error falls geometrically, so the finer
// estimate is far better than the change; 1e-42 leaves margin above the 45 digits written.
const Real kTolerance = Real(1e-42);
constexpr int kMaxLog2Intervals = 21;

struct Row {
  std::string category;
  double c[3], n[3], r, o[3];
  bool two_sided;
};

std::string fmt17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

Row make_row(std::string category, std::array<double, 3> c, std::array<double, 3> n, double r,
             std::array<double, 3> o, bool two_sided = false) {
  Row row;
  row.category = std::move(category);
  for (int i = 0; i < 3; ++i) {
    row.c[i] = c[i];
    row.n[i] = n[i];
    row.o[i] = o[i];
  }
  row.r = r;
  row.two_sided = two_sided;
  return row;
}

// Point at distance d from c along a direction making angle `tilt` (radians) with n, in the
// plane spanned by n and a fixed in-plane vector (all in double: the point IS the input).
std::array<double, 3> along(const std::array<double, 3>& c, const std::array<double, 3>& n,
                            double d, double tilt) {
  const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  double u[3] = {n[0] / nn, n[1] / nn, n[2] / nn};
  // In-plane unit vector: cross(u, ex) or cross(u, ey).
  double t[3];
  if (std::abs(u[0]) < 0.9) {
    t[0] = 0;
    t[1] = u[2];
    t[2] = -u[1];
  } else {
    t[0] = -u[2];
    t[1] = 0;
    t[2] = u[0];
  }
  const double tn = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  std::array<double, 3> o;
  for (int i = 0; i < 3; ++i)
    o[i] = c[i] + d * (std::cos(tilt) * u[i] + std::sin(tilt) * t[i] / tn);
  return o;
}

std::vector<Row> make_rows() {
  std::vector<Row> rows;
  const std::array<double, 3> z0{0, 0, 0}, ez{0, 0, 1};
  // On axis of the canonical disk: exact axis, closed form available.
  for (double d : {1e-6, 1e-4, 1e-2, 0.25, 0.5, 1.0, 2.0, 10.0, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8})
    rows.push_back(make_row("on_axis", z0, ez, 1.0, {0, 0, d}));
  // Tilted disk away from the origin, far away, at several tilts (angle from the normal).
  const std::array<double, 3> c1{1.5, -2.0, 0.25}, n1{2.0, -1.0, 2.0};
  for (double d : {10.0, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8})
    for (double tilt : {0.1, 0.8, 1.4})
      rows.push_back(make_row("far", c1, n1, 1.0, along(c1, n1, d, tilt)));
  // Near: small heights above interior points of the canonical and of the tilted disk.
  for (double h : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1})
    for (double e : {0.0, 0.3, 0.7})
      rows.push_back(make_row("near", z0, ez, 1.0, {e, 0.0, h}));
  for (double h : {1e-6, 1e-4, 1e-2}) {
    // o = c1 + 0.4 * (in-plane) + h * n1/|n1|, formed in double.
    const double nn = 3.0;  // |(2,-1,2)|
    const std::array<double, 3> o{c1[0] + 0.4 * 1.0 / std::sqrt(5.0) + h * n1[0] / nn,
                                  c1[1] + 0.4 * 2.0 / std::sqrt(5.0) + h * n1[1] / nn,
                                  c1[2] + h * n1[2] / nn};
    rows.push_back(make_row("near", c1, n1, 1.0, o));
  }
  // Grazing: far out in the plane, slightly above it.
  for (double e : {2.0, 10.0, 100.0})
    for (double ratio : {1e-1, 1e-2, 1e-3})
      rows.push_back(make_row("grazing", z0, ez, 1.0, {e, 0.0, e * ratio}));
  // Scaled scenes (the same shapes with r = 1e-3 and r = 1e3).
  for (double s : {1e-3, 1e3}) {
    rows.push_back(make_row("scaled", z0, ez, s, {0.3 * s, 0.0, 2.0 * s}));
    rows.push_back(make_row("scaled", z0, ez, s, {5.0 * s, 1.0 * s, 1e4 * s}));
  }
  // Two-sided from behind (positive), one-sided from behind and in-plane (zero).
  rows.push_back(make_row("two_sided", c1, n1, 1.0, along(c1, n1, -3.0, 0.5), true));
  rows.push_back(make_row("two_sided", z0, ez, 2.0, {0.5, 0.25, -1.0}, true));
  rows.push_back(make_row("degenerate", c1, n1, 1.0, along(c1, n1, -3.0, 0.5)));
  rows.push_back(make_row("degenerate", z0, ez, 1.0, {3.0, 0.0, 0.0}));
  rows.push_back(make_row("degenerate", z0, ez, 1.0, {0.5, 0.0, 0.0}, true));
  // Random configurations.
  std::mt19937_64 rng(20171123);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  int made = 0;
  while (made < 40) {
    const std::array<double, 3> c{5 * U(rng), 5 * U(rng), 5 * U(rng)};
    const std::array<double, 3> n{U(rng), U(rng), U(rng)};
    const double r = std::exp2(3.0 * U(rng));
    const std::array<double, 3> o{10 * U(rng), 10 * U(rng), 10 * U(rng)};
    const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (nn < 0.1) continue;
    double w[3] = {o[0] - c[0], o[1] - c[1], o[2] - c[2]};
    const double h = (w[0] * n[0] + w[1] * n[1] + w[2] * n[2]) / nn;
    const double d2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    const double e = std::sqrt(std::max(0.0, d2 - h * h));
    // Distance from o to the rim circle: sqrt(h^2 + (e - r)^2).
    if (std::hypot(h, e - r) < 0.05 * r) continue;
    rows.push_back(make_row("random", c, n, r, o, (made % 2) == 1));
    ++made;
  }
  return rows;
}

struct Scene {
  Real h, e, r;
  bool visible;
};

Scene scene_of(const Row& row) {
  Real n[3], w[3];
  Real nn2 = 0;
  for (int i = 0; i < 3; ++i) {
    n[i] = row.n[i];
    w[i] = Real(row.o[i]) - Real(row.c[i]);
    nn2 += n[i] * n[i];
  }
  const Real nn = sqrt(nn2);
  Real h = (w[0] * n[0] + w[1] * n[1] + w[2] * n[2]) / nn;
  const Real cx = (w[1] * n[2] - w[2] * n[1]) / nn, cy = (w[2] * n[0] - w[0] * n[2]) / nn,
             cz = (w[0] * n[1] - w[1] * n[0]) / nn;
  Scene s{h, sqrt(cx * cx + cy * cy + cz * cz), Real(row.r), true};
  if (s.h < 0 && row.two_sided) s.h = -s.h;
  if (!(s.h > 0) || !(s.r > 0)) s.visible = false;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Row> rows = make_rows();
  std::ostringstream body;
  long total_intervals = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& row = rows[i];
    const Scene s = scene_of(row);
    Real omega = 0;
    long intervals = 0;
    if (s.visible) {
      const auto q = disklab::ellipse::solid_angle_boundary_quadrature<Real>(
          s.h, s.e, s.r, kTolerance, kMaxLog2Intervals);
      if (!q.converged) {
        std::fprintf(stderr, "row %zu (%s): quadrature did not converge (change %s)\n", i,
                     row.category.c_str(), q.change.str(5).c_str());
        return 1;
      }
      omega = q.value;
      intervals = q.intervals;
      if (row.category == "on_axis") {
        const Real L = sqrt(s.h * s.h + s.r * s.r);
        const Real pi = boost::multiprecision::atan(Real(1)) * 4;
        const Real closed = 2 * pi * s.r * s.r / (L * (s.h + L));
        if (abs(closed / omega - 1) > Real(1e-40)) {
          std::fprintf(stderr, "row %zu: on-axis closed form disagrees\n", i);
          return 1;
        }
      }
    }
    total_intervals += intervals;
    const Real dist = sqrt(s.h * s.h + s.e * s.e) / s.r;
    body << i << ',' << row.category;
    for (double v : row.c)
      body << ',' << fmt17(v);
    for (double v : row.n)
      body << ',' << fmt17(v);
    body << ',' << fmt17(row.r);
    for (double v : row.o)
      body << ',' << fmt17(v);
    body << ',' << (row.two_sided ? 1 : 0) << ',' << fmt17(static_cast<double>(dist)) << ','
         << omega.str(45, std::ios_base::scientific) << ',' << intervals << '\n';
    std::fprintf(stderr, "\r%zu/%zu", i + 1, rows.size());
  }
  std::fprintf(stderr, "\n");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream out;
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  out << "# disklab reference: solid angle of a disk seen from a point, 45 significant digits\n"
      << "# generator: reference/generate/solid_angle.cpp (bin/reference_solid_angle), " << date
      << ", " << rows.size() << " rows, " << total_intervals << " trapezoid intervals in total, "
      << static_cast<int>(seconds) << " s\n"
      << "# method: boundary (wedge) quadrature in cpp_bin_float_50, no ellipse formula; "
         "trapezoid doubled until two levels agree to 1e-42 relative; on_axis rows also match "
         "the closed form to 1e-40\n"
      << "# inputs: doubles printed %.17g (exact); normal need not be unit; the lit face is "
         "+normal; two_sided=1 lights both faces; omega=0 where the point sees nothing\n"
      << "# distance = |o - c| / r (rounded, informative only)\n"
      << "id,category,cx,cy,cz,nx,ny,nz,radius,ox,oy,oz,two_sided,distance,omega,intervals\n"
      << body.str();
  std::filesystem::create_directories(dir);
  const auto target = dir / "solid_angle.csv";
  const auto temp = dir / ".solid_angle.csv.tmp";
  {
    std::ofstream f(temp, std::ios::binary);
    f << out.str();
    if (!f) {
      std::fprintf(stderr, "cannot write %s\n", temp.c_str());
      return 1;
    }
  }
  std::filesystem::rename(temp, target);
  std::fprintf(stderr, "wrote %s (%zu rows, %.1f s)\n", target.c_str(), rows.size(), seconds);
  return 0;
}
