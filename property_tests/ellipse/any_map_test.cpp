// ellipse::AnyMap (any_map.h): the run-time dispatch by name agrees bit for bit with the map
// structs it wraps, the name list is complete and unknown names throw, every forward sample is
// contained and invertible, directions off the disk and degenerate scenes have defined answers.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include "disklab/ellipse/any_map.h"
#include "ellipse/map_common.h"

namespace disklab::test {
namespace {

using ellipse::MapKind;

// ---- tolerances (one place) ----
// Dispatch must not change a single bit: AnyMap calls the same inline code on the same inputs.
// pdf * Omega for the uniform maps: pdf = 1/Omega is one correctly rounded division, so the
// product is within 1 ulp of 1; 2 eps allows the product's own rounding.
constexpr double kUniformPdfTol = 2 * std::numeric_limits<double>::epsilon();
// invert(sample(u)) vs u through AnyMap on the moderate configurations (not far/grazing, whose
// conditioning the bijectivity suite argues separately): same budget as map_bijectivity_test's
// kRoundTripU (1e-13) times 1e3 for the parallel map's rim conditioning and the world-frame
// detour (the direction is renormalized and rotated back to the local frame, a few ulps).
constexpr double kRoundTripU = 1e-10;
// A direction pushed out of the ellipse by this relative factor in the tangent plane must be
// rejected by contains(): 1e-6 is far above its slack (kRimSlack = 1e-9 plus 16 eps / b_t <=
// 3e-8 on these configurations).
constexpr double kOutsidePush = 1e-6;
// A local coordinate this small (absolute, unit directions) is on a quadrant seam as far as a
// direction that went through world coordinates can tell: 16 eps.
constexpr double kSeamAbs = 16 * std::numeric_limits<double>::epsilon();

const std::vector<std::string> kExpectedNames = {"area",      "gamito",      "parallel",
                                                 "radial",    "ld-radial",   "radial4",
                                                 "tabulated", "radial-fast", "projected"};

bool same(const ellipse::EllipseSample& a, const ellipse::EllipseSample& b) {
  auto eq = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  for (int i = 0; i < 3; ++i)
    if (!eq(a.direction[i], b.direction[i]) || !eq(a.local[i], b.local[i]) ||
        !eq(a.point[i], b.point[i]))
      return false;
  return eq(a.pdf, b.pdf) && a.valid == b.valid;
}

std::string show(const ellipse::EllipseSample& s) {
  std::ostringstream o;
  o.precision(17);
  o << "{dir=(" << s.direction.transpose() << ") local=(" << s.local.transpose()
    << ") pdf=" << s.pdf << " valid=" << s.valid << "}";
  return o.str();
}

// The struct's own answer for u (copy k of sample4 for radial4), computed without AnyMap.
ellipse::EllipseSample direct_sample(MapKind kind, const DiskConfig& c, Point2 u, int k) {
  const auto& [center, normal, r, o] = std::tie(c.center, c.normal, c.radius, c.point);
  switch (kind) {
    case MapKind::area:
      return ellipse::AreaSampler::make(ellipse::Disk{center, normal, r, false}, o).sample(u);
    case MapKind::gamito:
      return ellipse::GamitoSampler::make(ellipse::Disk{center, normal, r, false}, o).propose(u);
    case MapKind::parallel:
      return ellipse::ParallelMap::make(ellipse::Disk{center, normal, r, false}, o).sample(u);
    case MapKind::radial:
      return ellipse::RadialMap::make(ellipse::Disk{center, normal, r, false}, o).sample(u);
    case MapKind::ld_radial:
      return ellipse::LdRadialMap::make(ellipse::Disk{center, normal, r, false}, o).sample(u);
    case MapKind::radial4:
      return ellipse::Radial4Map::make(ellipse::Disk{center, normal, r, false}, o).sample4(u)[k];
    case MapKind::tabulated:
      return ellipse::TabulatedMap::make(ellipse::Disk{center, normal, r, false}, o).sample(u);
    case MapKind::radial_fast:
      return ellipse::RadialFastMap::make(ellipse::Disk{center, normal, r, false}, o).sample(u);
    case MapKind::projected:
      return ellipse::ProjectedMap::make(ellipse::Disk{center, normal, r, false}, o).sample(u);
  }
  return {};
}

std::optional<Point2> direct_invert(MapKind kind, const DiskConfig& c, const Vec3& d) {
  const auto& [center, normal, r, o] = std::tie(c.center, c.normal, c.radius, c.point);
  switch (kind) {
    case MapKind::area:
      return ellipse::AreaSampler::make(ellipse::Disk{center, normal, r, false}, o).invert(d);
    case MapKind::gamito:
      return std::nullopt;
    case MapKind::parallel:
      return ellipse::ParallelMap::make(ellipse::Disk{center, normal, r, false}, o).invert(d);
    case MapKind::radial:
      return ellipse::RadialMap::make(ellipse::Disk{center, normal, r, false}, o).invert(d);
    case MapKind::ld_radial:
      return ellipse::LdRadialMap::make(ellipse::Disk{center, normal, r, false}, o).invert(d);
    case MapKind::radial4:  // the inverse of sample(), the radial map's
      return ellipse::Radial4Map::make(ellipse::Disk{center, normal, r, false}, o).invert(d);
    case MapKind::tabulated:
      return ellipse::TabulatedMap::make(ellipse::Disk{center, normal, r, false}, o).invert(d);
    case MapKind::radial_fast:
      return ellipse::RadialFastMap::make(ellipse::Disk{center, normal, r, false}, o).invert(d);
    case MapKind::projected:
      return ellipse::ProjectedMap::make(ellipse::Disk{center, normal, r, false}, o).invert(d);
  }
  return std::nullopt;
}

TEST(AnyMap, NamesAreCompleteUniqueAndRoundTrip) {
  EXPECT_EQ(ellipse::map_names(), kExpectedNames);
  std::set<MapKind> kinds;
  for (const auto& name : kExpectedNames) {
    const auto kind = ellipse::parse_map(name);
    ASSERT_TRUE(kind.has_value()) << name;
    EXPECT_EQ(ellipse::map_name(*kind), name);
    kinds.insert(*kind);
    const auto m = ellipse::AnyMap::make(
        name, ellipse::Disk{Vec3(0, 0, 1), Vec3(0, 0, -1), 1.0, false}, Vec3::Zero());
    EXPECT_EQ(m.kind(), *kind);
    EXPECT_EQ(m.name(), name);
  }
  EXPECT_EQ(kinds.size(), kExpectedNames.size());
}

TEST(AnyMap, UnknownNamesThrowInvalidArgument) {
  for (const std::string bad : {"", "Radial", "radial ", "ld_radial", "polar", "radial5"}) {
    EXPECT_FALSE(ellipse::parse_map(bad).has_value()) << "'" << bad << "'";
    try {
      (void)ellipse::AnyMap::make(bad, ellipse::Disk{Vec3(0, 0, 1), Vec3(0, 0, -1), 1.0, false},
                                  Vec3::Zero());
      ADD_FAILURE() << "make('" << bad << "') did not throw";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("'" + bad + "'"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("radial-fast"), std::string::npos) << e.what();
    }
  }
}

// The kind predicates describe what the maps do: copies() is what sample_copies returns,
// has_inverse() whether invert finds valid samples back, is_uniform whether every valid sample's
// pdf is 1/Omega (checked on every configuration with 64 samples each).
TEST(AnyMap, PropertiesDescribeBehaviour) {
  for (const DiskConfig& c : map_configs()) {
    for (const auto& name : kExpectedNames) {
      // projected with a receiver normal 31 degrees off the disk's direction (its cosine then
      // varies over the ellipse even for distant disks; about the centre it would be 1 - O(a^2)).
      const Vec3 dir = (c.center - c.point).normalized();
      const Vec3 n_o = (dir + 0.6 * dir.unitOrthogonal()).normalized();
      const auto m = ellipse::AnyMap::make(name, c.disk(), c.point, n_o);
      ASSERT_TRUE(m.valid()) << name << " " << c.describe();
      bool all_uniform = true, all_inverted = true;
      std::array<ellipse::EllipseSample, 4> out;
      for (int i = 0; i < 64; ++i) {
        const Point2 u{(i + 0.5) / 64, ((i * 37) % 64 + 0.5) / 64};
        EXPECT_EQ(m.sample_copies(u, out), m.copies()) << name;
        const ellipse::EllipseSample s = m.sample(u);
        if (!s.valid) continue;
        all_uniform &= std::abs(s.pdf * m.omega() - 1.0) <= kUniformPdfTol;
        all_inverted &= m.invert(s.direction).has_value();
      }
      EXPECT_EQ(m.copies() == 4, name == "radial4") << name;
      EXPECT_EQ(m.has_inverse(), all_inverted) << name << " " << c.describe();
      EXPECT_EQ(ellipse::map_is_uniform(m.kind()), all_uniform) << name << " " << c.describe();
    }
  }
}

// Dispatch == direct struct, for samples and inverses, on every configuration.
RC_GTEST_PROP(AnyMap, DispatchAgreesWithStructs, ()) {
  const auto configs = map_configs();
  const DiskConfig& c = *rc::gen::elementOf(configs);
  const std::string name = *rc::gen::elementOf(kExpectedNames);
  const Point2 u{*rc::gen::inRange(0, 1 << 30) / double(1 << 30),
                 *rc::gen::inRange(0, (1 << 30) + 1) / double(1 << 30)};
  const auto m = ellipse::AnyMap::make(name, c.disk(), c.point);
  RC_ASSERT(m.valid());
  std::array<ellipse::EllipseSample, 4> out;
  const int n = m.sample_copies(u, out);
  RC_ASSERT(n == m.copies());
  for (int k = 0; k < n; ++k) {
    const ellipse::EllipseSample d = direct_sample(m.kind(), c, u, k);
    RC_LOG() << name << " on " << c.describe() << " u=(" << u.x << ", " << u.y << ") copy " << k
             << "\n  any=" << show(out[k]) << "\n  direct=" << show(d) << "\n";
    RC_ASSERT(same(out[k], d));
    if (!d.valid) continue;
    if (m.kind() == MapKind::radial4) {
      // The copies' inverse: the same u, and which copy it was.
      int copy = -1;
      const auto back = m.invert_copy(d.direction, &copy);
      const auto r4 = ellipse::Radial4Map::make(c.disk(), c.point);
      int direct_copy = -1;
      const Point2 direct =
          r4.invert_copy_local(r4.radial.g.to_local(d.direction.normalized()), direct_copy);
      RC_ASSERT(back.has_value());
      RC_ASSERT(*back == direct);
      RC_ASSERT(copy == direct_copy);
    }
  }
  // sample(u): the full-ellipse sample (radial4's is the radial map's), and its inverse.
  const ellipse::EllipseSample one = m.sample(u);
  const ellipse::EllipseSample direct_one = m.kind() == MapKind::radial4
                                                ? direct_sample(MapKind::radial, c, u, 0)
                                                : direct_sample(m.kind(), c, u, 0);
  RC_ASSERT(same(one, direct_one));
  if (!one.valid) return;
  const auto inv = m.invert(one.direction);
  // Each struct's invert takes a unit direction, but projected's normalizes its argument itself
  // as AnyMap's does: give it the raw direction, since normalizing is not idempotent to the ulp.
  const auto dinv = direct_invert(
      m.kind(), c, m.kind() == MapKind::projected ? one.direction : one.direction.normalized());
  RC_ASSERT(inv.has_value() == m.has_inverse());
  if (inv) RC_ASSERT(*inv == *dinv);
}

// Every valid forward sample, rim included (v = 1), is inside the disk (contains), and for the
// invertible maps invert() finds it back; the direction's length does not matter.
RC_GTEST_PROP(AnyMap, SamplesAreContainedAndInvertible, ()) {
  const auto configs = map_configs();
  const DiskConfig& c = *rc::gen::elementOf(configs);
  const std::string name = *rc::gen::elementOf(kExpectedNames);
  // One case in three on the rim (v = 1), where contains() works at its slack.
  const double v =
      *rc::gen::inRange(0, 3) == 0 ? 1.0 : *rc::gen::inRange(0, 1 << 30) / double(1 << 30);
  const Point2 u{*rc::gen::inRange(1, 1 << 30) / double(1 << 30), v};
  const auto m = ellipse::AnyMap::make(name, c.disk(), c.point);
  std::array<ellipse::EllipseSample, 4> out;
  const int n = m.sample_copies(u, out);
  for (int k = 0; k < n; ++k) {
    const ellipse::EllipseSample& s = out[k];
    RC_LOG() << name << " on " << c.describe() << " u=(" << u.x << ", " << u.y << ") copy " << k
             << " -> " << show(s) << "\n";
    RC_ASSERT(std::isfinite(s.pdf) && s.pdf >= 0.0);
    if (!s.valid) continue;
    RC_ASSERT(m.contains(s.direction));
    RC_ASSERT(m.contains(7.5 * s.direction));
    if (ellipse::map_is_uniform(m.kind()))
      RC_ASSERT(std::abs(s.pdf * m.omega() - 1.0) <= kUniformPdfTol);
    if (!m.has_inverse()) {
      RC_ASSERT(!m.invert(s.direction).has_value());
      continue;
    }
    // Copies come back through invert_copy (radial4: the first-quadrant u and the copy index).
    int copy = -1;
    const auto back = m.invert_copy(s.direction, &copy);
    const auto back_scaled = m.invert_copy(1e-3 * s.direction);
    RC_ASSERT(back.has_value() && back_scaled.has_value());
    // On a quadrant seam (a local x or y within the world round trip's rounding, ~eps of the
    // unit direction: far disks' copies there coincide) the neighbouring copy is as right.
    const Vec3 l = m.geometry().to_local(s.direction);
    const bool on_seam = std::min(std::abs(l.x()), std::abs(l.y())) <= kSeamAbs;
    RC_ASSERT(copy == k || (on_seam && (out[copy].direction - s.direction).norm() <= kSeamAbs));
    RC_LOG() << "  -> u'=(" << back->x << ", " << back->y << ")\n";
    RC_ASSERT(back->x >= 0.0 && back->x <= 1.0 && back->y >= 0.0 && back->y <= 1.0);
    // The round trip in u on configurations with moderate conditioning: u.y away from 0 (eps1
    // is undefined at the ellipse centre) and u.x away from the parallel map's slice ends.
    const bool moderate = c.name == "on-axis-unit" || c.name == "tilted-mid";
    if (moderate && u.y > 1e-3 && u.x > 1e-3 && u.x < 1 - 1e-3) {
      RC_ASSERT(std::abs(back->y - u.y) <= kRoundTripU);
      RC_ASSERT(std::abs(back->x - u.x) <= kRoundTripU);
    }
  }
}

// Directions off the disk: behind the point, and just outside the rim in the tangent plane.
RC_GTEST_PROP(AnyMap, DirectionsOffTheDiskAreRejected, ()) {
  const auto configs = map_configs();
  const DiskConfig& c = *rc::gen::elementOf(configs);
  const std::string name = *rc::gen::elementOf(kExpectedNames);
  const double t = *rc::gen::inRange(0, 1 << 20) / double(1 << 20) * 2 * math::kPi;
  const auto m = ellipse::AnyMap::make(name, c.disk(), c.point);
  const ellipse::MapGeometry& g = m.geometry();
  // A rim point of the tangent ellipse (a_t cos t, b_t sin t, 1), pushed outwards.
  const Vec3 rim_out(g.a_t * std::cos(t) * (1 + kOutsidePush),
                     g.b_t * std::sin(t) * (1 + kOutsidePush), 1.0);
  const Vec3 rim_in(g.a_t * std::cos(t) * (1 - kOutsidePush),
                    g.b_t * std::sin(t) * (1 - kOutsidePush), 1.0);
  const Vec3 out_world = g.to_world(rim_out), in_world = g.to_world(rim_in);
  RC_LOG() << name << " on " << c.describe() << " t=" << t << "\n";
  // The world-frame rotation rounds the tiny local offsets of far ellipses (relative error
  // ~eps / b_t); the push only resolves when it exceeds that.
  if (kOutsidePush > 1e3 * std::numeric_limits<double>::epsilon() / g.b_t) {
    RC_ASSERT(!m.contains(out_world));
    RC_ASSERT(!m.invert(out_world).has_value());
    RC_ASSERT(m.contains(in_world));
    RC_ASSERT(m.invert(in_world).has_value() == m.has_inverse());
  }
  RC_ASSERT(!m.contains(-in_world));
  RC_ASSERT(!m.invert(-in_world).has_value());
  RC_ASSERT(!m.contains(Vec3::Zero()));
  RC_ASSERT(!m.contains(Vec3(std::nan(""), 0, 1)));
}

// Degenerate scenes: no sample, zero pdf and solid angle, no inverse, never NaN.
TEST(AnyMap, DegenerateGeometryHasDefinedAnswers) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Scene {
    const char* what;
    Vec3 c, n;
    double r;
    Vec3 o;
  };
  const std::vector<Scene> scenes = {
      {"behind the one-sided disk", Vec3(0, 0, 1), Vec3(0, 0, 1), 1.0, Vec3::Zero()},
      {"in the disk's plane", Vec3(0, 0, 0), Vec3(0, 0, 1), 1.0, Vec3(3, 0, 0)},
      {"radius 0", Vec3(0, 0, 1), Vec3(0, 0, -1), 0.0, Vec3::Zero()},
      {"negative radius", Vec3(0, 0, 1), Vec3(0, 0, -1), -1.0, Vec3::Zero()},
      {"zero normal", Vec3(0, 0, 1), Vec3::Zero(), 1.0, Vec3::Zero()},
      {"NaN centre", Vec3(nan, 0, 1), Vec3(0, 0, -1), 1.0, Vec3::Zero()},
  };
  for (const auto& sc : scenes) {
    for (const auto& name : kExpectedNames) {
      const auto m = ellipse::AnyMap::make(name, ellipse::Disk{sc.c, sc.n, sc.r, false}, sc.o);
      SCOPED_TRACE(name + " " + sc.what);
      EXPECT_FALSE(m.valid());
      EXPECT_EQ(m.omega(), 0.0);
      std::array<ellipse::EllipseSample, 4> out;
      const int n = m.sample_copies({0.3, 0.7}, out);
      for (int k = 0; k < n; ++k) {
        EXPECT_FALSE(out[k].valid);
        EXPECT_EQ(out[k].pdf, 0.0);
        EXPECT_TRUE(out[k].direction.allFinite());
      }
      EXPECT_FALSE(m.contains(Vec3(0, 0, 1)));
      EXPECT_FALSE(m.invert(Vec3(0, 0, 1)).has_value());
    }
  }
}

}  // namespace
}  // namespace disklab::test
