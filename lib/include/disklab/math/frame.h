#pragma once
// Orthonormal frames: three unit vectors (x, y, z) with x cross y = z, and the change of
// coordinates between world space and the frame.
#include <cmath>
#include <limits>

#include <Eigen/Geometry>  // cross products

#include "disklab/types.h"

namespace disklab::math {

// |v| without the squares' underflow or overflow: v.norm() where |v|^2 is a normal double, else
// through v / max|v_i|.
inline double safe_norm(const Vec3& v) {
  const double n2 = v.squaredNorm();
  if (n2 >= std::numeric_limits<double>::min() && n2 < std::numeric_limits<double>::infinity())
    return std::sqrt(n2);
  const double m = v.cwiseAbs().maxCoeff();
  if (!(m > 0.0) || !std::isfinite(m)) return m;
  return m * (v / m).norm();
}

struct Frame {
  Vec3 x = Vec3::UnitX();
  Vec3 y = Vec3::UnitY();
  Vec3 z = Vec3::UnitZ();

  // Coordinates of the world vector v in this frame.
  Vec3 to_local(const Vec3& v) const { return {v.dot(x), v.dot(y), v.dot(z)}; }
  // World vector with coordinates l in this frame.
  Vec3 to_world(const Vec3& l) const { return l.x() * x + l.y() * y + l.z() * z; }

  // A right-handed frame whose z is the unit vector `z` (assumed unit). Branchless basis of
  // Duff et al. 2017 ("Building an orthonormal basis, revisited"): no normalisation, no
  // singular direction (the sign switch keeps 1 + |z_z| >= 1).
  static Frame from_z(const Vec3& z) {
    const double sign = std::copysign(1.0, z.z());
    const double a = -1.0 / (sign + z.z());
    const double b = z.x() * z.y() * a;
    Frame f;
    f.x = Vec3(1.0 + sign * z.x() * z.x() * a, sign * b, -sign * z.x());
    f.y = Vec3(b, sign + z.y() * z.y() * a, -z.y());
    f.z = z;
    return f;
  }

  // A right-handed frame with the given z (unit) and x as close as possible to `x_hint`: x is
  // x_hint with its z component removed (Gram-Schmidt) and normalised, y = z cross x. Falls back
  // to from_z when x_hint is (nearly) parallel to z. The projection step keeps x exactly
  // orthogonal to z up to rounding even when x_hint was formed with cancellation.
  // Lengths are taken scale-safely: a hint of length ~1e-160 (a point 1e-160 off the axis) has a
  // subnormal squared norm, whose sqrt is off by up to ~1e-5, and x came out that far from unit.
  static Frame from_zx(const Vec3& z, const Vec3& x_hint_in) {
    // A hint whose squares are subnormal is first scaled up by its largest component (the
    // projection below would otherwise be formed from underflowed products).
    Vec3 x_hint = x_hint_in;
    if (x_hint.squaredNorm() < std::numeric_limits<double>::min()) {
      const double m = x_hint.cwiseAbs().maxCoeff();
      if (m > 0.0 && std::isfinite(m)) x_hint /= m;
    }
    Vec3 x = x_hint - x_hint.dot(z) * z;
    const double norm = safe_norm(x), hint_norm = safe_norm(x_hint);
    // 1e-150 of the hint's length: below it the direction of x is noise; the fallback is then as
    // good as any (callers use this only where the choice of x does not matter, e.g. on axis).
    if (!(norm > 1e-150 * hint_norm) || !std::isfinite(norm)) return from_z(z);
    const double n2 = x.squaredNorm();
    if (n2 >= std::numeric_limits<double>::min()) {
      x /= norm;  // the plain form, bit for bit, where the squares are normal
    } else {
      x /= x.cwiseAbs().maxCoeff();
      x /= x.norm();
    }
    // A hint nearly along z (the cross product that makes it, for a point on a disk's axis, is
    // rounding noise and may point anywhere) leaves x a z component of up to eps |hint| / |x|
    // after one projection; a second one, on the unit x, brings it to rounding (Kahan's "twice
    // is enough", in Parlett's The Symmetric Eigenvalue Problem). Hints at least half
    // perpendicular to z skip it.
    if (norm < 0.5 * hint_norm) {
      x -= x.dot(z) * z;
      x /= x.norm();
    }
    Frame f;
    f.z = z;
    f.x = x;
    f.y = z.cross(x);
    return f;
  }
};

}  // namespace disklab::math
