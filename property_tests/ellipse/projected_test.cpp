// The projected-solid-angle map (ellipse/projected.h): P against a 50-digit quadrature that
// shares nothing with the map, zero variance for a Lambertian receiver, pdf and inverse against
// sample, and equal projected solid angle for every stratum image, on unclipped, straddling
// (clipped by the receiver's horizon) and distant configurations.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "disklab/ellipse/any_map.h"
#include "disklab/ellipse/projected.h"
#include "disklab/math/constants.h"
#include "disklab/sequence/random.h"
#include "ellipse/map_common.h"
#include "support/stats.h"

namespace {
using disklab::Point2;
using disklab::Vec3;
namespace ellipse = disklab::ellipse;
using Real = boost::multiprecision::cpp_bin_float_50;

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

// P = int_disk max(0, cos_o) cos_l / d^2 dA in 50 digits, in the disk's own coordinates
// (u, v): for each u the integral over the chord v in [-Y, Y] (Y = sqrt(R^2 - u^2)), clipped
// where the receiver's cosine changes sign (a line in the disk's plane), is closed-form,
//   int (n2 w + beta) / (w^2 + k)^2 dw = -n2 / (2 (w^2 + k))
//       + beta (w / (2 k (w^2 + k)) + atan(w / sqrt k) / (2 k^(3/2))),
// and u = R sin(theta) is integrated by tanh-sinh, split where the line meets the rim.
double projected_reference(const Config& c) {
  const ellipse::Disk& d = c.disk;
  const Vec3 nd = d.normal.normalized();
  const Vec3 e1 = nd.unitOrthogonal(), e2 = nd.cross(e1);
  const Vec3 q = c.point - d.center, no = c.receiver_normal.normalized();
  const Real h = q.dot(nd), q1 = q.dot(e1), q2 = q.dot(e2), R = d.radius;
  const Real n1 = no.dot(e1), n2 = no.dot(e2), n3 = no.dot(nd);
  using boost::multiprecision::abs;
  using boost::multiprecision::atan;
  using boost::multiprecision::sqrt;
  auto rmax = [](const Real& x, const Real& y) -> Real { return x > y ? x : y; };
  auto rmin = [](const Real& x, const Real& y) -> Real { return x < y ? x : y; };
  auto antiderivative = [&](const Real& w, const Real& beta, const Real& k) -> Real {
    const Real s = w * w + k;
    return -n2 / (2 * s) + beta * (w / (2 * k * s) + atan(w / sqrt(k)) / (2 * k * sqrt(k)));
  };
  auto chord = [&](const Real& u) -> Real {
    const Real Y = sqrt(rmax(Real(0), R * R - u * u));
    const Real beta = n1 * (u - q1) - n3 * h, k = (u - q1) * (u - q1) + h * h;
    Real lo = -Y - q2, hi = Y - q2;  // w = v - q2
    if (n2 > 0) {
      lo = rmax(lo, -beta / n2);
    } else if (n2 < 0) {
      hi = rmin(hi, -beta / n2);
    } else if (!(beta > 0)) {
      return 0;
    }
    if (!(hi > lo)) return 0;
    return antiderivative(hi, beta, k) - antiderivative(lo, beta, k);
  };
  auto integrand = [&](const Real& theta) -> Real {
    return abs(h) * chord(R * sin(theta)) * R * cos(theta);
  };
  // Where the line n1 (u - q1) + n2 (v - q2) = n3 h meets u^2 + v^2 = R^2: breakpoints in theta.
  std::vector<Real> cuts{-boost::math::constants::half_pi<Real>()};
  const Real cst = n1 * q1 + n2 * q2 + n3 * h;  // n1 u + n2 v = cst
  const Real nn = n1 * n1 + n2 * n2;
  if (nn > 0) {
    const Real dist = cst / sqrt(nn);
    if (abs(dist) < R) {
      const Real along = sqrt(R * R - dist * dist);
      const Real ux = n1 / sqrt(nn), uy = n2 / sqrt(nn);
      for (int sgn : {-1, 1}) {
        const Real u = dist * ux - sgn * along * uy;
        cuts.push_back(asin(rmin(Real(1), rmax(Real(-1), u / R))));
      }
    }
  }
  // The integrand peaks within ~|h| of the foot of the point (u = q1): cuts there too.
  for (double k : {-100.0, -10.0, -1.0, 0.0, 1.0, 10.0, 100.0}) {
    const Real u = q1 + k * abs(h);
    if (abs(u) < R) cuts.push_back(asin(u / R));
  }
  cuts.push_back(boost::math::constants::half_pi<Real>());
  std::sort(cuts.begin(), cuts.end());
  boost::math::quadrature::tanh_sinh<Real> ts(12);
  Real sum = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    if (cuts[i + 1] > cuts[i]) sum += ts.integrate(integrand, cuts[i], cuts[i + 1], Real(1e-40));
  return static_cast<double>(sum);
}

ellipse::ProjectedMap make(const Config& c) {
  return ellipse::ProjectedMap::make(c.disk, c.point, c.receiver_normal);
}

TEST(Projected, ProjectedSolidAngleMatchesFiftyDigitQuadrature) {
  // Unclipped, P = pi a b n_z with a, b to a few ulps: 1e-14. Clipped, the elementary pieces
  // (each O(a) of the ellipse's size) cancel down to P: the rounding bound of projected.h,
  // 64 eps pi a^2 / P relative (1e-14 where the disk fills much of the sky, ~1e-12 for a
  // small disk straddling the horizon).
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  for (const Config& c : configs()) {
    const ellipse::ProjectedMap m = make(c);
    ASSERT_TRUE(m.valid()) << c.name;
    const double ref = projected_reference(c);
    const double rel = std::abs(m.projected_solid_angle() - ref) / ref;
    const double bound =
        m.clipped ? std::max(1e-14, 64.0 * kEps * disklab::math::kPi * m.g.a * m.g.a / m.P) : 1e-14;
    std::printf("  %-16s P %.17g reference %.17g rel %.2e (bound %.1e)%s\n", c.name.c_str(), m.P,
                ref, rel, bound, m.clipped ? " clipped" : "");
    EXPECT_LE(rel, bound) << c.name;
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
  // pdf(sample(u)) = max(0, w . n_o) / P to 1e-12. invert_local(sample(u).local) = u to 1e-9
  // where the cosine is above 1e-3 (eps2's inverse is conditioned like 1 / cosine near the
  // horizon); through the world direction, whose rounding (~eps) is ~eps / b_t of the ellipse,
  // to 1e-9 + 16 eps / b_t.
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
    EXPECT_LE(worst, 1e-9) << c.name;
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
  const auto cfgs = configs();
  const double alpha = disklab::test::sidak_alpha(1e-4, cfgs.size());
  for (const Config& c : cfgs) {
    const ellipse::ProjectedMap m = make(c);
    if (m.g.a < 1e-3) continue;  // Gauss in s and t at the scale of a distant ellipse: skip
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

}  // namespace
