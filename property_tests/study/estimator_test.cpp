// The estimator harness (verify/study/estimator.h, convergence.h): unbiased for every disk
// strategy, progressive prefixes equal to separate runs, and a study whose numbers do not
// depend on the thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "disklab/sequence/sequence.h"
#include "study/convergence.h"
#include "study/estimator.h"
#include "study/reference.h"
#include "support/stats.h"

namespace {
using disklab::Vec3;
using namespace disklab::study;
namespace disk = disklab::disk;
namespace t = disklab::test;

// ---- Significance and sizes (the one place for this suite) ----
// Each check: |mean over kRandomizations estimates - reference| <= z SE, z at a Sidak-corrected
// level so all checks together reject correct code with probability kFamilyAlpha. The seeds are
// fixed, so the suite is deterministic. At N = 64 the standard error is ~1e-3 of E, so the
// biased control (pad-zero without its 4/pi, a 27% bias) is rejected by hundreds of SEs.
constexpr double kFamilyAlpha = 1e-3;
constexpr uint32_t kRandomizations = 2000;
constexpr uint32_t kSamples = 64;
constexpr std::size_t kChecks = 6 * 3;  // six strategies at three shading points

struct Point {
  const char* what;
  ShadingPoint sp;
};

std::vector<Point> points() {
  return {{"lit-axis corner", {Vec3(-0.6, -0.3, 0.0), Vec3::UnitZ()}},
          {"lit-off corner", {Vec3(-1.3, -1.6, 0.0), Vec3::UnitZ()}},
          {"penumbra corner", {Vec3(2.2, 0.5, 0.0), Vec3::UnitZ()}}};
}

// Fully lit points against the closed form, the penumbra point against the quadrature.
double reference(const Scene& scene, const ShadingPoint& sp) {
  const double d = std::hypot(sp.position.x(), sp.position.y());
  if (sp.position.x() < 0.0) return disk_irradiance_parallel(1.0, 1.0, 2.0, d);
  return irradiance_quadrature(scene, sp).value;
}

// One estimate per randomization (a random sequence per seed).
std::vector<double> estimates(disk::Strategy strategy, const Scene& scene, const ShadingPoint& sp,
                              bool drop_pad_weight = false) {
  std::vector<double> out;
  const std::vector<uint32_t> ns{kSamples};
  std::vector<double> est(1);
  for (uint32_t m = 0; m < kRandomizations; ++m) {
    const auto seq = disklab::sequence::make_sequence("random", 5000 + m);
    std::vector<AreaSample> samples = disk_samples(strategy, *seq, kSamples);
    if (drop_pad_weight)
      for (AreaSample& s : samples)
        s.weight = s.weight > 0.0 ? 1.0 : 0.0;
    progressive_irradiance(scene, sp, samples, ns, est);
    out.push_back(est[0]);
  }
  return out;
}

class Unbiased : public ::testing::TestWithParam<disk::Strategy> {};

TEST_P(Unbiased, MeanOverRandomizationsMatchesTheReference) {
  const Scene scene = memo_scene();
  const double z = t::normal_two_sided_quantile(t::sidak_alpha(kFamilyAlpha, kChecks));
  for (const Point& p : points()) {
    const t::MeanEstimate m = t::mean_estimate(estimates(GetParam(), scene, p.sp));
    const double ref = reference(scene, p.sp);
    std::printf("  %s, %s: mean %.6f +- %.6f, reference %.6f\n",
                std::string(disk::strategy_name(GetParam())).c_str(), p.what, m.mean, m.std_error,
                ref);
    EXPECT_LE(std::fabs(m.mean - ref), z * m.std_error)
        << disk::strategy_name(GetParam()) << " at " << p.what << ": mean " << m.mean << " +- "
        << m.std_error << ", reference " << ref;
  }
}

INSTANTIATE_TEST_SUITE_P(AllStrategies, Unbiased, ::testing::ValuesIn(disk::kAllStrategies),
                         [](const auto& info) {
                           std::string n(disk::strategy_name(info.param));
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

TEST(Estimator, PadZeroWithoutItsWeightIsCaught) {
  // Negative control: dropping the 4/pi weight of pad-zero scales the estimate by pi/4.
  const Scene scene = memo_scene();
  const Point p = points()[0];
  const t::MeanEstimate m =
      t::mean_estimate(estimates(disk::Strategy::pad_zero, scene, p.sp, /*drop_pad_weight=*/true));
  const double z = t::normal_two_sided_quantile(t::sidak_alpha(kFamilyAlpha, kChecks));
  EXPECT_GT(std::fabs(m.mean - reference(scene, p.sp)), z * m.std_error);
}

TEST(Estimator, PrefixesEqualSeparateRuns) {
  // One pass over N_max samples gives, at every N, exactly the estimate of a run of N samples.
  const Scene scene = memo_scene();
  const std::vector<uint32_t> ns{16, 32, 64, 128, 256};
  for (disk::Strategy st : disk::kAllStrategies) {
    const auto seq = disklab::sequence::make_sequence("sobol-owen", 7);
    const auto all = disk_samples(st, *seq, ns.back());
    std::vector<double> together(ns.size());
    progressive_irradiance(scene, points()[2].sp, all, ns, together);
    for (std::size_t k = 0; k < ns.size(); ++k) {
      const auto alone = disk_samples(st, *seq, ns[k]);
      std::vector<double> one(1);
      progressive_irradiance(scene, points()[2].sp, alone, std::vector<uint32_t>{ns[k]}, one);
      EXPECT_EQ(together[k], one[0]) << disk::strategy_name(st) << " N = " << ns[k];
    }
  }
}

TEST(Estimator, RejectionCountsAcceptedSamplesAndFourCopyStrategiesQuarterTheSquarePoints) {
  const auto seq = disklab::sequence::make_sequence("random", 3);
  for (const AreaSample& s : disk_samples(disk::Strategy::rejection, *seq, 1000))
    EXPECT_EQ(s.weight, 1.0);  // every sample is an accepted one
  // polar4: samples 4j .. 4j + 3 are the four rotations of one square point.
  const auto four = disk_samples(disk::Strategy::polar4, *seq, 64);
  for (std::size_t j = 0; j < 64; j += 4) {
    EXPECT_DOUBLE_EQ(four[j + 1].point.x, -four[j].point.y);
    EXPECT_DOUBLE_EQ(four[j + 2].point.x, -four[j].point.x);
  }
  EXPECT_EQ(square_points_needed(disk::Strategy::polar4, 4096), 1024u);
}

TEST(Convergence, NumbersDoNotDependOnTheThreadCount) {
  ConvergenceConfig c;
  c.sequences = {"pmj02", "sobol-xor", "random"};
  c.ns = {16, 32, 64, 128};
  c.seeds = 6;
  c.threads = 1;
  const ConvergenceResult one = run_convergence(c);
  c.threads = 2;
  const ConvergenceResult two = run_convergence(c);
  ASSERT_EQ(one.sse.size(), two.sse.size());
  EXPECT_EQ(one.sse, two.sse);
  EXPECT_EQ(one.rel_sse, two.rel_sse);
}

TEST(Convergence, ConfigurationErrorsAreRefused) {
  auto refused = [](auto edit) {
    ConvergenceConfig c;
    edit(c);
    EXPECT_THROW(finalize(c), std::invalid_argument);
  };
  refused([](ConvergenceConfig& c) { c.ns = {16, 48}; });  // not a power of two
  refused([](ConvergenceConfig& c) { c.ns = {64, 32}; });  // not increasing
  refused([](ConvergenceConfig& c) { c.seeds = 0; });
  refused([](ConvergenceConfig& c) { c.sequences = {"nope"}; });
  refused([](ConvergenceConfig& c) { c.ns = {16, 32, 64}; });  // one N in the fit range
}

}  // namespace
