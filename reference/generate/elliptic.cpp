// Reference tables of Legendre's F(phi|m) and Pi(n; phi|m) at 50 digits, computed INDEPENDENTLY
// of Carlson's algorithms: tanh-sinh quadrature (Boost.Math) of the defining integrals
//   F(phi|m)     = int_0^phi dt / sqrt(1 - m sin^2 t)
//   Pi(n; phi|m) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t))
// in boost::multiprecision::cpp_bin_float_50.
//
// Inputs are doubles (printed %.17g, so they read back exactly); where m or n is close to 1 it
// is 1 - k 2^-53 so that 1 - m, 1 - n are exact doubles too. The quadrature and how it keeps
// every digit at the singular corner: legendre_quadrature.h.
//
// Usage: reference_elliptic OUT_DIR   (writes OUT_DIR/elliptic_f.csv and elliptic_pi.csv)
// The row set is deterministic (fixed seed); see reference/README.md.
#include <algorithm>
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

#include "legendre_quadrature.h"

namespace {

using namespace disklab::reference_generate;

const double kHalfPi = 1.5707963267948966;  // fl(pi/2), below pi/2

struct Row {
  double n, phi, m;  // n unused for F
};

// m close to 1 with an exact complement: 1 - k 2^-53, k >= 1.
double one_minus_exact(double complement) {
  const double k = std::max(1.0, std::round(std::ldexp(complement, 53)));
  return 1.0 - std::ldexp(k, -53);
}

std::vector<double> hard_phis() {
  std::vector<double> v{kHalfPi, std::nextafter(kHalfPi, 0.0), 1e-300, 1e-20, 1e-8, 1e-3, 0.5, 1.0};
  for (int k = 1; k <= 15; k += 2)
    v.push_back(kHalfPi - std::pow(10.0, -k));
  return v;
}

std::vector<Row> f_rows(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<Row> rows;
  // Random over the domain.
  for (int i = 0; i < 500; ++i)
    rows.push_back({0, kHalfPi * U(rng), U(rng)});
  // m -> 1 (1 - m log-uniform down to 2^-53) at random and at hard phi.
  for (int i = 0; i < 300; ++i)
    rows.push_back({0, kHalfPi * U(rng), one_minus_exact(std::pow(2.0, -53 * U(rng)))});
  for (double phi : hard_phis())
    for (int e : {1, 4, 8, 12, 16, 20, 26, 32, 40, 46, 50, 52, 53})
      rows.push_back({0, phi, one_minus_exact(std::ldexp(1.0, -e))});
  // Small m, and tiny / near-pi/2 phi at random m.
  for (int i = 0; i < 100; ++i)
    rows.push_back({0, kHalfPi * U(rng), std::pow(10.0, -20 * U(rng))});
  for (int i = 0; i < 100; ++i)
    rows.push_back({0, std::pow(10.0, -12 * U(rng)), U(rng)});
  for (int i = 0; i < 100; ++i)
    rows.push_back({0, kHalfPi - std::pow(10.0, -16 * U(rng)), U(rng)});
  for (double phi : hard_phis())
    rows.push_back({0, phi, 0.0});
  return rows;
}

std::vector<Row> pi_rows(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<Row> rows;
  auto random_m = [&] {
    const double r = U(rng);
    if (r < 0.6) return U(rng);
    if (r < 0.9) return one_minus_exact(std::pow(2.0, -53 * U(rng)));
    return std::pow(10.0, -20 * U(rng));
  };
  auto random_phi = [&] {
    const double r = U(rng);
    if (r < 0.7) return kHalfPi * U(rng);
    if (r < 0.85) return kHalfPi - std::pow(10.0, -16 * U(rng));
    return std::pow(10.0, -12 * U(rng));
  };
  // n in (-1, 1) at random.
  for (int i = 0; i < 600; ++i)
    rows.push_back({2 * U(rng) - 1, random_phi(), random_m()});
  // Large negative n: -b_t^2 of the parallel map, b_t up to 1e8 (n down to -1e16).
  for (int i = 0; i < 700; ++i)
    rows.push_back({-std::pow(10.0, 16 * U(rng)), random_phi(), random_m()});
  // Small |n| of either sign.
  for (int i = 0; i < 200; ++i)
    rows.push_back(
        {(U(rng) < 0.5 ? -1 : 1) * std::pow(10.0, -12 * U(rng)), random_phi(), random_m()});
  // n -> 1 (1 - n exact, down to 2^-53).
  for (int i = 0; i < 500; ++i)
    rows.push_back({one_minus_exact(std::pow(2.0, -53 * U(rng))), random_phi(), random_m()});
  // Grids of hard cases.
  for (double phi : {kHalfPi, kHalfPi - 1e-9, 1e-8, 1.0})
    for (double n :
         {-1e16, -1e8, -1.0, -1e-8, 1e-8, 0.5, one_minus_exact(0x1p-20), one_minus_exact(0x1p-53)})
      for (double m : {0.0, 0.5, one_minus_exact(0x1p-20), one_minus_exact(0x1p-53)})
        rows.push_back({n, phi, m});
  for (double phi : {kHalfPi, 0.5})
    rows.push_back({0.0, phi, 0.5});
  return rows;
}

std::string header(const char* what, std::size_t count) {
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  std::ostringstream os;
  os << "# " << what << "\n"
     << "# made by: reference_elliptic (reference/generate/elliptic.cpp), " << date << "\n"
     << "# method: tanh-sinh quadrature (boost::math::quadrature::tanh_sinh, Boost "
     << BOOST_LIB_VERSION
     << ") of the defining integral in boost::multiprecision::cpp_bin_float_50;\n"
     << "#   level-to-level tolerance 1e-40 (digits double per level), interval cut at 10^-j "
        "from\n#   the integrand's narrow features (t = 0 for n << 0, t = pi/2 for m, n -> 1); no "
        "Carlson\n"
     << "# convention: F(phi|m) = int_0^phi dt/sqrt(1 - m sin^2 t); Pi(n;phi|m) = int_0^phi dt/((1 "
        "- n sin^2 t) sqrt(1 - m sin^2 t))\n"
     << "# inputs: doubles printed %.17g (exact); value: 45 significant digits; rows: " << count
     << "\n";
  return os.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::mt19937_64 rng(20261123);
  Quadrature quad;
  const auto start = std::chrono::steady_clock::now();
  {
    const auto rows = f_rows(rng);
    std::ostringstream out;
    out << header("Legendre F(phi|m), 50-digit reference", rows.size()) << "phi,m,F\n";
    for (const Row& r : rows) {
      const Real m = r.m;
      const Real F = quad.integrate(
          r.phi, [&](const Real& s, const Real& c) { return 1 / sqrt(one_minus_x_sin2(m, s, c)); },
          1.0, std::sqrt(1 - r.m));
      out << fmt17(r.phi) << "," << fmt17(r.m) << "," << fmt_real(F) << "\n";
    }
    std::ofstream(dir / "elliptic_f.csv") << out.str();
    std::fprintf(stderr, "elliptic_f.csv: %zu rows, %.1f s\n", rows.size(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  {
    const auto rows = pi_rows(rng);
    std::ostringstream out;
    out << header("Legendre Pi(n;phi|m), 50-digit reference", rows.size()) << "n,phi,m,Pi\n";
    for (const Row& r : rows) {
      const Real m = r.m, n = r.n;
      const Real P = quad.integrate(
          r.phi,
          [&](const Real& s, const Real& c) {
            return 1 / (one_minus_x_sin2(n, s, c) * sqrt(one_minus_x_sin2(m, s, c)));
          },
          r.n < 0 ? 1 / std::sqrt(-r.n) : 1.0,
          std::sqrt(std::min(1 - r.m, r.n > 0 ? 1 - r.n : 1.0)));
      out << fmt17(r.n) << "," << fmt17(r.phi) << "," << fmt17(r.m) << "," << fmt_real(P) << "\n";
    }
    std::ofstream(dir / "elliptic_pi.csv") << out.str();
    std::fprintf(stderr, "elliptic_pi.csv: %zu rows, %.1f s\n", rows.size(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return 0;
}
