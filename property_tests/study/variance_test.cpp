// The variance study's harness (verify/study/variance.h): the rim-integral reference against an
// independent quadrature, the shadow test's conservatism, every map's solid-angle estimator
// unbiased (lit and in the penumbra), iid variances against quadrature, and numbers that do
// not depend on the thread count.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "disklab/math/constants.h"
#include "disklab/sequence/random.h"
#include "disklab/sequence/sequence.h"
#include "study/estimator.h"
#include "study/reference.h"
#include "study/variance.h"
#include "support/stats.h"

namespace {
using disklab::Point2;
using disklab::Vec3;
using namespace disklab::study;
namespace ellipse = disklab::ellipse;
namespace t = disklab::test;
using disklab::math::kPi;
using disklab::math::kTwoPi;

// ---- Significance and sizes (the one place for this suite) ----
// Each statistical check rejects correct code with probability alpha, Sidak-corrected so that
// each test's checks together do with kFamilyAlpha. The seeds are fixed: deterministic.
constexpr double kFamilyAlpha = 1e-3;
constexpr uint32_t kRandomizations = 2000;  // estimates per (map, point) for the mean
constexpr uint32_t kSamples = 16;           // samples per estimate, as in the image
constexpr uint32_t kIidSamples = 200000;    // draws per (map, point) for the variance

std::vector<ellipse::MapKind> all_maps() {
  std::vector<ellipse::MapKind> out;
  for (const std::string& n : ellipse::map_names())
    out.push_back(*ellipse::parse_map(n));
  return out;
}

ShadingPoint ground(double x, double y) {
  return {Vec3(x, y, 0.0), Vec3::UnitZ()};
}

// A ground point in the sphere's penumbra: the first along y = 0.55 (x from -2 towards the
// light) where the visible fraction of the unoccluded irradiance is between 0.3 and 0.7.
ShadingPoint penumbra_point(const Scene& scene) {
  for (double x = -2.0; x < -0.3; x += 0.01) {
    const ShadingPoint sp = ground(x, 0.55);
    if (!may_be_shadowed(scene, sp)) continue;
    const double f =
        irradiance_quadrature(scene, sp, 1e-12).value / irradiance_rim(scene.light, sp).value;
    if (f > 0.3 && f < 0.7) return sp;
  }
  ADD_FAILURE() << "no penumbra point found";
  return ground(-1.0, 0.55);
}

TEST(VarianceScene, RegionsAndImageGridAreAsPrescribed) {
  const ImageGrid g;
  // Pixel centres x_i = -2 + (i + 1/2) / 32; row 0 at the top (largest y).
  EXPECT_DOUBLE_EQ(g.pixel(0, 0).position.x(), -2.0 + 0.5 / 32.0);
  EXPECT_DOUBLE_EQ(g.pixel(0, 0).position.y(), 2.0 - 0.5 / 32.0);
  EXPECT_DOUBLE_EQ(g.pixel(127, 5).position.y(), -2.0 + 0.5 / 32.0);
  EXPECT_DOUBLE_EQ(g.pixel(3, 127).position.x(), 2.0 - 0.5 / 32.0);
  const Scene s = variance_scene();
  EXPECT_TRUE(s.light.two_sided);
  EXPECT_DOUBLE_EQ(s.light.center.z() - s.light.radius, 0.1);  // lowest point at z = 0.1
  EXPECT_DOUBLE_EQ(s.light.axis_x.cross(s.light.axis_y).dot(s.light.normal), 1.0);
  for (const StudyRegion& r : variance_regions())
    for (const ShadingPoint& p : r.grid.points())
      EXPECT_FALSE(may_be_shadowed(s, p)) << r.grid.name << " must be unoccluded";
}

TEST(VarianceReference, RimIntegralAgreesWithIndependentQuadrature) {
  // The polar quadrature of the convergence study (reference.h) shares nothing with the rim
  // integral but the scene. Target 1e-12 relative: both estimate their errors far below it.
  const Scene s = variance_scene();
  std::vector<ShadingPoint> pts;
  for (const StudyRegion& r : variance_regions())
    for (const ShadingPoint& p : r.grid.points())
      pts.push_back(p);
  disklab::sequence::Pcg32 rng(11);
  while (pts.size() < 48 + 60) {  // unoccluded ground points anywhere in the image, both sides
    const ShadingPoint p = ground(-2.0 + 4.0 * rng.next_double(), -2.0 + 4.0 * rng.next_double());
    if (!may_be_shadowed(s, p) && std::fabs(p.position.x()) > 1e-3) pts.push_back(p);
  }
  double worst = 0.0;
  for (const ShadingPoint& p : pts) {
    const ReferenceValue rim = irradiance_rim(s.light, p);
    const ReferenceValue quad = irradiance_quadrature(s, p, 1e-14);
    const double rel = std::fabs(rim.value - quad.value) / quad.value;
    worst = std::max(worst, rel);
    EXPECT_LE(rel, 1e-12) << "at (" << p.position.x() << ", " << p.position.y() << ")";
    EXPECT_LE(rim.error_estimate, 1e-13 * rim.value);
  }
  std::printf("  rim vs quadrature: worst relative difference %.2e over %zu points\n", worst,
              pts.size());
  // And against the closed form of a receiver parallel to the disk (the memo's scene).
  const Scene memo = memo_scene();
  for (double d : {0.0, 0.3, 0.99, 1.01, 2.5}) {
    const ShadingPoint p = ground(d, 0.0);
    const double closed = disk_irradiance_parallel(1.0, 1.0, 2.0, d);
    // The closed form is good to 16 eps (convergence.cpp); the rim integral to its estimate.
    EXPECT_NEAR(irradiance_rim(memo.light, p).value, closed, 32.0 * 2.2e-16 * closed) << d;
  }
  // Below the horizon the method does not apply and says so.
  EXPECT_THROW(irradiance_rim(s.light, {Vec3(0.3, 0.0, 0.5), Vec3::UnitZ()}), std::domain_error);
}

TEST(VarianceReference, ShadowTestIsConservative) {
  // Where may_be_shadowed says no, no segment to the disk meets the sphere (checked on a dense
  // polar grid of disk points); some of the points it flags really are shadowed.
  const Scene s = variance_scene();
  const ImageGrid g{64, -2.0, 2.0};
  int flagged = 0, shadowed = 0;
  for (int row = 0; row < g.size; ++row)
    for (int col = 0; col < g.size; ++col) {
      const ShadingPoint p = g.pixel(row, col);
      const bool maybe = may_be_shadowed(s, p);
      flagged += maybe;
      bool any = false;
      for (int i = 0; i <= 16 && !any; ++i)
        for (int j = 0; j < 64 && !any; ++j) {
          const double r = i / 16.0, a = kTwoPi * j / 64;
          any = occluded(s, p.position, s.light.point({r * std::cos(a), r * std::sin(a)}));
        }
      shadowed += any;
      if (any) {
        EXPECT_TRUE(maybe) << "pixel " << row << "," << col;
      }
    }
  EXPECT_GT(shadowed, 0);
  EXPECT_GE(flagged, shadowed);
}

double reference(const Scene& s, const ShadingPoint& p) {
  return irradiance_reference(s, p, nullptr).value;
}

std::vector<std::pair<std::string, ShadingPoint>> test_points(const Scene& s) {
  return {{"near corner", ground(0.05, -0.15)},
          {"mid", ground(0.7, 0.05)},
          {"far corner", ground(2.0, 2.0)},
          {"penumbra", penumbra_point(s)}};
}

// One estimate per randomization of a random sequence.
t::MeanEstimate mean_of_estimates(ellipse::MapKind kind, const Scene& s, const ShadingPoint& p) {
  const ellipse::AnyMap map = light_map(kind, s, p);
  const std::vector<uint32_t> ns{kSamples};
  std::vector<double> values;
  std::vector<Point2> u(kSamples);
  double est = 0.0;
  for (uint32_t m = 0; m < kRandomizations; ++m) {
    const auto seq = disklab::sequence::make_sequence("random", 9000 + m);
    for (uint32_t i = 0; i < kSamples; ++i)
      u[i] = seq->at(i);
    progressive_irradiance(s, p, map, u, ns, {&est, 1});
    values.push_back(est);
  }
  return t::mean_estimate(values);
}

class MapUnbiased : public ::testing::TestWithParam<ellipse::MapKind> {};

TEST_P(MapUnbiased, MeanOverRandomizationsMatchesTheReference) {
  const Scene s = variance_scene();
  const double z = t::normal_two_sided_quantile(t::sidak_alpha(kFamilyAlpha, 4));
  for (const auto& [what, p] : test_points(s)) {
    const t::MeanEstimate m = mean_of_estimates(GetParam(), s, p);
    const double ref = reference(s, p);
    std::printf("  %s, %s: mean %.6f +- %.6f, reference %.6f\n",
                std::string(ellipse::map_name(GetParam())).c_str(), what.c_str(), m.mean,
                m.std_error, ref);
    // Plus 1e-12 of the reference for rounding: projected is zero-variance at lit points, so
    // its standard error (~1e-16) falls below the references' and P's accuracy (~1e-14).
    EXPECT_LE(std::fabs(m.mean - ref), z * m.std_error + 1e-12 * ref)
        << ellipse::map_name(GetParam()) << " at " << what;
  }
}

INSTANTIATE_TEST_SUITE_P(AllMaps, MapUnbiased, ::testing::ValuesIn(all_maps()),
                         [](const auto& info) {
                           std::string n(ellipse::map_name(info.param));
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

TEST(MapEstimator, AreaWithTheUniformPdfIsCaught) {
  // Negative control: area samples weighted as if uniform in solid angle (f Omega instead of
  // f / pdf) are biased near the light, and the test above would see it.
  const Scene s = variance_scene();
  const ShadingPoint p = ground(0.05, -0.15);
  const ellipse::AnyMap map = light_map(ellipse::MapKind::area, s, p);
  std::vector<double> values;
  for (uint32_t m = 0; m < kRandomizations; ++m) {
    const auto seq = disklab::sequence::make_sequence("random", 9000 + m);
    double sum = 0.0;
    for (uint32_t i = 0; i < kSamples; ++i) {
      const auto e = map.sample(seq->at(i));
      if (e.valid) sum += std::max(0.0, e.direction.dot(p.normal)) * map.omega();
    }
    values.push_back(sum / kSamples);
  }
  const t::MeanEstimate m = t::mean_estimate(values);
  const double z = t::normal_two_sided_quantile(t::sidak_alpha(kFamilyAlpha, 4));
  EXPECT_GT(std::fabs(m.mean - reference(s, p)), z * m.std_error);
}

// int_disk g(x) dA by composite Gauss-Legendre in the radius (8 panels of 20 nodes, clustered
// nowhere: the integrands are smooth on the closed disk) and the periodic trapezoid rule in
// the angle.
template <class G>
double disk_integral(const DiskLight& l, G&& g) {
  using Rule = boost::math::quadrature::gauss<double, 20>;
  constexpr int kPanels = 8, kAngles = 1024;
  double sum = 0.0;
  for (int j = 0; j < kAngles; ++j) {
    const double a = kTwoPi * (j + 0.5) / kAngles, c = std::cos(a), sn = std::sin(a);
    for (int k = 0; k < kPanels; ++k) {
      const double r0 = l.radius * k / kPanels, r1 = l.radius * (k + 1) / kPanels;
      sum += Rule::integrate(
          [&](double r) { return r * g(l.center + r * (c * l.axis_x + sn * l.axis_y)); }, r0, r1);
    }
  }
  return sum * kTwoPi / kAngles;
}

TEST(MapEstimator, IidVarianceMatchesQuadrature) {
  // With iid input, f / pdf per sample has variance Omega int f^2 dw - E^2 for a uniform map
  // and A int f_A^2 dA - E^2 for area sampling (f_A = L cos_o cos_l / d^2), both by quadrature
  // over the disk. The sample variance of kIidSamples draws has standard error
  // sqrt((m4 - s^4) / n); each check at the Sidak-corrected level.
  const Scene s = variance_scene();
  const DiskLight& l = s.light;
  const std::vector<ellipse::MapKind> maps = {ellipse::MapKind::area, ellipse::MapKind::parallel,
                                              ellipse::MapKind::radial, ellipse::MapKind::ld_radial,
                                              ellipse::MapKind::radial_fast};
  const std::vector<ShadingPoint> pts = {ground(0.05, -0.15), ground(0.7, 0.05), ground(2.0, 2.0)};
  const double z = t::normal_two_sided_quantile(t::sidak_alpha(kFamilyAlpha, maps.size() * 3));
  for (const ShadingPoint& p : pts) {
    auto geometry = [&](const Vec3& x, double& cos_o, double& cos_l, double& d2) {
      const Vec3 v = x - p.position;
      d2 = v.squaredNorm();
      cos_o = v.dot(p.normal) / std::sqrt(d2);
      cos_l = std::fabs(v.dot(l.normal)) / std::sqrt(d2);
    };
    const double omega = disk_integral(l, [&](const Vec3& x) {
      double co, cl, d2;
      geometry(x, co, cl, d2);
      return cl / d2;
    });
    const double e = disk_integral(l, [&](const Vec3& x) {
      double co, cl, d2;
      geometry(x, co, cl, d2);
      return co * cl / d2;
    });
    const double f2 = disk_integral(l, [&](const Vec3& x) {
      double co, cl, d2;
      geometry(x, co, cl, d2);
      return co * co * cl / d2;
    });
    const double fa2 = disk_integral(l, [&](const Vec3& x) {
      double co, cl, d2;
      geometry(x, co, cl, d2);
      return (co * cl / d2) * (co * cl / d2);
    });
    // The quadrature itself is checked against the rim integral (its E) first.
    ASSERT_NEAR(e, irradiance_rim(l, p).value, 1e-9 * e);
    const double area = kPi * l.radius * l.radius;
    for (ellipse::MapKind kind : maps) {
      const double predicted =
          kind == ellipse::MapKind::area ? area * fa2 - e * e : omega * f2 - e * e;
      const ellipse::AnyMap map = light_map(kind, s, p);
      disklab::sequence::Pcg32 rng(77);
      std::vector<double> y(kIidSamples);
      double mean = 0.0;
      for (double& v : y) {
        const auto smp = map.sample({rng.next_double(), rng.next_double()});
        v = smp.valid ? std::max(0.0, smp.direction.dot(p.normal)) / smp.pdf : 0.0;
        mean += v;
      }
      mean /= kIidSamples;
      double m2 = 0.0, m4 = 0.0;
      for (double v : y) {
        const double d = (v - mean) * (v - mean);
        m2 += d;
        m4 += d * d;
      }
      m2 /= kIidSamples - 1;
      m4 /= kIidSamples;
      const double se = std::sqrt(std::max(0.0, m4 - m2 * m2) / kIidSamples);
      std::printf("  %s at (%.2f, %.2f): variance %.6g +- %.2g, quadrature %.6g\n",
                  std::string(ellipse::map_name(kind)).c_str(), p.position.x(), p.position.y(), m2,
                  se, predicted);
      EXPECT_LE(std::fabs(m2 - predicted), z * se) << ellipse::map_name(kind);
    }
  }
}

VarianceConfig small_config(int threads) {
  VarianceConfig c;
  c.maps = {ellipse::MapKind::area, ellipse::MapKind::radial, ellipse::MapKind::radial4,
            ellipse::MapKind::gamito};
  c.sequences = {"random", "pmj02"};
  c.ns = {16, 32, 64};
  c.fit_min = 32;
  c.seeds = 3;
  c.image_randomizations = 2;
  c.image = ImageGrid{8, -2.0, 2.0};
  c.timing_repetitions = 1;
  c.threads = threads;
  return c;
}

TEST(Variance, NumbersDoNotDependOnTheThreadCount) {
  const VarianceResult one = run_variance(small_config(1));
  const VarianceResult two = run_variance(small_config(2));
  EXPECT_EQ(one.curves.sse, two.curves.sse);
  EXPECT_EQ(one.curves.rel_sse, two.curves.rel_sse);
  EXPECT_EQ(one.image.sse, two.image.sse);
  EXPECT_EQ(one.images, two.images);
  EXPECT_EQ(one.image_reference.value, two.image_reference.value);
  for (std::size_t m = 0; m < one.newton.size(); ++m)
    EXPECT_EQ(one.newton[m].histogram, two.newton[m].histogram);
  // radial solves a root per sample; area none.
  EXPECT_GT(one.newton[1].solves, 0u);
  EXPECT_EQ(one.newton[0].max, 0);
  // radial4 (index 2) shares each solve among its four copies.
  EXPECT_DOUBLE_EQ(one.newton[2].per_sample, one.newton[2].mean / 4.0);
  EXPECT_DOUBLE_EQ(one.newton[1].per_sample, one.newton[1].mean);
  // The baseline's ratio to itself is 1 by construction; every cost and ratio is positive and
  // finite, one per map.
  EXPECT_EQ(one.baseline_cost.ratio_to_baseline, 1.0);
  EXPECT_GT(one.baseline_cost.ns_per_sample, 0.0);
  ASSERT_EQ(one.cost.size(), one.map_names.size());
  for (const MapCost& c : one.cost) {
    EXPECT_GT(c.ns_per_sample, 0.0);
    EXPECT_GT(c.ratio_to_baseline, 0.0);
    EXPECT_LT(c.ratio_to_baseline, std::numeric_limits<double>::infinity());
  }
}

TEST(Variance, BadConfigurationsAreRejected) {
  VarianceConfig c = small_config(1);
  c.sequences = {"nope"};
  EXPECT_THROW(finalize(c), std::invalid_argument);
  c = small_config(1);
  c.spp = 6;
  EXPECT_THROW(finalize(c), std::invalid_argument);
  c = small_config(1);
  c.ns = {16, 16};
  EXPECT_THROW(finalize(c), std::invalid_argument);
  c = small_config(1);
  c.image_randomizations = 0;
  EXPECT_THROW(finalize(c), std::invalid_argument);
}

}  // namespace
