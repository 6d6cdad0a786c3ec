// Pad-zero and rejection are unbiased estimators of a disk integral, and their API reports
// weights and consumed square points honestly (Christensen 2018, Sec. 3; docs/design.md "Rejection
// must stay unbiased"). The maps are checked the same way, and two biased variants must fail.
#include <gtest/gtest.h>

#include <boost/math/special_functions/bessel.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "disklab/disk/strategy.h"
#include "disklab/math/constants.h"
#include "disklab/sequence/random.h"
#include "support/stats.h"

namespace {
using disklab::Point2;
using disklab::math::kPi;
using disklab::sequence::RandomSequence;
using namespace disklab::disk;
namespace t = disklab::test;

// ---- Significance and sizes (the one place for this suite) ----
// Each check compares the mean of kRandomizations independent estimates with the exact value:
// |mean - exact| <= z * standard error, z two-sided normal at a Sidak-corrected level so that
// all kChecks together reject correct code with probability kFamilyAlpha (for a given seed
// set; the seeds are fixed, so the suite is deterministic). 4000 estimates make the mean
// normal to good accuracy; the standard error is ~1e-3 of the exact value, so the biased
// variants below (20% off) are rejected by hundreds of standard errors.
constexpr double kFamilyAlpha = 1e-3;
constexpr std::size_t kChecks = 6 + 2;  // six strategies + the two consumption rates
constexpr uint32_t kRandomizations = 4000;
constexpr uint32_t kSamplesPerEstimate = 16;

double z_bound() {
  return t::normal_two_sided_quantile(t::sidak_alpha(kFamilyAlpha, kChecks));
}

// Smooth, asymmetric integrand with a closed-form disk average:
// (1/pi) int_D e^x dA = 2 I_1(1)  (from int_{-1}^{1} e^x sqrt(1 - x^2) dx = pi I_1(1)),
// (1/pi) int_D y^2 dA = 1/4, (1/pi) int_D y dA = 0.
double f(Point2 p) {
  return std::exp(p.x) + p.y * p.y + 0.5 * p.y;
}
double exact_average() {
  return 2.0 * boost::math::cyl_bessel_i(1, 1.0) + 0.25;
}

// One estimate per randomization (seed), from N samples of `strategy`.
std::vector<double> estimates(Strategy strategy, bool unweighted = false) {
  std::vector<double> out;
  for (uint32_t m = 0; m < kRandomizations; ++m) {
    const RandomSequence seq(1000 + m);
    DiskSampler<RandomSequence> sampler(strategy, seq);
    double sum = 0.0;
    for (uint32_t s = 0; s < kSamplesPerEstimate; ++s) {
      const DiskSample d = sampler.next();
      const double w = unweighted ? (d.weight > 0.0 ? 1.0 : 0.0) : d.weight;
      sum += w * f(d.point);
    }
    out.push_back(sum / kSamplesPerEstimate);
  }
  return out;
}

std::string describe(const t::MeanEstimate& m) {
  return "mean=" + std::to_string(m.mean) + " +- " + std::to_string(m.std_error) +
         " exact=" + std::to_string(exact_average()) + " z=" + std::to_string(z_bound()) + " (" +
         std::to_string(m.n) + " randomizations x " + std::to_string(kSamplesPerEstimate) +
         " samples)";
}

class Unbiased : public ::testing::TestWithParam<Strategy> {};

TEST_P(Unbiased, MeanOverRandomizationsMatchesTheClosedForm) {
  const t::MeanEstimate m = t::mean_estimate(estimates(GetParam()));
  std::printf("  %s: %s\n", std::string(strategy_name(GetParam())).c_str(), describe(m).c_str());
  EXPECT_LE(std::fabs(m.mean - exact_average()), z_bound() * m.std_error)
      << strategy_name(GetParam()) << ": " << describe(m);
}

INSTANTIATE_TEST_SUITE_P(AllStrategies, Unbiased, ::testing::ValuesIn(kAllStrategies),
                         [](const auto& info) {
                           std::string n(strategy_name(info.param));
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

// Negative controls for the bound's power: pad-zero without the 4/pi weight, and rejection
// that returns a zero sample (weight 1) instead of trying again, as docs/design.md warns. Both
// scale the estimate by the acceptance rate pi/4.
TEST(Unbiased, RejectsPadZeroWithoutItsWeight) {
  const t::MeanEstimate m = t::mean_estimate(estimates(Strategy::pad_zero, true));
  EXPECT_GT(std::fabs(m.mean - exact_average()), z_bound() * m.std_error) << describe(m);
}

TEST(Unbiased, RejectsRejectionThatReturnsAZeroSample) {
  std::vector<double> est;
  for (uint32_t m = 0; m < kRandomizations; ++m) {
    const RandomSequence seq(1000 + m);
    double sum = 0.0;
    for (uint32_t s = 0; s < kSamplesPerEstimate; ++s) {
      const RejectionTry r = try_rejection(seq.at(s));
      sum += r.accepted ? f(r.point) : 0.0;  // one try, a zero on failure, weight 1
    }
    est.push_back(sum / kSamplesPerEstimate);
  }
  const t::MeanEstimate m = t::mean_estimate(est);
  EXPECT_GT(std::fabs(m.mean - exact_average()), z_bound() * m.std_error) << describe(m);
}

// Rejection consumes a geometric number of square points per sample with mean 4/pi; pad-zero
// keeps a fraction pi/4 of its samples. Both rates are measured through the API's own counts.
TEST(Consumption, RejectionUsesFourOverPiSquarePointsPerSample) {
  std::vector<double> consumed;
  for (uint32_t m = 0; m < kRandomizations; ++m) {
    const RandomSequence seq(5000 + m);
    DiskSampler<RandomSequence> sampler(Strategy::rejection, seq);
    uint32_t total = 0;
    for (uint32_t s = 0; s < kSamplesPerEstimate; ++s) {
      const DiskSample d = sampler.next();
      ASSERT_EQ(d.weight, 1.0);
      ASSERT_LE(d.point.x * d.point.x + d.point.y * d.point.y, 1.0);
      ASSERT_EQ(d.square_index + 1, total + d.consumed) << "accepted point is the last consumed";
      total += d.consumed;
    }
    ASSERT_EQ(sampler.cursor(), total);
    consumed.push_back(double(total) / kSamplesPerEstimate);
  }
  const t::MeanEstimate m = t::mean_estimate(consumed);
  EXPECT_LE(std::fabs(m.mean - 4.0 / kPi), z_bound() * m.std_error)
      << "mean consumed " << m.mean << " +- " << m.std_error << " expected 4/pi";
}

TEST(Consumption, PadZeroKeepsPiOverFourOfItsSamples) {
  std::vector<double> kept;
  for (uint32_t m = 0; m < kRandomizations; ++m) {
    const RandomSequence seq(9000 + m);
    DiskSampler<RandomSequence> sampler(Strategy::pad_zero, seq);
    uint32_t nonzero = 0;
    for (uint32_t s = 0; s < kSamplesPerEstimate; ++s) {
      const DiskSample d = sampler.next();
      ASSERT_EQ(d.consumed, 1u);
      ASSERT_TRUE(d.weight == 0.0 || d.weight == 4.0 / kPi) << d.weight;
      const bool inside = d.point.x * d.point.x + d.point.y * d.point.y <= 1.0;
      ASSERT_EQ(inside, d.weight > 0.0);
      nonzero += d.weight > 0.0;
    }
    kept.push_back(double(nonzero) / kSamplesPerEstimate);
  }
  const t::MeanEstimate m = t::mean_estimate(kept);
  EXPECT_LE(std::fabs(m.mean - kPi / 4.0), z_bound() * m.std_error)
      << "kept fraction " << m.mean << " +- " << m.std_error << " expected pi/4";
}

// ---- API contracts on deterministic inputs ----

// A sequence that is outside the disk `outside` times (the corner (0,0) -> (-1,-1)), then at
// the centre: rejection must skip exactly those points, and give up after the cap.
struct CornerThenCentre {
  uint32_t outside;
  Point2 at(uint32_t i) const { return i < outside ? Point2{0.0, 0.0} : Point2{0.5, 0.5}; }
};

TEST(RejectionApi, CountsSkippedPointsAndStopsAtTheCap) {
  const RejectionSample a = sample_rejection(CornerThenCentre{3}, 0);
  EXPECT_TRUE(a.accepted);
  EXPECT_EQ(a.consumed, 4u);
  EXPECT_EQ(a.index, 3u);
  EXPECT_EQ(a.weight(), 1.0);
  EXPECT_EQ(a.point.x, 0.0);
  const RejectionSample b = sample_rejection(CornerThenCentre{1000}, 10);
  EXPECT_FALSE(b.accepted);
  EXPECT_EQ(b.consumed, kMaxRejectionTries);
  EXPECT_EQ(b.index, 10 + kMaxRejectionTries - 1);
  EXPECT_EQ(b.weight(), 0.0);
  EXPECT_TRUE(std::isfinite(b.point.x) && std::isfinite(b.point.y));
  // The rim is inside (closed disk): u = 1, v = 1/2 -> (1, 0).
  EXPECT_TRUE(try_rejection({1.0, 0.5}).accepted);
  EXPECT_FALSE(try_rejection({1.0, 1.0}).accepted);
}

TEST(PadZeroApi, WeightIsFourOverPiInsideAndZeroOutside) {
  const PadZeroSample in = sample_pad_zero({0.5, 0.75});
  EXPECT_EQ(in.point.x, 0.0);
  EXPECT_EQ(in.point.y, 0.5);
  EXPECT_EQ(in.weight, 4.0 / kPi);
  const PadZeroSample out = sample_pad_zero({0.0, 1.0});
  EXPECT_EQ(out.point.x, -1.0);
  EXPECT_EQ(out.point.y, 1.0);
  EXPECT_EQ(out.weight, 0.0);
  EXPECT_EQ(centered_to_square(in.point).x, 0.5);
  EXPECT_EQ(centered_to_square(in.point).y, 0.75);
}

TEST(DiskSamplerApi, FourCopyStrategiesReuseEachSquarePointFourTimes) {
  const RandomSequence seq(7);
  for (Strategy st : {Strategy::polar4, Strategy::concentric4}) {
    DiskSampler<RandomSequence> sampler(st, seq, 5);
    for (uint32_t s = 0; s < 12; ++s) {
      const DiskSample d = sampler.next();
      EXPECT_EQ(d.square_index, 5 + s / 4) << "memo Appendix A: sample s uses point s div 4";
      EXPECT_EQ(d.copy, s % 4);
      EXPECT_EQ(d.consumed, s % 4 == 0 ? 1u : 0u);
      const Point2 q = st == Strategy::polar4 ? sample_polar_quarter(seq.at(5 + s / 4))
                                              : sample_concentric_quarter(seq.at(5 + s / 4));
      const Point2 expect = rotate_quarter_turns(q, s % 4);
      EXPECT_EQ(d.point.x, expect.x);
      EXPECT_EQ(d.point.y, expect.y);
      EXPECT_EQ(d.weight, 1.0);
    }
    EXPECT_EQ(sampler.cursor(), 8u);
  }
}

TEST(DiskSamplerApi, NamesRoundTrip) {
  ASSERT_EQ(strategy_names().size(), std::size(kAllStrategies));
  for (Strategy s : kAllStrategies)
    EXPECT_EQ(parse_strategy(strategy_name(s)), s);
  EXPECT_FALSE(parse_strategy("polar5").has_value());
}

}  // namespace
