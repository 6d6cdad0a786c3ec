// Slopes, their bootstrap errors and the claims' verdicts (verify/study/fit.h, claims.h), on
// synthetic data whose answers are known.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "study/claims.h"
#include "study/convergence.h"
#include "study/fit.h"
#include "support/stats.h"

namespace {
using namespace disklab::study;
namespace t = disklab::test;

// ---- Tolerances (the one place for this suite) ----
// An exact power law is fitted to rounding: a few ulps of the logs' spread.
constexpr double kExactSlopeTol = 1e-12;
// Measures of exact power laws: a handful of logarithms and an interpolation, on values O(1) to
// O(1e3): 1e-12 relative.
constexpr double kExactMeasureRel = 1e-12;
// The bootstrap standard error against the spread of independent repeats: both are estimates
// from ~100 values (bootstrap: 400 replicates; repeats: kRepeats), each with ~10% relative
// error, so a factor 1.5 either way is a 4-sigma band.
constexpr double kSeRatioBand = 1.5;
constexpr int kRepeats = 120;

TEST(Fit, RecoversAnExactPowerLaw) {
  for (double slope : {-0.5, -0.75, -1.4, 0.3}) {
    std::vector<double> x, y;
    for (double n = 16; n <= 4096; n *= 2) {
      x.push_back(n);
      y.push_back(3.7e-2 * std::pow(n, slope));
    }
    const LineFit f = fit_log_log(x, y);
    EXPECT_NEAR(f.slope, slope, kExactSlopeTol);
    EXPECT_NEAR(f.intercept, std::log(3.7e-2), 10 * kExactSlopeTol);  // slope x mean log N
    // The test suite's own independent fitter agrees.
    EXPECT_NEAR(f.slope, t::log_log_slope(x, y), kExactSlopeTol);
  }
}

TEST(Fit, RefusesWhatHasNoLogarithm) {
  const std::vector<double> x{1, 2, 4}, y{1, 0, 1}, one{1}, same{2, 2, 2};
  EXPECT_THROW(fit_log_log(x, y), std::invalid_argument);
  EXPECT_THROW(fit_log_log(one, one), std::invalid_argument);
  EXPECT_THROW(fit_log_log(same, x), std::invalid_argument);
}

// A synthetic study: one region of `points` points, every listed curve's per-seed squared error
// set so that its RMS is exactly c N^slope (every seed alike) or, with `noise`, a noisy draw.
ConvergenceResult synthetic(const std::vector<std::string>& strategies,
                            const std::vector<std::string>& sequences,
                            const std::vector<std::string>& regions, uint32_t seeds = 10) {
  ConvergenceResult r;
  auto& c = r.config;
  c.regions.clear();
  for (const std::string& name : regions)
    c.regions.push_back({{name, 0, 1, 0, 1, 2, 2}, true});
  for (const std::string& s : strategies)
    c.strategies.push_back(*disklab::disk::parse_strategy(s));
  c.sequences = sequences;
  c.ns.clear();
  for (uint32_t n = 16; n <= 4096; n *= 2)
    c.ns.push_back(n);
  c.seeds = seeds;
  c.bootstrap_replicates = 400;
  for (const auto& region : c.regions) {
    RegionReferences refs{region.grid.name, "closed-form", {}};
    for (const auto& p : region.grid.points())
      refs.points.push_back({p, {1.0, 0.0}});
    r.references.push_back(refs);
  }
  r.allocate();
  return r;
}

void set_curve(ConvergenceResult& r, const std::string& region, const std::string& strategy,
               const std::string& sequence, double c, double slope) {
  const std::size_t curve = *r.find_curve(region, strategy, sequence);
  for (std::size_t k = 0; k < r.config.ns.size(); ++k) {
    const double e = c * std::pow(static_cast<double>(r.config.ns[k]), slope);
    for (std::size_t s = 0; s < r.config.seeds; ++s) {
      r.sse_at(curve, k, s) = e * e * 4.0;  // 4 points
      r.rel_sse_at(curve, k, s) = e * e * 4.0;
    }
  }
}

TEST(Fit, BootstrapErrorMatchesTheSpreadOfIndependentStudies) {
  // Per seed and N, squared errors of 4 points drawn as c^2 N^(2 s) chi^2_1: the RMS slope of
  // one study scatters around s; its bootstrap SE must match the SD of the slope over repeats.
  const double slope = -1.0;
  std::mt19937_64 rng(99);
  std::normal_distribution<double> normal;
  std::vector<double> slopes, ses;
  for (int rep = 0; rep < kRepeats; ++rep) {
    ConvergenceResult r = synthetic({"polar"}, {"pmj02"}, {"lit-axis"}, 40);
    const std::size_t curve = 0;
    for (std::size_t k = 0; k < r.config.ns.size(); ++k) {
      const double e = std::pow(static_cast<double>(r.config.ns[k]), slope);
      for (std::size_t s = 0; s < r.config.seeds; ++s) {
        double sum = 0.0;
        for (int p = 0; p < 4; ++p) {
          const double g = normal(rng) * e;
          sum += g * g;
        }
        r.sse_at(curve, k, s) = sum;
      }
    }
    const SeedBootstrap b(r.config.seeds, 400, 1000 + rep);
    slopes.push_back(*r.slope(curve));
    ses.push_back(
        *b.standard_error([&](std::span<const uint32_t> w) { return r.slope(curve, w); }));
  }
  const t::MeanEstimate m = t::mean_estimate(slopes);
  const double spread = m.std_error * std::sqrt(static_cast<double>(kRepeats));
  double mean_se = 0.0;
  for (double s : ses)
    mean_se += s / kRepeats;
  EXPECT_NEAR(m.mean, slope, 4.0 * m.std_error) << "the slope itself is unbiased";
  EXPECT_LT(mean_se, kSeRatioBand * spread) << "bootstrap SE " << mean_se << ", spread " << spread;
  EXPECT_GT(mean_se, spread / kSeRatioBand) << "bootstrap SE " << mean_se << ", spread " << spread;
}

TEST(Verdicts, RulesOnMadeUpValues) {
  struct Row {
    Rule rule;
    double measured, max_n;
    Verdict expected;
  };
  const double never = std::numeric_limits<double>::infinity();
  const Rule slope{RuleKind::slope, -1.0}, factor{RuleKind::factor, 3.5};
  const Rule same{RuleKind::about_equal, 1.0}, lower{RuleKind::lower, 0.8};
  const Rule higher{RuleKind::higher, 1.25}, cross{RuleKind::crossover, 2048};
  const Row rows[] = {
      {slope, -1.0, 0, Verdict::reproduced},       {slope, -0.91, 0, Verdict::reproduced},
      {slope, -1.15, 0, Verdict::roughly},         {slope, -0.81, 0, Verdict::roughly},
      {slope, -1.3, 0, Verdict::differs},          {factor, 3.0, 0, Verdict::reproduced},  // x0.86
      {factor, 4.3, 0, Verdict::reproduced},       {factor, 2.5, 0, Verdict::roughly},     // x0.71
      {factor, 1.8, 0, Verdict::differs},          {factor, -1.0, 0, Verdict::differs},
      {same, 1.05, 0, Verdict::reproduced},        {same, 0.8, 0, Verdict::roughly},
      {same, 1.66, 0, Verdict::differs},           {lower, 0.5, 0, Verdict::reproduced},
      {lower, 0.85, 0, Verdict::roughly},          {lower, 0.97, 0, Verdict::differs},
      {higher, 2.0, 0, Verdict::reproduced},       {higher, 1.2, 0, Verdict::roughly},
      {higher, 1.08, 0, Verdict::differs},         {cross, 1500.0, 0, Verdict::reproduced},
      {cross, 700.0, 0, Verdict::roughly},         {cross, 100.0, 0, Verdict::differs},
      {cross, 0.0, 0, Verdict::differs},            // already below at the first N
      {cross, never, 4096, Verdict::differs},       // the claimed window passed
      {cross, never, 1024, Verdict::not_measured},  // the run stopped too early
  };
  for (const Row& r : rows)
    EXPECT_EQ(judge(r.rule, r.measured, r.max_n), r.expected)
        << rule_text(r.rule) << ", measured " << r.measured << ", max N " << r.max_n;
  EXPECT_EQ(judge(slope, std::nullopt), Verdict::not_measured);
}

TEST(Claims, SlopeClaimsOnASyntheticStudy) {
  ConvergenceResult r =
      synthetic({"polar", "polar4"}, {"random", "pmj02"}, {"lit-axis", "lit-off"});
  for (const std::string region : {"lit-axis", "lit-off"}) {
    set_curve(r, region, "polar", "random", 0.1, -0.5);
    set_curve(r, region, "polar4", "random", 0.1, -0.5);
    set_curve(r, region, "polar4", "pmj02", 0.1, -1.4);
  }
  set_curve(r, "lit-axis", "polar", "pmj02", 0.1, -1.25);
  set_curve(r, "lit-off", "polar", "pmj02", 0.1, -0.9);  // differs from the claimed -1.25

  const std::vector<Claim> claims = memo_claims(r.config.sequences);
  const SeedBootstrap b(r.config.seeds, 50, 1);
  const std::vector<ClaimOutcome> out = evaluate_claims(claims, r, b);
  auto find = [&](const std::string& id, const std::string& region) -> const ClaimOutcome& {
    for (const ClaimOutcome& o : out)
      if (claims[o.claim].id == id && o.region == region) return o;
    ADD_FAILURE() << "no outcome " << id << " / " << region;
    static ClaimOutcome none;
    return none;
  };
  EXPECT_EQ(find("lit.polar.random.slope", "lit-axis").verdict, Verdict::reproduced);
  EXPECT_NEAR(*find("lit.polar.random.slope", "lit-axis").measured, -0.5, kExactSlopeTol);
  EXPECT_EQ(find("lit.polar.pmj02.slope", "lit-axis").verdict, Verdict::reproduced);
  EXPECT_EQ(find("lit.polar.pmj02.slope", "lit-off").verdict, Verdict::differs);
  EXPECT_EQ(find("lit.polar4.pmj02.slope", "lit-off").verdict, Verdict::reproduced);
  // Identical seeds: the bootstrap has nothing to resample.
  EXPECT_NEAR(*find("lit.polar4.pmj02.slope", "lit-off").se, 0.0, kExactSlopeTol);
  // Claims needing what the run lacks say so.
  const ClaimOutcome& missing = find("lit.polar.sobol-owen.slope", "lit-axis");
  EXPECT_EQ(missing.verdict, Verdict::not_measured);
  EXPECT_NE(missing.note.find("sobol-owen"), std::string::npos);
  // The Markdown flags the region dependence it sees.
  const std::string md = claims_markdown(claims, out, memo_sections(), "Ratios are of RMS errors.");
  EXPECT_NE(md.find("depends on the region"), std::string::npos);
}

TEST(Claims, CrossoverAndSampleRatioOnExactPowerLaws) {
  ConvergenceResult r = synthetic({"polar", "polar4"}, {"sobol-xor", "pmj02"}, {"lit-axis"});
  // a = N^-1, b = 32 N^-1.5: equal where N^0.5 = 32, at N = 1024.
  set_curve(r, "lit-axis", "polar", "sobol-xor", 1.0, -1.0);
  set_curve(r, "lit-axis", "polar", "pmj02", 32.0, -1.5);
  const Measure cross = measures::crossover("polar", "sobol-xor", "polar", "pmj02");
  EXPECT_NEAR(*cross(r, 0, {}), 1024.0, kExactMeasureRel * 1024.0);
  // Swapped: b starts below a, so the crossover is "already at the first N" (0).
  EXPECT_EQ(*measures::crossover("polar", "pmj02", "polar", "sobol-xor")(r, 0, {}), 0.0);
  // polar4 = 0.25 N^-1: it reaches a's error at N = n with n / 4 samples: ratio 4, at any n.
  set_curve(r, "lit-axis", "polar4", "pmj02", 0.25, -1.0);
  const Measure ratio = measures::sample_ratio("polar", "sobol-xor", "polar4", "pmj02", 256);
  EXPECT_NEAR(*ratio(r, 0, {}), 4.0, kExactMeasureRel * 4.0);
  EXPECT_NEAR(*measures::ratio_at("polar", "sobol-xor", "polar4", "pmj02", 256)(r, 0, {}), 4.0,
              kExactMeasureRel * 4.0);
  EXPECT_NEAR(*measures::mean_ratio("polar", "sobol-xor", "polar4", "pmj02")(r, 0, {}), 4.0,
              kExactMeasureRel * 4.0);
  EXPECT_FALSE(measures::ratio_at("polar", "sobol-xor", "polar4", "pmj02", 300)(r, 0, {}));
}

}  // namespace
