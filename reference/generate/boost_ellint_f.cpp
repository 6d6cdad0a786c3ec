// Reference table of Legendre's F(phi|m) at 50 digits at the INPUTS of Boost.Math's own test
// table for ellint_1 (boostorg/math, test/ellint_f_data.ipp: rows of phi, k, value). Only the
// two input columns are read; Boost's values are not used. The values are ours, by the
// quadrature of legendre_quadrature.h (independent of Carlson's algorithms, which they test).
//
// Inputs: phi as given (every one is an exact double; checked). m = k^2 is formed in 50 digits
// from the decimal k and rounded to the nearest double, which is the input F is evaluated at
// (checked to be the nearest; the header says how many rows have k^2 exact).
//
// Most phi exceed pi/2 (the table reaches ~1200). They are reduced in 100 digits, phi = j pi + r
// with |r| <= pi/2, and F(phi|m) = 2j K(m) + sign(r) F(|r| | m): the integrand is even and
// pi-periodic, and K(m) = F(pi/2|m). K and F(|r|) are both quadratures at 50 digits.
//
// Usage: reference_boost_ellint_f ELLINT_F_DATA_IPP OUT_DIR "PROVENANCE"
//   writes OUT_DIR/elliptic_f_boost_inputs.csv; PROVENANCE (where the .ipp came from: repository,
//   commit, path) goes into the file header verbatim. See reference/README.md.
#include <boost/math/special_functions/round.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "legendre_quadrature.h"

namespace {

using namespace disklab::reference_generate;

struct Input {
  std::string phi_text, k_text;  // as written in the .ipp
  double phi, m;
  bool m_exact;  // k^2 is a double
};

// The arguments of SC_(...) on one line of the .ipp, in order.
std::vector<std::string> sc_arguments(const std::string& line) {
  std::vector<std::string> out;
  for (std::size_t pos = line.find("SC_("); pos != std::string::npos;
       pos = line.find("SC_(", pos)) {
    const std::size_t start = pos + 4, end = line.find(')', start);
    if (end == std::string::npos) break;
    std::string arg = line.substr(start, end - start);
    arg.erase(0, arg.find_first_not_of(' '));
    arg.erase(arg.find_last_not_of(' ') + 1);
    out.push_back(arg);
    pos = end;
  }
  return out;
}

// The double nearest to x (checked against both neighbours: the conversion's rounding mode is
// not relied on).
double nearest_double(const Real& x) {
  const double d = x.convert_to<double>();
  const Real e = abs(Real(d) - x);
  for (const double nb : {std::nextafter(d, -INFINITY), std::nextafter(d, INFINITY)})
    if (abs(Real(nb) - x) < e) throw std::runtime_error("conversion did not round to nearest");
  return d;
}

std::vector<Input> read_inputs(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::vector<Input> rows;
  std::string line;
  while (std::getline(in, line)) {
    const auto args = sc_arguments(line);
    if (args.empty()) continue;
    if (args.size() != 3) throw std::runtime_error("row without three values: " + line);
    Input r{args[0], args[1], 0, 0, false};
    const Real phi50(r.phi_text), k50(r.k_text);
    r.phi = nearest_double(phi50);
    if (Real(r.phi) != phi50) throw std::runtime_error("phi is not a double: " + r.phi_text);
    const Real m50 = k50 * k50;
    r.m = nearest_double(m50);
    r.m_exact = Real(r.m) == m50;
    if (!(r.phi >= 0 && r.m >= 0 && r.m < 1))
      throw std::runtime_error("input outside phi >= 0, 0 <= m < 1: " + line);
    rows.push_back(r);
  }
  if (rows.empty()) throw std::runtime_error("no rows in " + path.string());
  return rows;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s ELLINT_F_DATA_IPP OUT_DIR PROVENANCE\n", argv[0]);
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Input> rows = read_inputs(argv[1]);
  const Wide pi = boost::math::constants::pi<Wide>(), half_pi = pi / 2;
  Quadrature quad;
  std::map<double, Real> K;  // K(m) per distinct m
  std::size_t exact = 0, reduced = 0;
  std::ostringstream body;
  for (const Input& r : rows) {
    exact += r.m_exact;
    const Wide phi = r.phi;
    const Wide j = boost::math::round(phi / pi);
    const Wide rem = phi - j * pi, rabs = abs(rem);
    Real F = quad.legendre_f(Real(rabs), Real(half_pi - rabs), r.m);
    if (rem < 0) F = -F;
    if (j != 0) {
      ++reduced;
      auto it = K.find(r.m);
      if (it == K.end()) it = K.emplace(r.m, quad.legendre_f(Real(half_pi), Real(0), r.m)).first;
      F += 2 * Real(j) * it->second;
    }
    body << fmt17(r.phi) << "," << fmt17(r.m) << "," << fmt_real(F) << "\n";
  }
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  std::ostringstream out;
  out << "# Legendre F(phi|m), 50-digit reference at the inputs of Boost.Math's ellint_1 test "
         "table\n"
      << "# inputs from: " << argv[3] << "; its (phi, k) columns only, its values unused\n"
      << "# m = k^2 formed in 50 digits from the decimal k, rounded to the nearest double ("
      << exact << " of " << rows.size() << " rows exact: k has 24 bits); phi as given (exact)\n"
      << "# made by: reference_boost_ellint_f (reference/generate/boost_ellint_f.cpp), " << date
      << "\n"
      << "# method: phi = j pi + r, |r| <= pi/2, reduced in 100 digits (" << reduced
      << " rows have j != 0); F = 2j K(m) + sign(r) F(|r| |m),\n"
      << "#   K and F(|r|) by tanh-sinh quadrature (boost::math::quadrature::tanh_sinh, Boost "
      << BOOST_LIB_VERSION << ") of the defining integral\n"
      << "#   in boost::multiprecision::cpp_bin_float_50, level-to-level tolerance 1e-40; no "
         "Carlson\n"
      << "# convention: F(phi|m) = int_0^phi dt/sqrt(1 - m sin^2 t) (Boost's ellint_1 takes k = "
         "sqrt(m))\n"
      << "# inputs: doubles printed %.17g (exact); value: 45 significant digits; rows: "
      << rows.size() << " (in the order of the source table)\n"
      << "phi,m,F\n"
      << body.str();
  const std::filesystem::path file = std::filesystem::path(argv[2]) / "elliptic_f_boost_inputs.csv";
  std::ofstream file_out(file);
  file_out << out.str();
  if (!file_out.flush()) {
    std::fprintf(stderr, "cannot write %s\n", file.c_str());
    return 1;
  }
  std::fprintf(stderr, "%s: %zu rows, %.1f s\n", file.c_str(), rows.size(),
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return 0;
}
