#pragma once
// Legendre's integrals at 50 digits by tanh-sinh quadrature of their defining integrands, shared
// by the reference generators (elliptic.cpp, boost_ellint_f.cpp). Independent of Carlson's
// algorithms, which the tables test. The integrand is evaluated with t and pi/2 - t both known to
// full precision (tanh-sinh hands over the distance to the nearest endpoint; pi/2 - phi comes
// from a 100-digit pi), so 1 - m sin^2 t = (1 - m) + m cos^2 t keeps every digit near the
// m -> 1, phi -> pi/2 singularity.
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace disklab::reference_generate {

using Real = boost::multiprecision::cpp_bin_float_50;
using Wide = boost::multiprecision::cpp_bin_float_100;

// Tanh-sinh roughly doubles the number of correct digits per level, so when two levels agree
// to 1e-40 the last one is good to far beyond the 45 digits written. The run aborts rather than
// write a row whose level-to-level difference is above kMaxEstimate.
inline const Real kTolerance = Real(1e-40);
inline const Real kMaxEstimate = Real(1e-36);

// 1 - X sin^2 t, accurate both for X far from 1 and for X -> 1 with t -> pi/2.
inline Real one_minus_x_sin2(const Real& X, const Real& s, const Real& c) {
  if (X > 0.5) return (1 - X) + X * c * c;
  return 1 - X * s * s;
}

struct Quadrature {
  boost::math::quadrature::tanh_sinh<Real> ts{20};

  // int_0^phi g(s, c) dt, s = sin t, c = cos t, for a double phi in [0, pi/2].
  template <class G>
  Real integrate(double phi_d, G g, double w_left, double w_right) {
    const Real delta = Real(boost::math::constants::half_pi<Wide>() - Wide(phi_d));  // pi/2 - phi
    return integrate(Real(phi_d), delta, g, w_left, w_right);
  }

  // The same for phi in [0, pi/2] given with delta = pi/2 - phi, both to working precision.
  // `w_left` and `w_right` are the widths of the integrand's features at t = 0 (large negative
  // n: 1/sqrt(-n)) and at t = pi/2 (m or n -> 1: sqrt(1 - m), sqrt(1 - n)). Tanh-sinh can declare
  // convergence before it resolves a feature many decades narrower than the interval, so the
  // interval is cut at distances 10^-j from the feature's end, down to a tenth of its width:
  // every piece is then smooth on its scale.
  template <class G>
  Real integrate(const Real& phi, const Real& delta, G g, double w_left, double w_right) {
    // Breakpoints as (t, u = pi/2 - t), both exact to working precision.
    std::vector<std::pair<Real, Real>> cuts{{Real(0), delta + phi}};
    for (double d = 0.1; d > w_left / 10 && d > 1e-300; d /= 10)
      if (Real(d) < phi / 2) cuts.push_back({Real(d), delta + (phi - Real(d))});
    for (double d = 0.1; d > w_right / 10 && d > 1e-300; d /= 10)
      if (Real(d) > delta && Real(d) - delta < 0.5 * phi)
        cuts.push_back({phi - (Real(d) - delta), Real(d)});
    cuts.push_back({phi, delta});
    std::sort(cuts.begin(), cuts.end());
    Real total = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const auto [ta, ua] = cuts[i];
      const auto [tb, ub] = cuts[i + 1];
      const Real L = tb - ta;
      if (!(L > 0)) continue;
      // v in [0, 1]; vc is the signed distance from v to the nearest end (a - v or b - v).
      // The bindings are captured by name: clang rejects structured bindings in a [&] capture.
      auto f = [&, ta = ta, ua = ua, tb = tb, ub = ub](const Real& v, const Real& vc) {
        if (v < 0.5) return L * g(sin(ta + L * abs(vc)), sin(ua - L * abs(vc)));
        return L * g(sin(tb - L * abs(vc)), sin(ub + L * abs(vc)));
      };
      Real error = 0;
      const Real q = ts.integrate(f, Real(0), Real(1), kTolerance, &error);
      if (!(error <= kMaxEstimate * abs(q))) {
        std::ostringstream os;
        os << "quadrature did not converge: phi=" << phi << " piece " << i
           << " rel.err=" << error / abs(q);
        throw std::runtime_error(os.str());
      }
      total += q;
    }
    return total;
  }

  // F(phi|m) for phi in [0, pi/2] given with delta = pi/2 - phi.
  Real legendre_f(const Real& phi, const Real& delta, double m) {
    const Real M = m;
    return integrate(
        phi, delta,
        [&](const Real& s, const Real& c) { return 1 / sqrt(one_minus_x_sin2(M, s, c)); }, 1.0,
        std::sqrt(1 - m));
  }
};

inline std::string fmt17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

inline std::string fmt_real(const Real& v) {
  std::ostringstream os;
  os << std::setprecision(45) << std::scientific << v;
  return os.str();
}

}  // namespace disklab::reference_generate
