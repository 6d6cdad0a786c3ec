// Reference table of the projected solid angle P = int max(0, w . n_o) dw of a disk seen from a
// point with receiver normal n_o, at 50 digits, computed WITHOUT ellipse/projected.h: the chord
// quadrature of projected_quadrature.h (closed-form chords, tanh-sinh over the disk in
// cpp_bin_float_50, split at the receiver's horizon line and around the foot of the point).
//
// Rows (every input a double printed with %.17g, so it reads back exactly):
//  on_axis      coaxial disk and receiver, 1e-6 .. 1e8 radii; also checked against the closed
//               form pi r^2 / (d^2 + r^2) to 1e-40;
//  far          tilted disk, 10 .. 1e8 radii, three view tilts, receivers 0.3, 1.2, 1.5 rad off
//               the disk's direction (the last straddles at 10 radii);
//  near         1e-6 .. 1e-1 radii below interior points, receiver facing the disk's plane;
//  near_tilted  the same with a tilted receiver whose horizon cuts the disk;
//  suite        the configurations of property_tests/ellipse/projected_test.cpp;
//  straddle     overhead disk, receiver tilted so its horizon cuts the disk (or passes through
//               the centre, or leaves only a sliver above);
//  straddle_far vertical disk straddling the horizon at 2 .. 1e6 radii (centre 0.5 r above, on,
//               0.5 r below), a tilted disk at 10 .. 1e5 radii, and an overhead disk at 10 .. 1e8
//               radii with the horizon halfway between its centre and its rim;
//  grazing      the point nearly in the disk's plane (h/e down to 1e-3), receiver facing it;
//  scaled       r = 1e-3 and 1e3 copies, unclipped and straddling;
//  random       fixed seed: random disks, points, receivers (points closer than 0.05 r to the rim
//               redrawn, and receivers that see nothing of the disk);
//  degenerate   behind a one-sided disk, wholly below the horizon: P = 0 exactly.
//
// Usage: reference_projected OUT_DIR   (writes OUT_DIR/projected_P.csv)
#include <array>
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

#include "projected_quadrature.h"

namespace {

using disklab::reference_generate::ProjectedQuadrature;
using Real = ProjectedQuadrature::Real;
using V3 = std::array<double, 3>;

// tanh-sinh's level-to-level stop (see projected_quadrature.h) and the largest relative error
// estimate a written row may carry: 45 digits are printed, at least 32 are claimed.
const Real kTolerance = Real(1e-40);
const Real kMaxRelativeError = Real(1e-32);

struct Row {
  std::string category;
  V3 c, n, o, no;
  double r;
  bool two_sided;
};

std::string fmt17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

double norm(const V3& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}
V3 unit(const V3& v) {
  const double l = norm(v);
  return {v[0] / l, v[1] / l, v[2] / l};
}
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const V3& a, const V3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Point at distance d from c along a direction making angle `tilt` with n (as in
// solid_angle.cpp; formed in double: the point IS the input).
V3 along(const V3& c, const V3& n, double d, double tilt) {
  const V3 u = unit(n);
  const V3 t = unit(std::abs(u[0]) < 0.9 ? V3{0, u[2], -u[1]} : V3{-u[2], 0, u[0]});
  V3 o;
  for (int i = 0; i < 3; ++i)
    o[i] = c[i] + d * (std::cos(tilt) * u[i] + std::sin(tilt) * t[i]);
  return o;
}

// A receiver normal `g` radians off the direction from o to c (towards a fixed side).
V3 receiver_towards(const V3& o, const V3& c, double g) {
  const V3 dir = unit({c[0] - o[0], c[1] - o[1], c[2] - o[2]});
  const V3 perp = unit(cross(dir, {0.36, 0.48, 0.8}));
  return {std::cos(g) * dir[0] + std::sin(g) * perp[0],
          std::cos(g) * dir[1] + std::sin(g) * perp[1],
          std::cos(g) * dir[2] + std::sin(g) * perp[2]};
}

std::vector<Row> make_rows() {
  std::vector<Row> rows;
  auto add = [&](std::string cat, V3 c, V3 n, double r, V3 o, V3 no, bool two_sided = false) {
    rows.push_back(Row{std::move(cat), c, n, o, no, r, two_sided});
  };
  const V3 z0{0, 0, 0}, ez{0, 0, 1}, mz{0, 0, -1};
  for (double d : {1e-6, 1e-4, 1e-2, 0.25, 0.5, 1.0, 2.0, 10.0, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8})
    add("on_axis", z0, ez, 1.0, {0, 0, d}, mz);
  const V3 c1{1.5, -2.0, 0.25}, n1{2.0, -1.0, 2.0};
  int k = 0;
  for (double d : {10.0, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8})
    for (double tilt : {0.1, 0.8, 1.4}) {
      const V3 o = along(c1, n1, d, tilt);
      const double g = std::array<double, 3>{0.3, 1.2, 1.5}[k++ % 3];
      add("far", c1, n1, 1.0, o, receiver_towards(o, c1, g));
    }
  for (double h : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1})
    for (double e : {0.0, 0.3, 0.7})
      add("near", {0, 0, h}, mz, 1.0, {e, 0, 0}, ez);
  for (double h : {1e-6, 1e-4, 1e-2})
    for (double e : {0.0, 0.5})
      add("near_tilted", {0, 0, h}, mz, 1.0, {e, 0, 0}, {0.3, 0.2, 1.0});
  // projected_test.cpp's configurations (normals as the test normalizes them, in double).
  const V3 tilt_n = unit({0.3, 0.2, 1.0}), far_n = unit({0.3, -0.2, -1}),
           far_no = unit({0.1, 0.2, 1});
  add("suite", {0, 0, 2}, mz, 1.0, z0, ez);
  add("suite", {0, 0, 2}, mz, 1.0, {1.5, 0.3, 0}, ez);
  add("suite", {0, 0, 0.6}, {1, 0, 0}, 0.5, {0.3, 0.1, 0}, ez, true);
  add("suite", {0, 0, 1e-6}, mz, 1.0, {0.3, 0.2, 0}, tilt_n);
  add("suite", {3e3, 2e3, 1e4}, far_n, 1.0, z0, far_no);
  add("suite", {3e7, 2e7, 1e8}, far_n, 1.0, z0, far_no);
  add("suite", {0, 0, 0.3}, {1, 0, 0}, 0.5, {0.3, 0.1, 0}, ez, true);
  add("suite", {0, 0, 0}, {1, 0, 0}, 0.5, {0.5, 0.1, 0}, ez, true);
  add("suite", {0, 0, -0.3}, {1, 0, 0}, 0.5, {0.3, 0.1, 0}, ez, true);
  add("suite", {0, 0, 0.1}, unit({0.3, 0.2, 1}), 0.5, {0.2, 0.1, 0.5}, unit({0.3, 1, 0.2}), true);
  add("suite", {0, 0, 0.2}, unit({1, 0, 1}), 1.0, {20, 3, 0}, ez, true);
  // Overhead disk (angular radius atan(1/2) = 0.46 rad), the receiver tilted by g: its horizon
  // is pi/2 - g from the zenith.
  for (double g : {1.2, 1.4, 1.5707963267948966, 1.9})
    add("straddle", {0, 0, 2}, mz, 1.0, z0, {std::sin(g), 0, std::cos(g)});
  for (double D : {2.0, 10.0, 1e2, 1e4, 1e6})
    for (double z : {0.5, 0.0, -0.5})
      add("straddle_far", {D, 0, z}, {-1, 0, 0}, 1.0, z0, ez);
  for (double D : {10.0, 1e3, 1e5})
    add("straddle_far", {0.6 * D, 0.8 * D, 0.3}, {-0.6, -0.8, 0.5}, 1.0, z0, {0.8, -0.6, 0.5});
  for (double D : {10.0, 1e3, 1e5, 1e8}) {
    const double g = 1.5707963267948966 - 0.5 / D;  // horizon 0.5 r from the centre
    add("straddle_far", {0, 0, D}, mz, 1.0, z0, {std::sin(g), 0, std::cos(g)});
  }
  for (double e : {2.0, 10.0, 100.0})
    for (double ratio : {1e-1, 1e-2, 1e-3})
      add("grazing", z0, ez, 1.0, {e, 0, e * ratio}, {-1, 0, -ratio});
  for (double s : {1e-3, 1e3}) {
    add("scaled", {0, 0, 2 * s}, mz, s, {0.3 * s, 0, 0}, ez);
    add("scaled", {0, 0, 2 * s}, mz, s, {0.3 * s, 0, 0}, {1.0, 0, 0.25});
  }
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  int made = 0;
  while (made < 30) {
    const V3 c{5 * U(rng), 5 * U(rng), 5 * U(rng)};
    const V3 n{U(rng), U(rng), U(rng)};
    const double r = std::exp2(3.0 * U(rng));
    const V3 o{10 * U(rng), 10 * U(rng), 10 * U(rng)};
    const V3 no{U(rng), U(rng), U(rng)};
    const bool two_sided = made % 2 == 1;
    if (norm(n) < 0.1 || norm(no) < 0.1) continue;
    const V3 w{o[0] - c[0], o[1] - c[1], o[2] - c[2]};
    const double h = dot(w, n) / norm(n);
    const double e = std::sqrt(std::max(0.0, dot(w, w) - h * h));
    if (std::hypot(h, e - r) < 0.05 * r) continue;  // near the rim: nearly singular
    if (!(h > 0) && !two_sided) continue;
    // Something of the disk above the receiver's horizon (rim points or the centre).
    const V3 t1 = unit(cross(n, std::abs(n[0]) < 0.9 * norm(n) ? V3{1, 0, 0} : V3{0, 1, 0}));
    const V3 t2 = unit(cross(n, t1));
    bool above = dot({c[0] - o[0], c[1] - o[1], c[2] - o[2]}, no) > 0;
    for (int j = 0; j < 64 && !above; ++j) {
      const double phi = 2 * M_PI * j / 64;
      V3 x;
      for (int i = 0; i < 3; ++i)
        x[i] = c[i] + r * (std::cos(phi) * t1[i] + std::sin(phi) * t2[i]) - o[i];
      above = dot(x, no) > 0;
    }
    if (!above) continue;
    add("random", c, n, r, o, no, two_sided);
    ++made;
  }
  add("degenerate", {0, 0, 2}, ez, 1.0, z0, ez);         // behind a one-sided disk
  add("degenerate", {0, 0, -2}, ez, 1.0, z0, ez, true);  // wholly below the horizon
  return rows;
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
  long total_pieces = 0;
  Real worst_error = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& row = rows[i];
    const ProjectedQuadrature q = disklab::reference_generate::projected_solid_angle_quadrature(
        row.c.data(), row.n.data(), row.r, row.two_sided, row.o.data(), row.no.data(), kTolerance);
    const Real rel_error = q.value > 0 ? q.error / q.value : Real(0);
    if (rel_error > kMaxRelativeError) {
      std::fprintf(stderr, "row %zu (%s): quadrature error estimate %s relative\n", i,
                   row.category.c_str(), rel_error.str(3).c_str());
      return 1;
    }
    if (row.category == "degenerate" ? q.value != 0 : !(q.value > 0)) {
      std::fprintf(stderr, "row %zu (%s): P = %s\n", i, row.category.c_str(),
                   q.value.str(5).c_str());
      return 1;
    }
    if (row.category == "on_axis") {
      const Real d = row.o[2], r = row.r;
      const Real closed = boost::math::constants::pi<Real>() * r * r / (d * d + r * r);
      if (abs(closed / q.value - 1) > Real(1e-40)) {
        std::fprintf(stderr, "row %zu: on-axis closed form disagrees\n", i);
        return 1;
      }
    }
    if (rel_error > worst_error) worst_error = rel_error;
    total_pieces += q.pieces;
    const V3 w{row.o[0] - row.c[0], row.o[1] - row.c[1], row.o[2] - row.c[2]};
    body << i << ',' << row.category;
    for (const V3* v : {&row.c, &row.n})
      for (double x : *v)
        body << ',' << fmt17(x);
    body << ',' << fmt17(row.r);
    for (const V3* v : {&row.o, &row.no})
      for (double x : *v)
        body << ',' << fmt17(x);
    char err[32];
    std::snprintf(err, sizeof err, "%.1e", static_cast<double>(rel_error));
    body << ',' << (row.two_sided ? 1 : 0) << ',' << fmt17(norm(w) / row.r) << ','
         << (q.straddles ? 1 : 0) << ',' << q.value.str(45, std::ios_base::scientific) << ',' << err
         << ',' << q.pieces << '\n';
    std::fprintf(stderr, "\r%zu/%zu", i + 1, rows.size());
  }
  std::fprintf(stderr, "\n");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  char worst[32];
  std::snprintf(worst, sizeof worst, "%.1e", static_cast<double>(worst_error));
  std::ostringstream out;
  out << "# disklab reference: projected solid angle P = int max(0, w . n_o) dw of a disk, 45 "
         "significant digits\n"
      << "# generator: reference/generate/projected.cpp (bin/reference_projected), " << date << ", "
      << rows.size() << " rows, " << total_pieces << " tanh-sinh intervals in total, "
      << static_cast<int>(seconds) << " s\n"
      << "# method: generate/projected_quadrature.h in cpp_bin_float_50, no ellipse formula: "
         "closed-form chords of the disk clipped at the receiver's horizon line, tanh-sinh over "
         "the chord position to 1e-40 level-to-level; quad_error = the summed tanh-sinh error "
         "estimate / P (worst "
      << worst
      << ", at most 1e-32 written); on_axis rows also match pi r^2 / (d^2 + r^2) to "
         "1e-40\n"
      << "# inputs: doubles printed %.17g (exact); normals need not be unit; the lit face is "
         "+normal; two_sided=1 lights both faces; r* is the receiver normal; P=0 where nothing "
         "is visible above the receiver's horizon\n"
      << "# distance = |o - c| / r (rounded, informative only); straddles=1 where the receiver's "
         "horizon plane cuts the disk (computed in 50 digits)\n"
      << "id,category,cx,cy,cz,nx,ny,nz,radius,ox,oy,oz,rx,ry,rz,two_sided,distance,straddles,P,"
         "quad_error,intervals\n"
      << body.str();
  std::filesystem::create_directories(dir);
  const auto target = dir / "projected_P.csv";
  const auto temp = dir / ".projected_P.csv.tmp";
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
