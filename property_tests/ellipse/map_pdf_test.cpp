// pdf(direction) of every spherical-ellipse map (any_map.h), what multiple importance sampling
// needs: it equals what sample() reports for the same direction, vanishes off the disk, and
// integrates over the sphere to 1 (uniform maps and area) or to the acceptance rate of a
// single-shot proposal (gamito, tabulated). Also: two-sided lights in every map, and the size of
// the samplers.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "disklab/ellipse/any_map.h"
#include "disklab/math/constants.h"
#include "disklab/sequence/random.h"
#include "ellipse/map_common.h"

namespace disklab::test {
namespace {

using ellipse::AnyMap;
using ellipse::MapKind;

// ---- tolerances and sizes (one place) ----
constexpr double kEps = std::numeric_limits<double>::epsilon();
// area: sample() forms |x - o|^2 / (A cos) from the local-frame offset, pdf(direction) from the
// hit point of the world direction; each is a few roundings of |x - o|^2 and of cos(theta_l),
// whose relative error is ~eps / cos: 1e-12 covers cos >= 1e-3 (the grazing configuration's
// smallest is ~0.02).
constexpr double kAreaPdfRel = 1e-12;
// A tabulated sample exactly on a table cell's edge may be found in the neighbouring cell by
// pdf(direction) (the inverse has the same property): within this many radians of an edge
// either cell's density is accepted.
constexpr double kCellEdgeSlack = 1e-12;
// Quadrature of pdf over the sphere, in the tangent-ellipse coordinates of the geometry (not of
// any map): (x, y) = (a_t rho cos psi, b_t rho sin psi) on the plane z_e = 1, where the rim is
// rho = 1, a cell edge, and dw = a_t b_t rho drho dpsi / (1 + x^2 + y^2)^(3/2). A midpoint grid;
// its error is estimated from the same grid at half the resolution (O(h^2): the difference over
// 3), and cells whose corners disagree with their centre on the density (tabulated's cell
// edges, or containment where rounding puts the rim off the cell edge) add the spread of their
// densities times their solid angle. A ring of cells outside the rim checks that the density
// vanishes there.
constexpr int kRhoCells = 160, kPsiCells = 320, kOutsideRhoCells = 16;
constexpr double kOutsideRho = 1.1;
// A two-sided disk seen from behind: the mirrored scene's solid angle is computed from mirrored
// (rounded) coordinates, a few ulps apart; its samples hit the disk to the maps' rim slack.
constexpr double kMirroredOmegaRel = 1e-12;
constexpr double kHitRimRel = 1e-9;
// pdf(out) must be 0 for a direction pushed this far outside the rim (relative, in the tangent
// plane: far above contains()'s slack), where the world-frame rotation resolves it.
constexpr double kOutsidePush = 1e-6;
// The largest sampler must stay under this (issue: renderers keep one per shading point).
constexpr std::size_t kMaxSamplerBytes = 512;

const std::vector<std::string> kNames = {"area",      "gamito",  "parallel",  "radial",
                                         "ld-radial", "radial4", "tabulated", "radial-fast"};

AnyMap make(const std::string& name, const DiskConfig& c) {
  return AnyMap::make(*ellipse::parse_map(name), c.disk(), c.point);
}

// Whether a direction's first-quadrant azimuth lies on a tabulated cell edge, to within what the
// round trip through world coordinates can move it: kCellEdgeSlack, plus an absolute error ~eps
// in the local x, y, i.e. eps / rho in azimuth at distance rho from the ellipse's centre (where
// every cell meets and the azimuth is undefined).
bool near_cell_edge(const AnyMap& m, const Vec3& direction) {
  const auto& t = std::get<ellipse::TabulatedMap>(m.variant());
  const Vec3 l = t.g.to_local(direction.normalized());
  const double phi = std::atan2(std::abs(l.y()), std::abs(l.x()));
  const double rho = std::hypot(l.x(), l.y());
  const double slack = kCellEdgeSlack + 16 * kEps / rho;
  for (int j = 0; j <= t.table->n_eps; ++j)
    if (std::abs(phi - t.phi_at(j)) <= slack) return true;
  return false;
}

RC_GTEST_PROP(MapPdf, PdfOfASampleIsItsPdf, ()) {
  const auto configs = map_configs();
  const DiskConfig& c = *rc::gen::elementOf(configs);
  const std::string name = *rc::gen::elementOf(kNames);
  const Point2 u{*rc::gen::inRange(0, 1 << 30) / double(1 << 30),
                 *rc::gen::inRange(0, (1 << 30) + 1) / double(1 << 30)};
  const AnyMap m = make(name, c);
  // sample(u), then every copy of sample_copies(u) (radial4's four reflections).
  std::vector<ellipse::EllipseSample> samples{m.sample(u)};
  std::array<ellipse::EllipseSample, 4> copies;
  const int n = m.sample_copies(u, copies);
  samples.insert(samples.end(), copies.begin(), copies.begin() + n);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const ellipse::EllipseSample& s = samples[k];
    if (!s.valid) continue;
    const double p = m.pdf(s.direction);
    RC_LOG() << name << " on " << c.describe() << " u=(" << u.x << ", " << u.y << ") sample " << k
             << ": sample pdf " << s.pdf << ", pdf(direction) " << p << "\n";
    if (name == "area") {
      RC_ASSERT(std::abs(p - s.pdf) <= kAreaPdfRel * s.pdf);
    } else if (name == "tabulated" && p != s.pdf) {
      RC_ASSERT(near_cell_edge(m, s.direction));
    } else {
      RC_ASSERT(p == s.pdf);
    }
    // The length of the direction does not matter (area renormalizes it: a few ulps).
    const double scaled = m.pdf(1e-3 * s.direction);
    if (name == "area")
      RC_ASSERT(std::abs(scaled - p) <= kAreaPdfRel * p);
    else if (name == "tabulated" && scaled != p)
      RC_ASSERT(near_cell_edge(m, s.direction));
    else
      RC_ASSERT(scaled == p);
  }
}

RC_GTEST_PROP(MapPdf, PdfIsZeroOffTheDisk, ()) {
  const auto configs = map_configs();
  const DiskConfig& c = *rc::gen::elementOf(configs);
  const std::string name = *rc::gen::elementOf(kNames);
  const double t = *rc::gen::inRange(0, 1 << 20) / double(1 << 20) * 2 * math::kPi;
  const AnyMap m = make(name, c);
  const ellipse::MapGeometry& g = m.geometry();
  // A rim point of the tangent ellipse pushed outwards, and one well inside.
  const Vec3 out = g.to_world(
      Vec3(g.a_t * std::cos(t) * (1 + kOutsidePush), g.b_t * std::sin(t) * (1 + kOutsidePush), 1));
  const Vec3 in = g.to_world(Vec3(g.a_t * std::cos(t) * 0.999, g.b_t * std::sin(t) * 0.999, 1));
  RC_LOG() << name << " on " << c.describe() << " t=" << t << "\n";
  if (kOutsidePush > 1e3 * kEps / g.b_t) RC_ASSERT(m.pdf(out) == 0.0);
  RC_ASSERT(m.pdf(in) > 0.0);
  RC_ASSERT(m.pdf(-in) == 0.0);
  RC_ASSERT(m.pdf(Vec3::Zero()) == 0.0);
  RC_ASSERT(m.pdf(Vec3(std::nan(""), 0.0, 1.0)) == 0.0);
}

// What the pdf must integrate to: 1, or the acceptance rate computed without the sampler's pdf:
// gamito's Omega / S (S the spherical square's solid angle); tabulated's sum over its cells of
// (1/n) (solid angle of the ellipse in the cell's sector, from solid_angle.h) / (the sector's
// solid angle dphi (1 - h_r(phi_j)), the Hat-Box area of the proposal).
double expected_total(const AnyMap& m) {
  if (m.kind() == MapKind::gamito) {
    const auto& gs = std::get<ellipse::GamitoSampler>(m.variant());
    return gs.g.omega / gs.rect.S;
  }
  if (m.kind() == MapKind::tabulated) {
    const auto& t = std::get<ellipse::TabulatedMap>(m.variant());
    const int n = t.table->n_eps;
    double sum = 0.0;
    for (int j = 0; j < n; ++j) {
      const double p0 = t.phi_at(j), p1 = t.phi_at(j + 1);
      const double inside = t.g.radial_sector(p1) - t.g.radial_sector(p0);
      sum += inside / ((p1 - p0) * t.g.one_minus_hr(p0)) / n;
    }
    return sum;
  }
  return 1.0;
}

struct Quadrature {
  double value = 0.0, band = 0.0, outside = 0.0;
};

Quadrature integrate_pdf(const AnyMap& m, int rho_cells, int psi_cells) {
  const ellipse::MapGeometry& g = m.geometry();
  const double drho = 1.0 / rho_cells, dpsi = math::kTwoPi / psi_cells;
  const int outside_cells = kOutsideRhoCells * rho_cells / kRhoCells;
  const double drho_out = (kOutsideRho - 1.0) / outside_cells;
  auto dir = [&](double rho, double psi) {
    return g.to_world(Vec3(g.a_t * rho * std::cos(psi), g.b_t * rho * std::sin(psi), 1.0));
  };
  auto jacobian = [&](double rho, double psi) {
    const double x = g.a_t * rho * std::cos(psi), y = g.b_t * rho * std::sin(psi);
    const double q = 1.0 + x * x + y * y;
    return g.a_t * g.b_t * rho / (q * std::sqrt(q));
  };
  const bool smooth = m.kind() == MapKind::area;
  Quadrature out;
  for (int i = 0; i < rho_cells + outside_cells; ++i) {
    const bool inside = i < rho_cells;
    const double r0 = inside ? i * drho : 1.0 + (i - rho_cells) * drho_out;
    const double dr = inside ? drho : drho_out, rm = r0 + 0.5 * dr;
    for (int j = 0; j < psi_cells; ++j) {
      const double p0 = j * dpsi, pm = p0 + 0.5 * dpsi;
      const double measure = jacobian(rm, pm) * dr * dpsi;
      const double centre = m.pdf(dir(rm, pm));
      if (!inside) {
        out.outside += centre * measure;
        continue;
      }
      const double corners[4] = {m.pdf(dir(r0, p0)), m.pdf(dir(r0, p0 + dpsi)),
                                 m.pdf(dir(r0 + dr, p0)), m.pdf(dir(r0 + dr, p0 + dpsi))};
      // The integral over the cell lies between its smallest and largest density times its
      // measure where the density jumps inside it: at the rim (a corner outside), and for the
      // tabulated map at its cells' edges (small steps between neighbours). area's density is
      // smooth inside: only the rim counts, the rest is the midpoint rule's O(h^2).
      bool rim = false, step = false;
      double top = centre, bottom = centre;
      for (double x : corners) {
        rim |= (x > 0.0) != (centre > 0.0);
        step |= x != centre;
        top = std::max(top, x);
        bottom = std::min(bottom, x);
      }
      out.value += centre * measure;
      if (rim || (step && !smooth)) out.band += (top - bottom) * measure;
    }
  }
  return out;
}

TEST(MapPdf, IntegratesToOneOrTheAcceptanceRate) {
  for (const DiskConfig& c : map_configs()) {
    for (const std::string& name : kNames) {
      const AnyMap m = make(name, c);
      ASSERT_TRUE(m.valid()) << name << " on " << c.describe();
      const Quadrature fine = integrate_pdf(m, kRhoCells, kPsiCells);
      const Quadrature coarse = integrate_pdf(m, kRhoCells / 2, kPsiCells / 2);
      const double expected = expected_total(m);
      const double error = std::abs(fine.value - coarse.value) / 3.0 + fine.band;
      std::printf("  %-11s %-13s integral %.9f expected %.9f error estimate %.1e\n", name.c_str(),
                  c.name.c_str(), fine.value, expected, error);
      EXPECT_LE(std::abs(fine.value - expected), 2.0 * error + 64 * kEps * expected)
          << name << " on " << c.describe();
      EXPECT_EQ(fine.outside, 0.0) << name << " on " << c.describe();
    }
  }
}

// A two-sided disk seen from behind is the mirror image of the one-sided disk seen from the
// front: the same solid angle, and every map samples it (the one-sided one sees nothing).
TEST(MapPdf, TwoSidedLightsWorkInEveryMap) {
  for (const DiskConfig& front : map_configs()) {
    DiskConfig back = front;
    // Mirror the point through the disk's plane.
    const Vec3 n = front.normal.normalized();
    back.point = front.point - 2.0 * (front.point - front.center).dot(n) * n;
    back.two_sided = true;
    DiskConfig one_sided_back = back;
    one_sided_back.two_sided = false;
    sequence::Pcg32 rng(77);
    for (const std::string& name : kNames) {
      const AnyMap a = make(name, front), b = make(name, back);
      EXPECT_FALSE(make(name, one_sided_back).valid()) << name << " " << back.describe();
      ASSERT_TRUE(b.valid()) << name << " " << back.describe();
      EXPECT_NEAR(b.omega(), a.omega(), kMirroredOmegaRel * a.omega())
          << name << " " << back.describe();
      for (int i = 0; i < 64; ++i) {
        const ellipse::EllipseSample s = b.sample({rng.next_double(), rng.next_double()});
        if (!s.valid) continue;
        // The direction meets the disk from the back side.
        const double t = (back.center - back.point).dot(n) / s.direction.dot(n);
        const Vec3 hit = back.point + t * s.direction;
        EXPECT_GT(t, 0.0) << name;
        EXPECT_LE((hit - back.center).norm(), back.radius * (1.0 + kHitRimRel)) << name;
        EXPECT_GT(b.pdf(s.direction), 0.0) << name;
      }
    }
  }
}

TEST(MapPdf, SamplersAreSmall) {
  std::printf(
      "  sizeof: AnyMap %zu, area %zu, gamito %zu, parallel %zu, radial %zu, ld-radial %zu, "
      "radial4 %zu, tabulated %zu, radial-fast %zu\n",
      sizeof(AnyMap), sizeof(ellipse::AreaSampler), sizeof(ellipse::GamitoSampler),
      sizeof(ellipse::ParallelMap), sizeof(ellipse::RadialMap), sizeof(ellipse::LdRadialMap),
      sizeof(ellipse::Radial4Map), sizeof(ellipse::TabulatedMap), sizeof(ellipse::RadialFastMap));
  EXPECT_LT(sizeof(AnyMap), kMaxSamplerBytes);
}

}  // namespace
}  // namespace disklab::test
