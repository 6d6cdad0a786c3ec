// libFuzzer: the spherical ellipse and its solid angle (ellipse/geometry.h, solid_angle.h) on any
// disk and point (NaN, Inf, subnormal and huge values, zero and extreme normals). Contracts:
// never throws except std::invalid_argument exactly when valid_disk_input is false; the noexcept
// form agrees; Omega is finite and in [0, 2 pi]; a non-empty ellipse has 0 < b <= a <= 1,
// 0 < beta <= alpha <= pi/2, finite positive a_t >= b_t (to 4 ulps), complements in [0, 1] and a
// unit frame.
#include <cmath>
#include <limits>
#include <stdexcept>

#include "disklab/ellipse/geometry.h"
#include "disklab/ellipse/solid_angle.h"
#include "disklab/math/constants.h"
#include "fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using disklab::Vec3;
  namespace ellipse = disklab::ellipse;
  disklab::fuzz::Bytes in(data, size);
  ellipse::Disk disk;
  for (int i = 0; i < 3; ++i)
    disk.center[i] = in.any_double();
  for (int i = 0; i < 3; ++i)
    disk.normal[i] = in.any_double();
  disk.radius = in.any_double();
  disk.two_sided = in.u8() & 1;
  Vec3 o;
  for (int i = 0; i < 3; ++i)
    o[i] = in.any_double();
  const bool valid = ellipse::valid_disk_input(disk, o);
  ellipse::SphericalEllipse se;
  bool threw = false;
  try {
    se = ellipse::make_spherical_ellipse(disk, o);
  } catch (const std::invalid_argument&) {
    threw = true;
  }
  FUZZ_CHECK(threw == !valid);
  const ellipse::SphericalEllipse quiet = ellipse::spherical_ellipse(disk, o);
  if (!valid) {
    FUZZ_CHECK(quiet.empty && quiet.omega == 0.0);
    return 0;
  }
  FUZZ_CHECK(quiet.empty == se.empty && quiet.omega == se.omega);
  FUZZ_CHECK(std::isfinite(se.omega) && se.omega >= 0.0 && se.omega <= disklab::math::kTwoPi);
  if (se.empty) {
    FUZZ_CHECK(se.omega == 0.0);
    return 0;
  }
  FUZZ_CHECK(se.omega > 0.0 && se.quadrant > 0.0 && std::isfinite(se.quadrant));
  // On the axis a == b in exact arithmetic, and the closed forms of a_t and b_t round
  // differently: the orderings hold to kOrderUlps.
  constexpr double kOrder = 1.0 + 4 * std::numeric_limits<double>::epsilon();
  FUZZ_CHECK(se.b > 0.0 && se.b <= se.a * kOrder && se.a <= 1.0);
  FUZZ_CHECK(se.beta > 0.0 && se.beta <= se.alpha * kOrder && se.alpha <= disklab::math::kHalfPi);
  FUZZ_CHECK(std::isfinite(se.a_t) && se.b_t > 0.0 && se.b_t <= se.a_t * kOrder);
  FUZZ_CHECK(se.one_minus_a2 >= 0.0 && se.one_minus_a2 <= 1.0);
  FUZZ_CHECK(se.one_minus_b2 >= 0.0 && se.one_minus_b2 <= 1.0);
  FUZZ_CHECK(se.m >= 0.0 && se.m <= 1.0 && se.one_minus_m >= 0.0 && se.one_minus_m <= 1.0);
  for (const Vec3* v : {&se.frame.x, &se.frame.y, &se.frame.z})
    FUZZ_CHECK(std::abs(v->norm() - 1.0) <= 1e-12);
  FUZZ_CHECK(std::abs(se.frame.x.dot(se.frame.z)) <= 1e-12);
  return 0;
}
