// Bijectivity of the spherical-ellipse maps: inverse(map(u)) == u and map(inverse(w)) == w,
// random (rapidcheck) and adversarial (quadrant seams, centre, rim, eps = 0 and 1 - ulp), over
// configurations from on-axis to grazing to 1e8 radii.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "ellipse/map_common.h"

namespace disklab::test {
namespace {

// ---- tolerances (one place) ----
// u -> w -> u' through the local frame. Newton stops at 1e-15 of the quadrant (eps1 to 2.5e-16);
// the inverse re-evaluates the same quadrature (a sum of 128 positive terms, relative rounding
// ~1e-15) and an atan2 whose condition number for t is at most ~4/pi; eps2 is a ratio of two
// quantities each with a few ulps of relative error. 1e-13 leaves a factor ~30 above that budget.
constexpr double kRoundTripU = 1e-13;
// The parallel map's h_p vanishes at the rim as sqrt(beta - phi_p): eps2 = (h/h_p + 1)/2 is
// ill-conditioned there, with condition ~ 1/(1 - (2 eps2 - 1)^2)-free but ~ |h| / h_p^2 * dh_p
// in phi; it is tested on eps1 in [1e-6, 1 - 1e-6], where dh_p/dphi_p * dphi_p/deps1 stays below
// ~1e3, hence 1e3 * kRoundTripU.
constexpr double kRoundTripUParallel = 1e-10;
// w -> u -> w': the local direction is compared, scaled by the ellipse's size a; rounding of the
// forward map is a few ulps of the local coordinates (relative to a), amplified by the map's
// Jacobian condition (at most ~1e3 near the rim of the thin grazing ellipse).
constexpr double kRoundTripW = 1e-11;
// The z component of a unit direction towards a small ellipse is cos(angle) ~ 1: its rounding is
// absolute (an ulp of 1 is 2.2e-16) whatever the map does, so it is held to kRoundTripW * a or
// kRoundTripZUlps ulps of 1, whichever is larger (a 1-ulp difference at a ~ 1e-8 would otherwise
// read as 1e-8 of the ellipse's size).
constexpr double kRoundTripZUlps = 4;
// ld-radial goes through the concentric map and its atan-based inverse (absolute accuracy a
// few ulps, disk/concentric.h) and the polar detour; same budget as radial.
constexpr double kRoundTripULd = 1e-13;

double uniform01(uint64_t bits) {
  return static_cast<double>(bits >> 11) * 0x1p-53;
}

std::string chain(const AnyMap& m, const DiskConfig& c, Point2 u, const ellipse::EllipseSample& s,
                  Point2 back) {
  std::ostringstream o;
  o.precision(17);
  o << m.name << " on " << c.describe() << "\n  u=(" << u.x << ", " << u.y << ") -> local=("
    << s.local.transpose() << ") valid=" << s.valid << " pdf=" << s.pdf << "\n  -> u'=(" << back.x
    << ", " << back.y << ") err=(" << back.x - u.x << ", " << back.y - u.y << ")";
  return o.str();
}

double u_tolerance(const std::string& name) {
  if (name == "parallel") return kRoundTripUParallel;
  if (name == "ld-radial") return kRoundTripULd;
  return kRoundTripU;
}

// Checks inverse(map(u)) == u; eps1 is undefined at the ellipse centre (eps2 == 0) and, for the
// parallel map, at the slice ends.
void check_u(const AnyMap& m, const DiskConfig& c, Point2 u) {
  const ellipse::EllipseSample s = m.sample(u, nullptr);
  ASSERT_TRUE(s.valid) << chain(m, c, u, s, {});
  ASSERT_TRUE(s.local.allFinite() && s.direction.allFinite() && std::isfinite(s.pdf))
      << chain(m, c, u, s, {});
  EXPECT_NEAR(s.direction.norm(), 1.0, 1e-15);
  const Point2 back = m.invert_local(s.local);
  const double tol = u_tolerance(m.name);
  // At the centre eps1 is undefined: eps2 == 0, or eps2 so small (a denormal) that the offset
  // from the centre underflows and the direction IS the centre direction.
  const bool centre = m.name != "ld-radial" && m.name != "parallel" &&
                      (u.y == 0.0 || (s.local.x() == 0.0 && s.local.y() == 0.0));
  double de1 = std::abs(back.x - u.x);
  if (m.name == "radial" || m.name == "radial-fast") de1 = std::min(de1, 1.0 - de1);  // periodic
  if (!centre) {
    EXPECT_LE(de1, tol) << chain(m, c, u, s, back);
  }
  EXPECT_LE(std::abs(back.y - u.y), tol) << chain(m, c, u, s, back);
}

class MapBijectivity : public ::testing::TestWithParam<std::string> {};

TEST_P(MapBijectivity, AdversarialRoundTrips) {
  const double one_minus = math::kOneMinusEpsilon;
  const double tiny = std::numeric_limits<double>::denorm_min();
  const std::vector<double> e1s = {0.0,
                                   tiny,
                                   1e-300,
                                   1e-12,
                                   0.25,
                                   std::nextafter(0.25, 0.0),
                                   std::nextafter(0.25, 1.0),
                                   0.5,
                                   std::nextafter(0.5, 0.0),
                                   0.75,
                                   0.3,
                                   0.999999,
                                   one_minus};
  const std::vector<double> e2s = {tiny, 1e-300, 1e-12, 0.5, 0.999999, one_minus, 1.0};
  for (const DiskConfig& c : map_configs()) {
    const AnyMap m = make_map(GetParam(), c);
    for (double e1 : e1s) {
      for (double e2 : e2s) {
        if (m.name == "parallel" && (e1 < 1e-6 || e1 > 1.0 - 1e-6 || e2 == 1.0)) continue;
        if (m.name == "ld-radial" && (e2 == 1.0 || e1 == 0.0)) continue;  // square's rim wraps
        check_u(m, c, {e1, e2});
      }
    }
  }
}

RC_GTEST_PROP(MapBijectivityRandom, InverseOfMapIsIdentity, ()) {
  const auto names = bijective_map_names();
  const auto configs = map_configs();
  const auto mi = *rc::gen::inRange<std::size_t>(0, names.size());
  const auto ci = *rc::gen::inRange<std::size_t>(0, configs.size());
  const Point2 u{uniform01(*rc::gen::arbitrary<uint64_t>()),
                 uniform01(*rc::gen::arbitrary<uint64_t>())};
  const AnyMap m = make_map(names[mi], configs[ci]);
  if (m.name == "parallel" && (u.x < 1e-6 || u.x > 1.0 - 1e-6)) return;
  const ellipse::EllipseSample s = m.sample(u, nullptr);
  RC_ASSERT(s.valid);
  const Point2 back = m.invert_local(s.local);
  double de1 = std::abs(back.x - u.x);
  de1 = std::min(de1, 1.0 - de1);
  RC_LOG() << chain(m, configs[ci], u, s, back) << "\n";
  RC_ASSERT(de1 <= u_tolerance(m.name));
  RC_ASSERT(std::abs(back.y - u.y) <= u_tolerance(m.name));
}

// w -> u -> w' for directions w drawn by area sampling (an independent sampler), so the inverse
// is exercised on directions the forward map did not produce.
RC_GTEST_PROP(MapBijectivityRandom, MapOfInverseIsIdentity, ()) {
  const auto names = bijective_map_names();
  const auto configs = map_configs();
  const auto mi = *rc::gen::inRange<std::size_t>(0, names.size());
  const auto ci = *rc::gen::inRange<std::size_t>(0, configs.size());
  const DiskConfig& c = configs[ci];
  const Point2 v{uniform01(*rc::gen::arbitrary<uint64_t>()),
                 uniform01(*rc::gen::arbitrary<uint64_t>())};
  const auto area = ellipse::AreaSampler::make(c.disk(), c.point);
  const ellipse::EllipseSample w = area.sample(v);
  RC_ASSERT(w.valid);
  Vec3 l = w.local;
  if (names[mi] == "radial4") l = Vec3(std::abs(l.x()), std::abs(l.y()), l.z());
  const AnyMap m = make_map(names[mi], c);
  const Point2 u = m.invert_local(l);
  const ellipse::EllipseSample back = m.sample(u, nullptr);
  RC_ASSERT(back.valid);
  const double scale = area.g.a;
  const double err = (back.local.head<2>() - l.head<2>()).norm() / scale;
  const double err_z = std::abs(back.local.z() - l.z());
  RC_LOG() << m.name << " on " << c.describe() << "\n  w=" << l.transpose() << " -> u=(" << u.x
           << ", " << u.y << ") -> w'=" << back.local.transpose() << " err_xy/a=" << err
           << " err_z=" << err_z << "\n";
  RC_ASSERT(err <= kRoundTripW);
  RC_ASSERT(err_z <= std::max(kRoundTripW * scale,
                              kRoundTripZUlps * std::numeric_limits<double>::epsilon()));
}

INSTANTIATE_TEST_SUITE_P(All, MapBijectivity, ::testing::ValuesIn(bijective_map_names()),
                         [](const auto& info) {
                           std::string s = info.param;
                           for (char& ch : s)
                             if (ch == '-') ch = '_';
                           return s;
                         });

// Degenerate geometry gives "no sample", never NaN.
TEST(MapDegenerate, NoSampleAndNoNaN) {
  const std::vector<DiskConfig> bad = {
      {"behind", Vec3(0, 0, 1), Vec3(0, 0, 1), 1.0, Vec3::Zero()},
      {"in-plane", Vec3(2, 0, 0), Vec3(0, 0, -1), 1.0, Vec3::Zero()},
      {"zero-radius", Vec3(0, 0, 1), Vec3(0, 0, -1), 0.0, Vec3::Zero()},
      {"nan-point", Vec3(0, 0, 1), Vec3(0, 0, -1), 1.0, Vec3(NAN, 0, 0)},
      {"zero-normal", Vec3(0, 0, 1), Vec3(0, 0, 0), 1.0, Vec3::Zero()},
  };
  for (const DiskConfig& c : bad) {
    for (const auto& name : bijective_map_names()) {
      const AnyMap m = make_map(name, c);
      const auto s = m.sample({0.3, 0.7}, nullptr);
      EXPECT_FALSE(s.valid) << name << " " << c.describe();
      EXPECT_FALSE(std::isnan(s.pdf)) << name << " " << c.describe();
    }
    EXPECT_FALSE(ellipse::AreaSampler::make(c.disk(), c.point).sample({0.3, 0.7}).valid);
    EXPECT_FALSE(ellipse::GamitoSampler::make(c.disk(), c.point).propose({0.3, 0.7}).valid);
    EXPECT_FALSE(ellipse::TabulatedMap::make(c.disk(), c.point).sample({0.3, 0.7}).valid);
  }
}

}  // namespace
}  // namespace disklab::test
