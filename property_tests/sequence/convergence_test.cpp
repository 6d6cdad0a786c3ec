// Convergence of the randomized quadrature error over the unit square (Christensen 2018, Sec. 3
// and docs/design.md "Randomizations and nets"): RMS error over many seeds at N = 2^4 .. 2^12,
// fitted log-log slope. Owen-scrambled nets (sobol-owen, pmj02) reach ~N^-1.5 on a smooth integrand
// and ~N^-0.75 on one with a discontinuity along a curve; random points ~N^-0.5 on both.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common.h"
#include "disklab/math/constants.h"
#include "disklab/sequence/random.h"
#include "disklab/sequence/sequence.h"
#include "disklab/sequence/sobol.h"
#include "disklab/sequence/tabulated.h"
#include "support/stats.h"

namespace disklab::sequence {
namespace {

constexpr int kMinLog2 = 4, kMaxLog2 = 12;
constexpr int kSeeds = 128;
constexpr int kBootstrap = 200;

// Expected slope and its tolerance. The asymptotic rates carry slowly varying factors (Owen's
// smooth-case variance is O(N^-3 log N), so the local slope over this range is about -1.5 +
// 0.5/ln N ~ -1.43; measured -1.39 for both sobol-owen and pmj02), hence a model tolerance of 0.15
// around the nominal rate; the statistical spread of the fitted slope (bootstrap over the seeds) is
// required to be well below it, at most kMaxSpreadFraction of the tolerance, so that a pass is not
// luck of the seeds.
constexpr double kSlopeTolerance = 0.15;
constexpr double kMaxSpreadFraction = 0.5;
// Owen vs rotation/xor on the smooth integrand: measured slope gaps 0.18 and 0.22 and RMS ratios
// 2.7 and 5.2 at N = 4096 (bootstrap sd of each slope ~0.015): require 0.1 and 2.
constexpr double kRandomizationGap = 0.1;
constexpr double kRmsRatio = 2.0;

struct Integrand {
  const char* name;
  std::function<double(Point2)> f;
  double exact;
};

// Isotropic Gaussian centred off the square's centre: smooth, not periodic, not separable-trivial.
constexpr double kSigma = 0.3, kMx = 0.45, kMy = 0.6;
double gauss_1d(double mu) {
  return kSigma * std::sqrt(math::kPi / 2.0) *
         (std::erf((1.0 - mu) / (kSigma * std::sqrt(2.0))) +
          std::erf(mu / (kSigma * std::sqrt(2.0))));
}
// Quarter disk of radius kR centred at the origin: a discontinuity along a curve.
constexpr double kR = 0.9;

const Integrand kIntegrands[] = {
    {"gaussian",
     [](Point2 p) {
       return std::exp(-((p.x - kMx) * (p.x - kMx) + (p.y - kMy) * (p.y - kMy)) /
                       (2 * kSigma * kSigma));
     },
     gauss_1d(kMx) * gauss_1d(kMy)},
    {"quarter-disk", [](Point2 p) { return p.x * p.x + p.y * p.y < kR * kR ? 1.0 : 0.0; },
     math::kPi* kR* kR / 4.0},
};

struct Case {
  const char* sequence;
  std::function<std::unique_ptr<Sequence>(uint64_t)> make;
  double slope[2];  // expected, per integrand
};

// errors[seed][level]: signed error of the N = 2^(kMinLog2 + level) prefix estimate.
std::vector<std::vector<double>> errors_for(const Case& c, const Integrand& in) {
  std::vector<std::vector<double>> e(kSeeds, std::vector<double>(kMaxLog2 - kMinLog2 + 1));
  for (int s = 0; s < kSeeds; ++s) {
    const auto seq = c.make(derive_seed(2026, static_cast<uint64_t>(s)));
    double sum = 0.0;
    for (uint32_t i = 0; i < (1u << kMaxLog2); ++i) {
      sum += in.f(seq->at(i));
      const uint32_t n = i + 1;
      if (n >= (1u << kMinLog2) && std::has_single_bit(n))
        e[s][std::bit_width(n) - 1 - kMinLog2] = sum / n - in.exact;
    }
  }
  return e;
}

double slope_of(const std::vector<std::vector<double>>& e, const std::vector<int>& seeds,
                std::vector<double>* rms_out = nullptr) {
  std::vector<double> ns, rms;
  for (int level = 0; level <= kMaxLog2 - kMinLog2; ++level) {
    double ss = 0.0;
    for (int s : seeds)
      ss += e[s][level] * e[s][level];
    ns.push_back(std::ldexp(1.0, kMinLog2 + level));
    rms.push_back(std::sqrt(ss / seeds.size()));
  }
  if (rms_out) *rms_out = rms;
  return test::log_log_slope(ns, rms);
}

TEST(Convergence, FittedSlopesMatchTheKnownRates) {
  const Case cases[] = {
      {"random", [](uint64_t s) { return make_sequence("random", s); }, {-0.5, -0.5}},
      {"sobol-owen", [](uint64_t s) { return make_sequence("sobol-owen", s); }, {-1.5, -0.75}},
      {"pmj02",
       [](uint64_t s) {
         return std::make_unique<SequenceAdapter<Pmj02>>("pmj02", Pmj02(s, 1u << kMaxLog2));
       },
       {-1.5, -0.75}},
      // A rotation or a digital shift randomizes the net without Owen's nested independence:
      // smooth convergence is asymptotically ~N^-1 (docs/design.md; Christensen 2018 Figs. 5-6 show
      // the gap to Owen/pmj02). Over N = 16..4096 the fitted slopes are about -1.2 (erratic
      // curves between the two regimes), so no nominal slope is asserted for the smooth case
      // (NaN); the gap to Owen is asserted below instead.
      {"sobol-rotated", [](uint64_t s) { return make_sequence("sobol-rotated", s); }, {NAN, -0.75}},
      {"sobol-xor", [](uint64_t s) { return make_sequence("sobol-xor", s); }, {NAN, -0.75}},
  };
  Pcg32 boot(17);
  std::map<std::string, double> smooth_slope, smooth_rms_last;
  for (const Case& c : cases)
    for (int k = 0; k < 2; ++k) {
      const Integrand& in = kIntegrands[k];
      const auto e = errors_for(c, in);
      std::vector<int> all(kSeeds);
      for (int s = 0; s < kSeeds; ++s)
        all[s] = s;
      std::vector<double> rms;
      const double slope = slope_of(e, all, &rms);
      // Bootstrap over seeds: the spread of the fitted slope.
      double m1 = 0.0, m2 = 0.0;
      for (int b = 0; b < kBootstrap; ++b) {
        std::vector<int> pick(kSeeds);
        for (int& s : pick)
          s = static_cast<int>(boot.next_u32() % kSeeds);
        const double sb = slope_of(e, pick);
        m1 += sb / kBootstrap;
        m2 += sb * sb / kBootstrap;
      }
      const double spread = std::sqrt(std::max(0.0, m2 - m1 * m1));
      std::printf(
          "%-11s %-13s slope %+.3f (expected %+.2f, bootstrap sd %.3f); RMS at N=2^%d..2^%d:",
          c.sequence, in.name, slope, c.slope[k], spread, kMinLog2, kMaxLog2);
      for (double r : rms)
        std::printf(" %.3g", r);
      std::printf("\n");
      if (!std::isnan(c.slope[k])) {
        EXPECT_NEAR(slope, c.slope[k], kSlopeTolerance)
            << c.sequence << " on " << in.name << " (bootstrap sd " << spread << ")";
      }
      if (k == 0) {
        smooth_slope[c.sequence] = slope;
        smooth_rms_last[c.sequence] = rms.back();
      }
      EXPECT_LT(spread, kMaxSpreadFraction * kSlopeTolerance) << c.sequence << " on " << in.name;
    }
  // Owen scrambling beats rotation and xor on the smooth integrand: a steeper fit (by more than
  // kRandomizationGap, over 6 bootstrap sd) and a clearly smaller error at N = 4096.
  for (const char* weaker : {"sobol-rotated", "sobol-xor"}) {
    EXPECT_LT(smooth_slope["sobol-owen"], smooth_slope[weaker] - kRandomizationGap)
        << "smooth slopes: sobol-owen " << smooth_slope["sobol-owen"] << ", " << weaker << " "
        << smooth_slope[weaker];
    EXPECT_GT(smooth_rms_last[weaker], kRmsRatio * smooth_rms_last["sobol-owen"])
        << "smooth RMS at N=4096: sobol-owen " << smooth_rms_last["sobol-owen"] << ", " << weaker
        << " " << smooth_rms_last[weaker];
  }
}

}  // namespace
}  // namespace disklab::sequence
