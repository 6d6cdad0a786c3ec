// Links against the installed disklab and uses a sequence and the elliptic integrals (whose
// public headers must compile without the library's private ones): exits non-zero if anything
// is off.
#include <cmath>
#include <cstdio>

#include <disklab/math/elliptic.h>
#include <disklab/sequence/sequence.h>

int main() {
  auto seq = disklab::sequence::make_sequence("random", 7);
  const disklab::Point2 p = seq->at(3);
  std::printf("%.17g %.17g\n", p.x, p.y);
  // Pi(0.5; 1|0.3) = 1.2391080217058432724 (mpmath ellippi, 30 digits); the library promises
  // 2 ulp, 1e-15 relative is a loose check that the installed kernel dispatch links and runs.
  constexpr double kPi = 1.2391080217058432724, kRelative = 1e-15;
  const double pi = disklab::math::ellint_pi(0.5, 1.0, 0.3);
  std::printf("%.17g\n", pi);
  const bool sequence_ok = p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0;
  return sequence_ok && std::fabs(pi - kPi) <= kRelative * kPi ? 0 : 1;
}
