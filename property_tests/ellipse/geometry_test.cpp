// Spherical-ellipse geometry (Guillén et al. 2017, Sec. 3, eqs. 3-5, with the frame fix of
// docs/design.md section 3): frames, shape, degenerate input, invariances.
//
// Replay a rapidcheck failure with RC_PARAMS="reproduce=<string it printed>".
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "disklab/ellipse/geometry.h"
#include "disklab/ellipse/solid_angle.h"
#include "ellipse/geometry_scenes.h"
#include "support/disk_quadrature.h"

namespace disklab::test {
namespace {

using ellipse::Disk;
using ellipse::make_spherical_ellipse;
using ellipse::SphericalEllipse;

constexpr double kEps = std::numeric_limits<double>::epsilon();
// TOLERANCES (one place for the suite).
// Frames: unit vectors and products formed with a handful of roundings each.
constexpr double kFrameTol = 16 * kEps;
// Closed forms of a, b (geometry.h) against the printed construction of eqs. (3)-(5) run at 50
// digits from the same h, e, r: each closed form is ~10 correctly rounded operations on
// cancellation-free terms, so a few ulps; 32 ulps leaves room for sqrt/atan/hypot libm error.
constexpr double kShapeUlps = 32;
// Boundary points of the disk vs the ellipse, as angles from z_e (radians, absolute): the
// direction to a rim point p is formed in double from world coordinates of magnitude M, so its
// angle carries absolute error ~ eps M / |p - o| (|p - o| >= h); the test runs within 1e3 radii
// so that this stays a small fraction of alpha. Allowance: kBoundaryUlps eps (1 + M / h).
constexpr double kBoundaryUlps = 64;
// Invariance under rigid motion and scaling: the scene's inputs are rounded after the motion,
// which moves o relative to the disk by ~eps * (coordinate magnitude). Omega, a, b react through
// h (relative sensitivity ~ |o - c| / h); the allowance is kInvarianceUlps eps times that
// conditioning number.
constexpr double kInvarianceUlps = 64;
// Exact power-of-two scaling changes no input bit pattern except the exponent: results agree to
// the roundings that are not scale-free (none in theory); allow 4 ulps.
constexpr double kPowerOfTwoUlps = 4;

double rel(double x, double ref) {
  return ref == 0.0 ? std::fabs(x) : std::fabs(x / ref - 1.0);
}

std::string frame_text(const math::Frame& f) {
  std::ostringstream s;
  s.precision(17);
  s << "x=(" << f.x.transpose() << ") y=(" << f.y.transpose() << ") z=(" << f.z.transpose() << ")";
  return s.str();
}

void check_frame(const math::Frame& f, const std::string& what) {
  RC_ASSERT(std::fabs(f.x.norm() - 1.0) <= kFrameTol);
  RC_ASSERT(std::fabs(f.y.norm() - 1.0) <= kFrameTol);
  RC_ASSERT(std::fabs(f.z.norm() - 1.0) <= kFrameTol);
  RC_ASSERT(std::fabs(f.x.dot(f.y)) <= kFrameTol);
  RC_ASSERT(std::fabs(f.y.dot(f.z)) <= kFrameTol);
  RC_ASSERT(std::fabs(f.z.dot(f.x)) <= kFrameTol);
  RC_ASSERT((f.x.cross(f.y) - f.z).norm() <= kFrameTol);  // right-handed
  (void)what;
}

RC_GTEST_PROP(GeometryFrame, OrthonormalRightHandedAndAlignedWithTheTilt, (uint64_t seed)) {
  const Scene s = random_scene(seed);
  const SphericalEllipse se = make_spherical_ellipse(s.disk, s.point);
  RC_TAG(s.describe());
  RC_ASSERT(!se.empty);
  RC_LOG() << s.describe() << "\nR_d " << frame_text(se.disk_frame()) << "\nR_e "
           << frame_text(se.frame) << "\n";
  const math::Frame disk_frame = se.disk_frame();  // x_d = x_e and z_d = -n by construction
  check_frame(disk_frame, "R_d");
  check_frame(se.frame, "R_e");
  // z_d = -n of the lit face, with n the input normal up to its length and the two-sided flip;
  // o sees the lit face (h > 0).
  RC_ASSERT(std::fabs(std::fabs(disk_frame.z.dot(s.disk.normal)) - s.disk.normal.norm()) <=
            kFrameTol * s.disk.normal.norm());
  RC_ASSERT(se.h > 0.0);
  // Eq. (3) fixed: the disk centre has no x_d component and lies towards -y_d (y_c = -e).
  const Vec3 v = s.disk.center - s.point;
  RC_ASSERT(std::fabs(v.dot(disk_frame.x)) <= kFrameTol * v.norm());
  RC_ASSERT(v.dot(disk_frame.y) <= kFrameTol * v.norm());
  // z_e lies in the (y_d, z_d) plane, between the disk centre's direction and the normal side.
  RC_ASSERT(std::fabs(se.frame.z.dot(disk_frame.x)) <= kFrameTol);
  RC_ASSERT(se.frame.z.dot(disk_frame.z) > 0.0);
}

// A point exactly on the axis of a disk whose normal is nearly a coordinate axis (a ceiling
// light slightly tilted, seen from right below): z_d x (c - o), which gives x_d, is then rounding
// noise, and may lie almost along z_d. One Gram-Schmidt projection left x_d up to 1.4e-8 off
// perpendicular here (found by fuzz_geometry); the frames must stay orthonormal to rounding.
RC_GTEST_PROP(GeometryFrame, OrthonormalOnTheAxisOfANearlyAxisAlignedDisk, (uint64_t seed)) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const int axis = static_cast<int>(rng() % 3);
  const double tilt = std::pow(10.0, -12.0 + 11.0 * (U(rng) + 1.0) / 2.0);
  Vec3 normal(tilt * U(rng), tilt * U(rng), tilt * U(rng));
  normal[axis] = rng() % 2 ? 1.0 : -1.0;
  const Vec3 center = rng() % 2 ? Vec3(0, 0, 0) : Vec3(U(rng), U(rng), U(rng));
  const Disk disk{center, normal, 0.5 + std::fabs(U(rng)), false};
  const Vec3 o = center + (0.1 + 10.0 * std::fabs(U(rng))) * normal;  // on the lit side
  const SphericalEllipse se = make_spherical_ellipse(disk, o);
  RC_ASSERT(!se.empty);
  RC_LOG() << "normal " << normal.transpose() << " centre " << center.transpose() << "\nR_d "
           << frame_text(se.disk_frame()) << "\nR_e " << frame_text(se.frame) << "\n";
  check_frame(se.disk_frame(), "R_d");
  check_frame(se.frame, "R_e");
}

RC_GTEST_PROP(GeometryFrame, EllipseCentreRayHitsTheDiskInside, (uint64_t seed)) {
  const Scene s = random_scene(seed, -3.0, 3.0);
  const SphericalEllipse se = make_spherical_ellipse(s.disk, s.point);
  RC_ASSERT(!se.empty);
  // o + t z_e meets the plane (p - c).n = 0 at t = h / (z_e . (-n)).
  const double t = se.h / se.frame.z.dot(-se.normal);
  const Vec3 p = s.point + t * se.frame.z;
  const double rho = (p - s.disk.center).norm();
  RC_LOG() << s.describe() << " hit at " << rho / s.disk.radius << " radii from the centre\n";
  RC_ASSERT(t > 0.0);
  RC_ASSERT(rho < s.disk.radius);
}

RC_GTEST_PROP(GeometryShape, AxesOrderedAndComplementsConsistent, (uint64_t seed)) {
  const Scene s = random_scene(seed, -3.0, 8.0);
  const SphericalEllipse se = make_spherical_ellipse(s.disk, s.point);
  RC_LOG() << s.describe() << " a=" << se.a << " b=" << se.b << " alpha=" << se.alpha
           << " beta=" << se.beta << " a_t=" << se.a_t << " b_t=" << se.b_t << "\n";
  RC_ASSERT(!se.empty);
  RC_ASSERT(se.b > 0.0);
  RC_ASSERT(se.a >= se.b);
  RC_ASSERT(se.alpha >= se.beta);
  RC_ASSERT(se.a_t >= se.b_t);
  RC_ASSERT(se.a < 1.0 || se.one_minus_a2 < kEps);
  RC_ASSERT(rel(std::sin(se.alpha), se.a) <= kShapeUlps * kEps);
  // atan is well conditioned (tan is not near pi/2): check beta = atan(b_t) that way round.
  RC_ASSERT(rel(std::atan(se.b_t), se.beta) <= kShapeUlps * kEps);
  RC_ASSERT(std::fabs(se.one_minus_a2 - std::cos(se.alpha) * std::cos(se.alpha)) <=
            kShapeUlps * kEps * se.one_minus_a2 + kEps);
  RC_ASSERT(se.m >= 0.0 && se.m < 1.0);
  RC_ASSERT(std::fabs(se.m + se.one_minus_m - 1.0) <= 4 * kEps);
  RC_ASSERT(std::fabs(se.n_r + se.one_minus_n_r - 1.0) <= 4 * kEps);
}

// The closed forms of geometry.h against eqs. (3)-(5) followed step by step (50 digits).
RC_GTEST_PROP(GeometryShape, ClosedFormsMatchThePrintedConstruction, (uint64_t seed)) {
  const Scene s = random_scene(seed, -3.0, 8.0);
  const SphericalEllipse se = make_spherical_ellipse(s.disk, s.point);
  RC_ASSERT(!se.empty);
  const PrintedShape p = printed_shape(se.h, se.e, se.radius);
  RC_LOG() << s.describe() << " h=" << se.h << " e=" << se.e << "\n a=" << se.a
           << " printed=" << p.a << " rel=" << rel(se.a, p.a) << "\n b=" << se.b
           << " printed=" << p.b << " rel=" << rel(se.b, p.b) << "\n";
  RC_ASSERT(rel(se.a, p.a) <= kShapeUlps * kEps);
  RC_ASSERT(rel(se.b, p.b) <= kShapeUlps * kEps);
  RC_ASSERT(rel(se.a_t, p.a_t) <= kShapeUlps * kEps);
  RC_ASSERT(rel(se.b_t, p.b_t) <= kShapeUlps * kEps);
}

TEST(GeometryShape, OnAxisIsACircleOfTheClosedFormRadius) {
  for (double d : {1e-6, 1e-2, 1.0, 1e3, 1e8}) {
    const Disk disk{Vec3(1, 2, 3), Vec3(0, 0, 2), 0.5, false};
    const Vec3 o(1, 2, 3 + d);
    const double d_exact = o.z() - 3.0;  // what 3 + d rounded to (Sterbenz: exact)
    const SphericalEllipse se = make_spherical_ellipse(disk, o);
    ASSERT_FALSE(se.empty) << d;
    EXPECT_LE(rel(se.b, se.a), kShapeUlps * kEps) << "d=" << d << " a=" << se.a << " b=" << se.b;
    EXPECT_LE(se.m, kShapeUlps * kEps) << d;
    // tan(alpha) = r / d on axis.
    EXPECT_LE(rel(se.a_t, 0.5 / d_exact), kShapeUlps * kEps) << "d=" << d << " a_t=" << se.a_t;
  }
}

// Rim points of the disk land on the spherical ellipse: their angle from z_e equals the
// ellipse's angular radius atan(r_t(phi)) at their azimuth phi (r_t from a_t, b_t: eq. 18 on the
// tangent ellipse); interior points land strictly inside.
RC_GTEST_PROP(GeometryShape, RimMapsOntoTheEllipseAndInteriorInside, (uint64_t seed)) {
  const Scene s = random_scene(seed, -1.0, 3.0);
  const SphericalEllipse se = make_spherical_ellipse(s.disk, s.point);
  RC_ASSERT(!se.empty);
  const math::Frame plane = math::Frame::from_z(se.normal);
  const double M = std::max(s.disk.center.norm(), s.point.norm());
  const double tol = kBoundaryUlps * kEps * (1.0 + M / se.h);
  for (int k = 0; k < 16; ++k) {
    const double psi = math::kTwoPi * (k + 0.37) / 16;
    for (double rho : {1.0, 0.6}) {
      const Vec3 p =
          s.disk.center + s.disk.radius * rho * (std::cos(psi) * plane.x + std::sin(psi) * plane.y);
      const Vec3 l = se.to_local((p - s.point).normalized());
      const double theta = std::atan2(std::hypot(l.x(), l.y()), l.z());
      const double phi = std::atan2(l.y(), l.x());
      const double sp = std::sin(phi), cp = std::cos(phi);
      const double rt =
          se.a_t * se.b_t / std::hypot(se.a_t * sp, se.b_t * cp);  // tangent-ellipse radius
      const double theta_e = std::atan(rt);
      RC_LOG() << s.describe() << " psi=" << psi << " rho=" << rho << " theta=" << theta
               << " ellipse=" << theta_e << "\n";
      if (rho == 1.0) {
        RC_ASSERT(std::fabs(theta - theta_e) <= tol);
      } else {
        RC_ASSERT(theta < theta_e - tol);
      }
    }
  }
}

TEST(GeometryDegenerate, EmptyCasesHaveZeroSolidAngle) {
  const Disk one{Vec3(0, 0, 0), Vec3(0, 0, 1), 1.0, false};
  const Disk two{Vec3(0, 0, 0), Vec3(0, 0, 1), 1.0, true};
  // In the plane (outside, on the rim, inside), behind a one-sided disk, zero radius.
  for (const Vec3& o : {Vec3(3, 0, 0), Vec3(1, 0, 0), Vec3(0.2, 0.1, 0)}) {
    EXPECT_TRUE(make_spherical_ellipse(one, o).empty) << o.transpose();
    EXPECT_TRUE(make_spherical_ellipse(two, o).empty) << o.transpose();
    EXPECT_EQ(make_spherical_ellipse(two, o).omega, 0.0);
  }
  const SphericalEllipse behind = make_spherical_ellipse(one, Vec3(0.1, 0.2, -1));
  EXPECT_TRUE(behind.empty);
  EXPECT_EQ(behind.omega, 0.0);
  EXPECT_EQ(ellipse::radial_sector(behind, 1.0), 0.0);
  EXPECT_EQ(ellipse::parallel_half_sector(behind, 0.1), 0.0);
  const Disk zero{Vec3(0, 0, 0), Vec3(0, 0, 1), 0.0, false};
  EXPECT_TRUE(make_spherical_ellipse(zero, Vec3(0, 0, 1)).empty);
  EXPECT_EQ(ellipse::solid_angle(zero, Vec3(0, 0, 1)), 0.0);
}

TEST(GeometryDegenerate, TwoSidedFromBehindIsTheMirroredFront) {
  const Disk two{Vec3(1, -2, 0.5), Vec3(0.3, 0.4, -1.2), 0.75, true};
  const Disk flipped{two.center, -two.normal, two.radius, false};
  const Vec3 o(2.5, 1.0, 4.0);  // behind `two` (normal points away), in front of `flipped`
  const SphericalEllipse a = make_spherical_ellipse(two, o);
  const SphericalEllipse b = make_spherical_ellipse(flipped, o);
  ASSERT_FALSE(a.empty);
  EXPECT_TRUE(make_spherical_ellipse(Disk{two.center, two.normal, two.radius, false}, o).empty);
  EXPECT_EQ(a.omega, b.omega);
  EXPECT_EQ(a.a, b.a);
  EXPECT_EQ(a.b, b.b);
  EXPECT_EQ((a.frame.z - b.frame.z).norm(), 0.0);
}

TEST(GeometryDegenerate, InvalidInputThrows) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Disk ok{Vec3(0, 0, 0), Vec3(0, 0, 1), 1.0, false};
  const Vec3 o(0, 0, 1);
  EXPECT_NO_THROW(make_spherical_ellipse(ok, o));
  for (double bad : {nan, inf, -inf}) {
    Disk d = ok;
    d.center.x() = bad;
    EXPECT_THROW(make_spherical_ellipse(d, o), std::invalid_argument);
    d = ok;
    d.normal.y() = bad;
    EXPECT_THROW(make_spherical_ellipse(d, o), std::invalid_argument);
    d = ok;
    d.radius = bad;
    EXPECT_THROW(make_spherical_ellipse(d, o), std::invalid_argument);
    EXPECT_THROW(make_spherical_ellipse(ok, Vec3(0, bad, 1)), std::invalid_argument);
  }
  Disk d = ok;
  d.normal = Vec3::Zero();
  EXPECT_THROW(make_spherical_ellipse(d, o), std::invalid_argument);
  d = ok;
  d.radius = -1.0;
  EXPECT_THROW(make_spherical_ellipse(d, o), std::invalid_argument);
}

// Rotating, translating and scaling the whole scene changes nothing but rounding.
RC_GTEST_PROP(GeometryInvariance, RigidMotionAndScaling, (uint64_t seed)) {
  const Scene s = random_scene(seed, -2.0, 6.0);
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(math::kPi * U(rng), random_unit(rng)).toRotationMatrix();
  const Vec3 shift(10 * U(rng), 10 * U(rng), 10 * U(rng));
  const double scale = std::exp2(4 * U(rng));  // not a power of two in general
  Disk moved = s.disk;
  moved.center = scale * (R * s.disk.center + shift);
  moved.normal = R * s.disk.normal;
  moved.radius = scale * s.disk.radius;
  const Vec3 o = scale * (R * s.point + shift);
  const SphericalEllipse a = make_spherical_ellipse(s.disk, s.point);
  const SphericalEllipse b = make_spherical_ellipse(moved, o);
  RC_ASSERT(!a.empty && !b.empty);
  // Conditioning: coordinate magnitude over the height of o (both scenes).
  const double mag = std::max(
      {s.disk.center.norm(), s.point.norm(), shift.norm(), (s.point - s.disk.center).norm()});
  const double kappa = 1.0 + 2.0 * mag / a.h;
  const double tol = kInvarianceUlps * kEps * kappa;
  RC_LOG() << s.describe() << " scale=" << scale << " kappa=" << kappa << "\n omega " << a.omega
           << " vs " << b.omega << " rel=" << rel(b.omega, a.omega) << " tol=" << tol << "\n";
  RC_ASSERT(rel(b.omega, a.omega) <= tol);
  RC_ASSERT(rel(b.a, a.a) <= tol);
  RC_ASSERT(rel(b.b, a.b) <= tol);
  // Exact power-of-two scaling (no motion): every input scales exactly.
  Disk scaled = s.disk;
  const double p2 = std::exp2(std::floor(20 * U(rng)));
  scaled.center *= p2;
  scaled.normal *= p2;
  scaled.radius *= p2;
  const SphericalEllipse c = make_spherical_ellipse(scaled, p2 * s.point);
  RC_ASSERT(rel(c.omega, a.omega) <= kPowerOfTwoUlps * kEps);
  RC_ASSERT(rel(c.b, a.b) <= kPowerOfTwoUlps * kEps);
}

// The same at the ends of the double range (lengths up to ~1e280 and down to ~1e-280): the shape
// depends on h/r and e/r only, so no square may overflow or underflow on the way.
RC_GTEST_PROP(GeometryInvariance, ExtremePowerOfTwoScales, (uint64_t seed)) {
  const Scene s = random_scene(seed, -3.0, 6.0);
  const SphericalEllipse a = make_spherical_ellipse(s.disk, s.point);
  RC_PRE(!a.empty);
  std::mt19937_64 rng(seed + 7);
  const int exponent = std::uniform_int_distribution<int>(600, 900)(rng);
  for (const double p2 : {std::exp2(exponent), std::exp2(-exponent)}) {
    Disk scaled = s.disk;
    scaled.center *= p2;
    scaled.radius *= p2;
    const SphericalEllipse c = make_spherical_ellipse(scaled, p2 * s.point);
    RC_LOG() << s.describe() << " scale=2^" << std::log2(p2) << " omega " << a.omega << " -> "
             << c.omega << "\n";
    RC_ASSERT(!c.empty);
    RC_ASSERT(rel(c.omega, a.omega) <= kPowerOfTwoUlps * kEps);
    RC_ASSERT(rel(c.a, a.a) <= kPowerOfTwoUlps * kEps);
    RC_ASSERT(rel(c.b, a.b) <= kPowerOfTwoUlps * kEps);
  }
}

// Closer than 1e-150 radii under the disk, a_t ~ r/h overflows in a_t^2; the disk then covers the
// hemisphere to double precision. On axis the closed form 2 pi r^2/(L (h + L)), L = hypot(h, r),
// is the reference; off axis (e = r/2) Omega = 2 pi - O(h/r). Beyond the rim (e = 2r) Omega is
// proportional to h up to O(h/r): it must keep its true tiny scale (a clamp of h would give the
// ratio 1), so Omega(2h)/Omega(h) = 2; 1e-12 is far above rounding (a few ulps) and far below 1.
TEST(GeometryDegenerate, TinyHeightsKeepTheirLimits) {
  for (const double h : {1e-100, 1e-150, 1e-160, 1e-250, 1e-300}) {
    const Disk disk{Vec3::Zero(), Vec3(0, 0, 1), 1.0, false};
    const double on_axis = make_spherical_ellipse(disk, Vec3(0, 0, h)).omega;
    EXPECT_NEAR(on_axis, ellipse::solid_angle_on_axis(h, 1.0), 2 * kEps * math::kTwoPi) << h;
    const double inside = make_spherical_ellipse(disk, Vec3(0.5, 0, h)).omega;
    EXPECT_NEAR(inside, math::kTwoPi, 2 * kEps * math::kTwoPi) << h;
    EXPECT_LE(inside, math::kTwoPi) << h;
    const double beyond = make_spherical_ellipse(disk, Vec3(2.0, 0, h)).omega;
    const double beyond2 = make_spherical_ellipse(disk, Vec3(2.0, 0, 2 * h)).omega;
    EXPECT_GT(beyond, 0.0) << h;
    EXPECT_NEAR(beyond2 / beyond, 2.0, 1e-12) << h;
  }
}

}  // namespace
}  // namespace disklab::test
