// The projected-solid-angle map (ellipse/projected.h): P against the 50-digit table
// reference/projected_P.csv (a quadrature that shares nothing with the map), zero variance for a
// Lambertian receiver, pdf and inverse against sample, and equal projected solid angle for every
// stratum image, on unclipped, straddling (clipped by the receiver's horizon) and distant
// configurations.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "disklab/ellipse/any_map.h"
#include "disklab/ellipse/contracts.h"
#include "disklab/ellipse/projected.h"
#include "disklab/math/constants.h"
#include "disklab/sequence/random.h"
#include "ellipse/map_common.h"
#include "reference_csv.h"
#include "support/stats.h"

namespace {
using disklab::Point2;
using disklab::Vec3;
namespace ellipse = disklab::ellipse;

struct Config {
  std::string name;
  ellipse::Disk disk;
  Vec3 point, receiver_normal;
};

// Unclipped from 1e-6 to 1e8 radii, straddling the horizon at several depths, the centre
// exactly on the horizon, mostly below it, two-sided from behind.
std::vector<Config> configs() {
  const Vec3 tilt = Vec3(0.3, 0.2, 1.0).normalized();
  return {
      {"overhead", {Vec3(0, 0, 2), Vec3(0, 0, -1), 1.0, false}, Vec3::Zero(), Vec3::UnitZ()},
      {"off-axis", {Vec3(0, 0, 2), Vec3(0, 0, -1), 1.0, false}, Vec3(1.5, 0.3, 0), Vec3::UnitZ()},
      {"vertical", {Vec3(0, 0, 0.6), Vec3(1, 0, 0), 0.5, true}, Vec3(0.3, 0.1, 0), Vec3::UnitZ()},
      {"near-1e-6", {Vec3(0, 0, 1e-6), Vec3(0, 0, -1), 1.0, false}, Vec3(0.3, 0.2, 0), tilt},
      {"far-1e4",
       {Vec3(3e3, 2e3, 1e4), Vec3(0.3, -0.2, -1).normalized(), 1.0, false},
       Vec3::Zero(),
       Vec3(0.1, 0.2, 1).normalized()},
      {"far-1e8",
       {Vec3(3e7, 2e7, 1e8), Vec3(0.3, -0.2, -1).normalized(), 1.0, false},
       Vec3::Zero(),
       Vec3(0.1, 0.2, 1).normalized()},
      {"straddle-low",
       {Vec3(0, 0, 0.3), Vec3(1, 0, 0), 0.5, true},
       Vec3(0.3, 0.1, 0),
       Vec3::UnitZ()},
      {"straddle-half",
       {Vec3(0, 0, 0), Vec3(1, 0, 0), 0.5, true},
       Vec3(0.5, 0.1, 0),
       Vec3::UnitZ()},
      {"straddle-deep",
       {Vec3(0, 0, -0.3), Vec3(1, 0, 0), 0.5, true},
       Vec3(0.3, 0.1, 0),
       Vec3::UnitZ()},
      {"straddle-tilted",
       {Vec3(0, 0, 0.1), Vec3(0.3, 0.2, 1).normalized(), 0.5, true},
       Vec3(0.2, 0.1, 0.5),
       Vec3(0.3, 1, 0.2).normalized()},
      {"straddle-far",
       {Vec3(0, 0, 0.2), Vec3(1, 0, 1).normalized(), 1.0, true},
       Vec3(20, 3, 0),
       Vec3::UnitZ()},
  };
}

ellipse::ProjectedMap make(const Config& c) {
  return ellipse::ProjectedMap::make(c.disk, c.point, c.receiver_normal);
}

// Tolerance of P against the 50-digit reference table (reference/projected_P.csv, which holds
// this suite's configurations as its "suite" rows): the 1e-14 on every row. Unclipped,
// P = pi a b n_z with a, b to a few ulps and n_z compensated. Clipped, the reduced boundary form
// (projected.h) sums terms of the size of P itself, each to a few ulps, even where a small
// ellipse straddles the horizon (P ~ a^3); the elementary form it replaced lost eps / a^2 there.
constexpr double kProjectedTarget = 1e-14;

struct TableResult {
  const disklab::reference::ProjectedRow* row = nullptr;
  ellipse::ProjectedMap map;
  double rel = 0.0;
};

std::vector<TableResult> evaluate_table(const std::vector<disklab::reference::ProjectedRow>& rows) {
  std::vector<TableResult> out;
  for (const auto& t : rows) {
    const ellipse::Disk disk{Vec3(t.center[0], t.center[1], t.center[2]),
                             Vec3(t.normal[0], t.normal[1], t.normal[2]), t.radius, t.two_sided};
    const Vec3 o(t.point[0], t.point[1], t.point[2]);
    const Vec3 n_o(t.receiver_normal[0], t.receiver_normal[1], t.receiver_normal[2]);
    TableResult r;
    r.row = &t;
    r.map = ellipse::ProjectedMap::make(disk, o, n_o);
    const long double ref = std::strtold(t.p_text.c_str(), nullptr);
    r.rel =
        ref > 0
            ? static_cast<double>(
                  std::fabs(static_cast<long double>(r.map.projected_solid_angle()) - ref) / ref)
            : 0.0;
    out.push_back(r);
  }
  return out;
}

std::vector<disklab::reference::ProjectedRow> projected_table() {
  return disklab::reference::read_projected_table(std::filesystem::path(DISKLAB_REFERENCE_DIR) /
                                                  "projected_P.csv");
}

TEST(Projected, ProjectedSolidAngleMatchesTheReferenceTable) {
  // Every row of reference/projected_P.csv (1e-6 to 1e8 radii, tilted, straddling near and far,
  // grazing, scaled, random) within 1e-14; rows with P = 0 give no map. Prints the worst per form.
  const auto rows = projected_table();
  ASSERT_GE(rows.size(), 100u);
  int unclipped = 0, clipped = 0, small_clipped = 0;
  double worst_unclipped = 0.0, worst_clipped = 0.0;
  for (const TableResult& r : evaluate_table(rows)) {
    const auto& t = *r.row;
    const ellipse::ProjectedMap& m = r.map;
    const std::string where = "row " + std::to_string(t.id) + " (" + t.category + ")";
    // The table's own claim: at least 32 digits.
    EXPECT_LE(t.quad_error, 1e-32) << where;
    if (t.p == 0.0) {
      EXPECT_FALSE(m.valid()) << where;
      EXPECT_EQ(m.projected_solid_angle(), 0.0) << where;
      continue;
    }
    ASSERT_TRUE(m.valid()) << where;
    (m.clipped ? clipped : unclipped) += 1;
    if (m.clipped && m.g.a < 5e-3) ++small_clipped;
    double& worst = m.clipped ? worst_clipped : worst_unclipped;
    worst = std::max(worst, r.rel);
    EXPECT_LE(r.rel, kProjectedTarget)
        << where << " distance " << t.distance << " a " << m.g.a << " clipped " << m.clipped
        << " P " << m.P << " reference " << t.p_text;
  }
  std::printf("  %zu rows: %d unclipped (worst %.2e), %d clipped (worst %.2e; %d with a < 5e-3)\n",
              rows.size(), unclipped, worst_unclipped, clipped, worst_clipped, small_clipped);
  EXPECT_GT(unclipped, 0);
  // The table must exercise what was hard: small ellipses straddling the horizon (1e3 to 1e8
  // radii away), where the previous elementary form lost eps / a^2.
  EXPECT_GE(small_clipped, 8);
}

// Small ellipses straddling the receiver's horizon, 1e4 to 1e8 radii away (a = 1e-4 .. 1e-8):
// P ~ a^3 there, the case the reduced boundary form exists for. Exact inputs on the horizon
// (c - o and n_o representable) and a tilted one with rounded inputs.
std::vector<Config> small_straddling_configs() {
  return {
      {"straddle-1e4",
       {Vec3(1e4, 0, 0.25), Vec3(-1, 0, 0), 1.0, false},
       Vec3::Zero(),
       Vec3::UnitZ()},
      {"straddle-1e6-below",
       {Vec3(1e6, 0, -0.3), Vec3(-1, 0, 0), 1.0, false},
       Vec3::Zero(),
       Vec3::UnitZ()},
      {"straddle-1e8-tilted",
       {Vec3(6e7, 8e7, 0.3), Vec3(-0.6, -0.8, 0.5), 1.0, false},
       Vec3::Zero(),
       Vec3(0.8, -0.6, 0.5)},
  };
}

TEST(Projected, SmallStraddlingEllipsesAreSampledConsistently) {
  // Every sample valid, inside the disk's solid angle and above the horizon (in R_e, where the
  // map works: the world direction's rounding, ~eps, is ~eps / a of these cosines), meeting the
  // contracts (ellipse/contracts.h); and the map's two fractions read back from the local
  // direction. u.x goes through the cumulative C(s) / P and back: with C's terms as small as P each
  // costs a few ulps of P, and s's rounding moves C by ~eps s C' ~ eps P: kAzimuthRoundTrip. u.y
  // goes through F(t) on the meridian; near the horizon (kind 3's t_lo) F is flat, so t -> u.y is
  // well conditioned there: the same bound.
  constexpr double kAzimuthRoundTrip = 1e-12;
  for (const Config& c : small_straddling_configs()) {
    const ellipse::ProjectedMap m = make(c);
    const auto any =
        ellipse::AnyMap::make(ellipse::MapKind::projected, c.disk, c.point, c.receiver_normal);
    ASSERT_TRUE(m.valid()) << c.name;
    EXPECT_TRUE(m.clipped) << c.name;
    EXPECT_LT(m.g.a, 2e-4) << c.name;
    disklab::sequence::Pcg32 rng(17);
    double worst_x = 0.0, worst_y = 0.0;
    for (int i = 0; i < 20000; ++i) {
      const Point2 u{rng.next_double(), rng.next_double()};
      const ellipse::EllipseSample smp = m.sample(u);
      ASSERT_TRUE(smp.valid) << c.name << " u " << u.x << "," << u.y;
      EXPECT_TRUE(m.g.contains(smp.direction)) << c.name;
      EXPECT_GT(smp.local.dot(m.n), 0.0) << c.name;
      // The contracts' checker: pdf(direction) within the cosine's resolution, among others.
      EXPECT_EQ(ellipse::check_sample(any, smp), ellipse::Violation::none) << c.name;
      const Point2 back = m.invert_local(smp.local);
      worst_x = std::max(worst_x, std::abs(back.x - u.x));
      worst_y = std::max(worst_y, std::abs(back.y - u.y));
    }
    std::printf("  %s: a %.2g P %.3g, round trip u.x %.2e u.y %.2e\n", c.name.c_str(), m.g.a, m.P,
                worst_x, worst_y);
    EXPECT_LE(worst_x, kAzimuthRoundTrip) << c.name;
    EXPECT_LE(worst_y, kAzimuthRoundTrip) << c.name;
  }
}

TEST(Projected, RootSolvesMeetTheirTolerance) {
  // The azimuth solve (Halley with the series' derivatives where there is one, Newton on the
  // clipped pieces) and the altitude solve (Halley, in x = t - t_lo) stop at kProjectedNewtonTol
  // of their totals,
  // some steps without an evaluation at their end (their predicted residual): recomputed here,
  // the residual is that tolerance plus the rounding of one evaluation of C or G (a few ulps of
  // the total: kEvalRounding; G's terms share a sign on the horizon's meridians).
  constexpr double kEvalRounding = 8 * std::numeric_limits<double>::epsilon();
  auto cfgs = configs();
  for (const Config& c : small_straddling_configs())
    cfgs.push_back(c);
  for (const Config& c : cfgs) {
    const ellipse::ProjectedMap m = make(c);
    disklab::sequence::Pcg32 rng(23);
    double worst_s = 0.0, worst_t = 0.0;
    for (int i = 0; i < 20000; ++i) {
      const double u1 = rng.next_double(), u2 = rng.next_double();
      const double s = m.solve_s(u1, nullptr).s;
      const double target = u1 * 2.0 * m.P;
      // Clipped pieces can sum terms larger than P: their rounding, measured as the spread of C
      // over s's neighbouring doubles (where C itself moves by ~1e-16 of its slope), is what the
      // solve cannot go below; it is subtracted (unclipped, the series' terms are below P).
      double lo_c = HUGE_VAL, hi_c = -HUGE_VAL, sn = s;
      for (int k = 0; k < 4; ++k)
        sn = std::nextafter(sn, -HUGE_VAL);
      for (int k = 0; k < 9; ++k, sn = std::nextafter(sn, HUGE_VAL)) {
        const double c2 = m.twice_c(sn);
        lo_c = std::min(lo_c, c2), hi_c = std::max(hi_c, c2);
      }
      const double noise = m.clipped ? hi_c - lo_c : 0.0;
      worst_s = std::max(worst_s, (std::abs(m.twice_c(s) - target) - noise) / (2.0 * m.P));
      const auto md = m.meridian(s, m.clipped ? m.pieces.kind[m.piece_of(s)] : 1);
      if (!(md.t_hi > md.t_lo)) continue;
      int evals = 0;
      const double x = m.solve_x(md, u2, &evals).s;
      worst_t = std::max(worst_t, std::abs(m.G(md, x) - u2 * m.G_range(md)) / m.G_range(md));
    }
    EXPECT_LE(worst_s, ellipse::kProjectedNewtonTol + kEvalRounding) << c.name;
    EXPECT_LE(worst_t, ellipse::kProjectedNewtonTol + kEvalRounding) << c.name;
  }
}

TEST(Projected, ZeroVarianceForALambertianReceiver) {
  // f / pdf = L (w . n_o) / pdf = L P for every valid sample, which must also meet the disk
  // above the horizon: the relative standard deviation over 1e4 samples is rounding only.
  for (const Config& c : configs()) {
    const ellipse::ProjectedMap m = make(c);
    disklab::sequence::Pcg32 rng(5);
    std::vector<double> values;
    for (int i = 0; i < 10000; ++i) {
      const ellipse::EllipseSample s = m.sample({rng.next_double(), rng.next_double()});
      ASSERT_TRUE(s.valid) << c.name;
      ASSERT_TRUE(m.g.contains(s.direction)) << c.name;
      const double cosine = s.direction.dot(c.receiver_normal.normalized());
      ASSERT_GT(cosine, 0.0) << c.name;
      values.push_back(cosine / s.pdf);
    }
    double mean = 0.0, ss = 0.0;
    for (double v : values)
      mean += v;
    mean /= static_cast<double>(values.size());
    for (double v : values)
      ss += (v - mean) * (v - mean);
    const double sd = std::sqrt(ss / static_cast<double>(values.size() - 1));
    EXPECT_LE(sd / mean, 1e-12) << c.name;
    EXPECT_NEAR(mean, m.P, 1e-12 * m.P) << c.name;
  }
}

TEST(Projected, PdfAndInverseAgreeWithSample) {
  // pdf(sample(u)) = max(0, w . n_o) / P to 1e-12. invert_local(sample(u).local) = u to the
  // radial map's standard, 1e-13 (map_bijectivity_test.cpp's kRoundTripU: both solves stop at
  // 1e-15 of their totals and the inverse re-evaluates the same functions), where the cosine is
  // above 1e-3 (eps2's inverse is conditioned like 1 / cosine near the horizon); through the
  // world direction, whose rounding (~eps) is ~eps / b_t of the ellipse, to 1e-9 + 16 eps / b_t.
  for (const Config& c : configs()) {
    const ellipse::ProjectedMap m = make(c);
    const auto any =
        ellipse::AnyMap::make(ellipse::MapKind::projected, c.disk, c.point, c.receiver_normal);
    disklab::sequence::Pcg32 rng(6);
    double worst = 0.0, worst_world = 0.0;
    for (int i = 0; i < 4000; ++i) {
      const Point2 u{rng.next_double(), rng.next_double()};
      const ellipse::EllipseSample s = m.sample(u);
      ASSERT_TRUE(s.valid);
      const double cosine = s.direction.dot(c.receiver_normal.normalized());
      EXPECT_NEAR(s.pdf, cosine / m.P, 1e-12 * s.pdf) << c.name;
      EXPECT_NEAR(any.pdf(s.direction), s.pdf, 1e-12 * s.pdf) << c.name;
      const auto back = any.invert(s.direction);
      ASSERT_TRUE(back.has_value()) << c.name;
      const Point2 local = m.invert_local(s.local);
      if (cosine > 1e-3) {
        worst = std::max({worst, std::abs(local.x - u.x), std::abs(local.y - u.y)});
        worst_world = std::max({worst_world, std::abs(back->x - u.x), std::abs(back->y - u.y)});
      }
    }
    std::printf("  %s: round trip u, ellipse frame %.2e, world %.2e\n", c.name.c_str(), worst,
                worst_world);
    EXPECT_LE(worst, 1e-13) << c.name;
    EXPECT_LE(worst_world, 1e-9 + 16.0 * std::numeric_limits<double>::epsilon() / m.g.b_t)
        << c.name;
    // Off the disk, and on the disk below the horizon: density 0, no inverse.
    const Vec3 away = -(c.disk.center - c.point);
    EXPECT_EQ(any.pdf(away), 0.0);
    EXPECT_FALSE(any.invert(away).has_value());
  }
}

// n_o . int_region w dw for the region bounded by the closed spherical polygon `w` (unit,
// counter-clockwise about the region): (1/2) sum over great-circle edges of angle x unit normal.
double projected_area_of_polygon(const std::vector<Vec3>& w, const Vec3& n_o) {
  double sum = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const Vec3& p = w[i];
    const Vec3& q = w[(i + 1) % w.size()];
    const Vec3 x = p.cross(q);
    const double len = x.norm();
    if (len > 0.0) sum += std::atan2(len, p.dot(q)) * x.dot(n_o) / len;
  }
  return 0.5 * sum;
}

TEST(Projected, StratumImagesHaveEqualProjectedSolidAngle) {
  // The image of each stratum of a 4 x 4 grid, its boundary mapped point by point and closed
  // by great-circle chords, Richardson-extrapolated from M and 2M points per edge (chords err
  // by O(M^-2)), M = 1024 so that the corners where a clipped meridian pinches to a point
  // (the parametrization is singular there) are resolved too: P / 16 each, to 1e-7 of P.
  // Nothing here uses the pdf.
  // Skipped for ellipses below a = 1e-3: the polygon's terms (each ~ its edge) cancel to the
  // region's O(a^2) with rounding ~eps / a^2 relative. Boundary points stay kInset inside the
  // square: on the horizon (a clipped meridian's end at u2 = 1, its pinch points at u1 = 0, 1)
  // the density, and with it the sample's validity, is 0; the inset moves each stratum's
  // measure by O(kInset) of it.
  constexpr int kGrid = 4, kM = 1024;
  constexpr double kInset = 1e-9;
  for (const Config& c : configs()) {
    const ellipse::ProjectedMap m = make(c);
    if (m.g.a < 1e-3) continue;
    const Vec3 n_o = c.receiver_normal.normalized();
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j) {
        auto area = [&](int per_edge) {
          std::vector<Vec3> w;
          for (int k = 0; k < 4 * per_edge; ++k) {
            const Point2 u = disklab::test::stratum_boundary(
                double(i) / kGrid, double(i + 1) / kGrid, double(j) / kGrid, double(j + 1) / kGrid,
                double(k) / (4 * per_edge));
            const Point2 inside{std::clamp(u.x, kInset, 1.0 - kInset),
                                std::clamp(u.y, kInset, 1.0 - kInset)};
            const ellipse::EllipseSample smp = m.sample(inside);
            EXPECT_TRUE(smp.valid);
            w.push_back(smp.direction);
          }
          return projected_area_of_polygon(w, n_o);
        };
        // The map turns the square's counter-clockwise boundary clockwise about the region (u1
        // runs with the azimuth, u2 outwards), hence the sign; chords err by O(M^-2).
        const double a1 = -area(kM), a2 = -area(2 * kM);
        const double extrapolated = (4.0 * a2 - a1) / 3.0;
        EXPECT_NEAR(extrapolated, m.P / (kGrid * kGrid), 1e-7 * m.P)
            << c.name << " stratum " << i << "," << j;
      }
  }
}

TEST(Projected, ChiSquareAgainstBinsOfTheProjectedMeasure) {
  // Bins in (s, f): the parametric azimuth s (kS per piece of the turn, so that no bin spans a
  // horizon crossing, where the marginal has a kink) and the fraction f of each meridian's
  // visible range [t_lo, t_hi]. A bin's probability is the integral of the cosine over it,
  //   int int (A sin t + n_z cos t) sin t (t_hi - t_lo) (a b / r^2) / P df ds,
  // by 8 x 8 Gauss-Legendre (the integrand is smooth inside a bin); the map's inverse and its
  // marginal are not used. Pearson chi-square over 1e5 samples per configuration at a
  // Sidak-corrected 1e-4.
  using Rule = boost::math::quadrature::gauss<double, 8>;
  constexpr int kS = 8, kF = 8, kSamples = 100000;
  // The small straddling ellipses are included: their bins are integrated in the same R_e
  // coordinates, where the cosine is O(a) and no term cancels.
  auto cfgs = configs();
  for (const Config& c : small_straddling_configs())
    cfgs.push_back(c);
  const double alpha = disklab::test::sidak_alpha(1e-4, cfgs.size());
  for (const Config& c : cfgs) {
    const ellipse::ProjectedMap m = make(c);
    // Gauss in s and t at the scale of a distant unclipped ellipse: skip
    if (m.g.a < 1e-3 && !m.clipped) continue;
    std::vector<double> s_edges;
    if (m.clipped) {
      for (int i = 0; i < m.pieces.count; ++i) {
        if (m.pieces.kind[i] == 0) continue;
        for (int k = 0; k < kS; ++k)
          s_edges.push_back(m.pieces.edge[i] + (m.pieces.edge[i + 1] - m.pieces.edge[i]) * k / kS);
        s_edges.push_back(m.pieces.edge[i + 1]);
      }
    } else {
      for (int k = 0; k <= 4 * kS; ++k)
        s_edges.push_back(disklab::math::kTwoPi * k / (4 * kS));
    }
    std::sort(s_edges.begin(), s_edges.end());
    s_edges.erase(std::unique(s_edges.begin(), s_edges.end()), s_edges.end());
    const std::size_t ns = s_edges.size() - 1;
    auto kind_at = [&](double s) { return m.clipped ? m.pieces.kind[m.piece_of(s)] : 1; };
    std::vector<double> expected(ns * kF, 0.0), observed(ns * kF, 0.0);
    for (std::size_t i = 0; i < ns; ++i)
      for (int j = 0; j < kF; ++j) {
        const double f0 = double(j) / kF, f1 = double(j + 1) / kF;
        const double s_mid = 0.5 * (s_edges[i] + s_edges[i + 1]);
        const int kind = kind_at(s_mid);
        expected[i * kF + j] =
            Rule::integrate(
                [&](double s) {
                  const auto md = m.meridian(s, kind);
                  if (!(md.t_hi > md.t_lo)) return 0.0;
                  return Rule::integrate(
                             [&](double f) {
                               const double t = md.t_lo + f * (md.t_hi - md.t_lo);
                               return (md.A * std::sin(t) + m.n.z() * std::cos(t)) * std::sin(t);
                             },
                             f0, f1) *
                         (md.t_hi - md.t_lo) * m.g.a * m.g.b / md.r2;
                },
                s_edges[i], s_edges[i + 1]) /
            m.P * kSamples;
      }
    double total = 0.0;
    for (double e : expected)
      total += e;
    // The bins cover the visible part: their probabilities sum to 1 (quadrature error only).
    EXPECT_NEAR(total / kSamples, 1.0, 1e-6) << c.name;
    for (double& e : expected)
      e *= kSamples / total;
    disklab::sequence::Pcg32 rng(99);
    for (int k = 0; k < kSamples; ++k) {
      const ellipse::EllipseSample smp = m.sample({rng.next_double(), rng.next_double()});
      ASSERT_TRUE(smp.valid);
      const Vec3 l = m.g.to_local(smp.direction);
      double s = std::atan2(m.g.a * l.y(), m.g.b * l.x());
      if (s < 0.0) s += disklab::math::kTwoPi;
      if (s < s_edges.front()) s += disklab::math::kTwoPi;
      const auto it = std::upper_bound(s_edges.begin(), s_edges.end(), s);
      const std::size_t i = std::min<std::size_t>(
          ns - 1, static_cast<std::size_t>(std::max<std::ptrdiff_t>(1, it - s_edges.begin()) - 1));
      const auto md = m.meridian(s, kind_at(0.5 * (s_edges[i] + s_edges[i + 1])));
      const double t = std::atan2(std::hypot(l.x(), l.y()), l.z());
      const double f = (t - md.t_lo) / (md.t_hi - md.t_lo);
      const int j = std::clamp(static_cast<int>(f * kF), 0, kF - 1);
      observed[i * kF + j] += 1.0;
    }
    const disklab::test::ChiSquareResult r = disklab::test::chi_square(observed, expected);
    EXPECT_GT(r.p_value, alpha) << c.name << ": " << r.summary();
  }
}

TEST(Projected, DegenerateAndBelowTheHorizonGiveNoSample) {
  // Wholly below the receiver's horizon, a zero receiver normal, a point behind a one-sided disk.
  const ellipse::Disk below{Vec3(0, 0, -2), Vec3(0, 0, 1), 1.0, false};
  EXPECT_FALSE(ellipse::ProjectedMap::make(below, Vec3::Zero(), Vec3::UnitZ()).valid());
  const ellipse::Disk above{Vec3(0, 0, 2), Vec3(0, 0, -1), 1.0, false};
  EXPECT_FALSE(ellipse::ProjectedMap::make(above, Vec3::Zero(), Vec3::Zero()).valid());
  EXPECT_FALSE(ellipse::ProjectedMap::make(above, Vec3(0, 0, 3), Vec3::UnitZ()).valid());
  const auto m = ellipse::ProjectedMap::make(above, Vec3::Zero(), Vec3::UnitZ());
  ASSERT_TRUE(m.valid());
  EXPECT_FALSE(m.sample({NAN, 0.5}).valid);
  // The receiver facing away from the disk: nothing above its horizon.
  EXPECT_FALSE(ellipse::ProjectedMap::make(above, Vec3::Zero(), -Vec3::UnitZ()).valid());
}

// A disk 1e490 times wider than the point's height above it fills the hemisphere, so u.y = 1
// lands on the horizon: the direction's cosine came out as the smallest subnormal, positive,
// and cosine / P underflowed to a valid sample of density 0 (found by fuzz_maps; an estimator
// would divide by it). Such a sample is no sample, as one exactly on the horizon is; just
// inside it every sample keeps the contracts (contracts.h: positive pdf, pdf(direction) agrees).
TEST(Projected, HorizonSampleWhoseDensityUnderflowsIsNoSample) {
  const ellipse::Disk disk{
      Vec3(-1.2260560296460538e-59, 2.0703262594797636e-317, 2.070237821729158e-317),
      Vec3(-3.5376696985814819e+108, 1.8866021494726503e+185, 3.7284217522330064e-138),
      3.380693404685836e+184, true};
  const Vec3 o(2.1655808787051005e-47, 9.3451711386140203e-306, 0);
  const auto m = ellipse::AnyMap::make(ellipse::MapKind::projected, disk, o);
  ASSERT_TRUE(m.valid());
  for (double v : {1.0, 1.0 - 0x1p-53, 0.999, 0.5}) {
    const ellipse::EllipseSample s = m.sample({0.79999999999999882, v});
    EXPECT_TRUE(!s.valid || s.pdf > 0.0) << "v=" << v << " pdf=" << s.pdf;
    if (v < 1.0) {
      ASSERT_TRUE(s.valid) << v;
    }
    EXPECT_EQ(ellipse::check_sample(m, s), ellipse::Violation::none) << v;
  }
}

// G(r^2) = S(asin r) / r^3, the series the set-up fits (projected_detail::G, g_series): against
// the same Maclaurin series summed in long double by its term recurrence to 2^-100 (no table,
// no Horner), on [0, 1/4) where the double code sums the series, and with the degree the set-up
// takes for a whole ellipse (g_series_degree of its largest r^2) at every smaller r^2. 2 ulps:
// Horner's rounding in double is about one ulp (the sum's terms are all positive and fall by
// r^2 <= 1/4), and the dropped tail is below 2^-58 relative.
TEST(Projected, MaclaurinSeriesOfGIsAccurate) {
  auto reference = [](long double r2) {
    long double c = 1.0L, p = 1.0L, sum = 1.0L / 3.0L;
    for (int k = 1; k < 400; ++k) {
      c *= (2.0L * k - 1.0L) / (2.0L * k);
      p *= r2;
      const long double term = c * p / (2.0L * k + 3.0L);
      sum += term;
      if (term < 0x1p-100L * sum) break;
    }
    return sum;
  };
  auto ulps = [](double got, long double ref) {
    return static_cast<double>(std::abs(got - ref) /
                               std::ldexp(1.0L, std::ilogb(static_cast<double>(ref)) - 52));
  };
  namespace pd = ellipse::projected_detail;
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const double r2 = 0.25 * i / 2000.0;
    worst = std::max(worst, ulps(pd::G(r2), reference(r2)));
    for (const double max_r2 : {r2, std::min(0.2499, 1.5 * r2 + 1e-3), 0.2499}) {
      const double got = pd::g_series(r2, pd::g_series_degree(max_r2));
      EXPECT_LE(ulps(got, reference(r2)), 2.0) << "r2 = " << r2 << ", max_r2 = " << max_r2;
    }
  }
  EXPECT_LE(worst, 2.0);
  // The degree grows with the range and stays within the table.
  EXPECT_EQ(pd::g_series_degree(0.0), 0);
  EXPECT_LT(pd::g_series_degree(1e-4), pd::g_series_degree(0.01));
  EXPECT_LT(pd::g_series_degree(0.01), pd::g_series_degree(0.2499));
  EXPECT_LT(pd::g_series_degree(0.2499), pd::kGSeriesTerms - 1);
  std::printf("G's series on [0, 1/4): worst %.2f ulp; degree %d at r^2 = 0.01, %d at 0.25\n",
              worst, pd::g_series_degree(0.01), pd::g_series_degree(0.2499));
}

}  // namespace
