#pragma once
// The elliptic integrals' domain (m in [0, 1), n < 1, phi in [0, pi/2]) and its hard corners, as
// maps of a uniform u in [0, 1). Shared by the rapidcheck generators (elliptic_property_test.cpp)
// and the deterministic 50-digit sweep (elliptic_reference_test.cpp).
#include <algorithm>
#include <cmath>

namespace disklab::test::elliptic_domain {

constexpr double kHalfPi = 1.5707963267948966;  // fl(pi/2) < pi/2
constexpr int kPhiKinds = 3, kMKinds = 2, kNKinds = 3;

// Kind 0: uniform on [0, pi/2]; 1: pi/2 - 10^-(0..16) (c -> 0); 2: 10^-(0..12) (s -> 0).
inline double phi(int kind, double u) {
  if (kind == 0) return kHalfPi * u;
  if (kind == 1) return kHalfPi - std::pow(10.0, -16 * u);
  return std::pow(10.0, -12 * u);
}
// 1 - 2^-(0..53) rounded to a multiple of 2^-53: below 1, with an exact complement.
inline double near_one(double u) {
  return 1.0 - std::ldexp(std::max(1.0, std::round(std::ldexp(std::pow(2.0, -53 * u), 53))), -53);
}
// Kind 0: uniform on [0, 1); 1: m -> 1.
inline double m(int kind, double u) {
  return kind == 0 ? u : near_one(u);
}
// Kind 0: (-1, 1); 1: -10^(0..16) (the parallel map's n = -b_t^2); 2: n -> 1.
inline double n(int kind, double u) {
  if (kind == 0) return 2 * u - 1;
  if (kind == 1) return -std::pow(10.0, 16 * u);
  return near_one(u);
}

}  // namespace disklab::test::elliptic_domain
