#pragma once
// Claims of a paper next to what a study measures, with a verdict computed by a stated rule.
// The rules are generic (slopes, factors, "about the same", "lower", "higher", a crossover
// sample count, an upper bound); claims are measured on a study's CurveTable with bootstrap
// standard errors over its seeds. The memo's claims (Christensen 2018, Secs. 4.1-4.2) are listed
// in memo_claims().
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "study/curves.h"
#include "study/fit.h"

namespace disklab::study {

enum class Verdict { reproduced, roughly, differs, not_measured };
const char* verdict_name(Verdict v);

enum class RuleKind {
  slope,        // |m - c| <= 0.10 reproduced, <= 0.20 roughly
  factor,       // m / c within x1.25 reproduced, within x1.5 roughly (either way)
  about_equal,  // a ratio that should be 1 ("a few percent"): |m - 1| <= 0.10, <= 0.25
  lower,        // a ratio below c: m <= c reproduced, m <= (1 + c) / 2 roughly
  higher,       // a ratio above c: m >= c reproduced, m >= (1 + c) / 2 roughly
  crossover,    // a sample count: |log2(m / c)| <= 1 reproduced, <= 2 roughly
  at_most,      // "up to c": m <= c reproduced, m <= 1.5 c roughly
};

struct Rule {
  RuleKind kind = RuleKind::slope;
  double claimed = 0.0;
};

// The verdict of a measured value. nullopt (nothing to measure) is not_measured. A crossover
// measured as +infinity means "not within the run's sample counts": it differs once the run
// reached 4x the claim, else it is not_measured.
Verdict judge(const Rule& rule, std::optional<double> measured, double max_n = 0.0);
// The rule in words, for the report.
std::string rule_text(const Rule& rule);

using Measure = std::function<std::optional<double>(const CurveTable&, std::size_t region,
                                                    std::span<const uint32_t> weights)>;

struct Claim {
  std::string id;           // stable key, e.g. "lit.polar.pmj02.slope"
  std::string section;      // a ClaimSection key, e.g. "fully lit"
  std::string text;         // the memo's claim, in our words, with its section
  std::string measured_as;  // how the number is computed here
  Rule rule;
  std::vector<std::string> regions;
  std::vector<std::string> needs_sequences, needs_methods;  // to say why it is not measured
  Measure measure;
  // False for a value measured once (a count, a timing): no bootstrap standard error.
  bool bootstrap = true;
};

// A table of the markdown: the claims whose section is `key`, under the heading `title`.
struct ClaimSection {
  std::string key, title;
};

struct ClaimOutcome {
  std::size_t claim = 0;  // index into the claim list
  std::string region;
  std::optional<double> measured, se;
  Verdict verdict = Verdict::not_measured;
  std::string note;  // why not measured, or the difference from the claim
};

// The memo's claims; claims about "every other sequence" expand over `sequences` (the run's).
std::vector<Claim> memo_claims(const std::vector<std::string>& sequences);
// "fully lit" (memo Sec. 4.1) and "penumbra" (Sec. 4.2).
std::vector<ClaimSection> memo_sections();

std::vector<ClaimOutcome> evaluate_claims(const std::vector<Claim>& claims, const CurveTable& table,
                                          const SeedBootstrap& bootstrap);

// Markdown: the rules in use, one table per section (one column pair per region), and a tally.
// `ratios_note` says what the ratios are ratios of.
std::string claims_markdown(const std::vector<Claim>& claims,
                            const std::vector<ClaimOutcome>& outcomes,
                            const std::vector<ClaimSection>& sections,
                            const std::string& ratios_note);

// Measures shared by the claims (exposed for the tests). All return nullopt if a curve or N
// is missing from the run. A "strategy" is a curve table's method.
namespace measures {
// Slope of one curve.
Measure slope(const std::string& strategy, const std::string& sequence);
// The steepest (most negative) slope of `strategy` over every sequence of the run.
Measure best_slope(const std::string& strategy);
// slope(a) - slope(b) for one sequence.
Measure slope_difference(const std::string& strategy_a, const std::string& strategy_b,
                         const std::string& sequence);
// A value measured once (bootstrap replicates see the same value).
Measure constant(std::optional<double> value);
// rmse(a) / rmse(b) at N = n (n = 0: the run's smallest N).
Measure ratio_at(const std::string& strategy_a, const std::string& sequence_a,
                 const std::string& strategy_b, const std::string& sequence_b, uint32_t n);
// Geometric mean over the fit range of rmse(a) / rmse(b).
Measure mean_ratio(const std::string& strategy_a, const std::string& sequence_a,
                   const std::string& strategy_b, const std::string& sequence_b);
// First N (interpolated in log N) at which curve b's rmse falls to curve a's; +infinity if it
// does not within the run, 0 if it is already below at the smallest N.
Measure crossover(const std::string& strategy_a, const std::string& sequence_a,
                  const std::string& strategy_b, const std::string& sequence_b);
// n / N_b, where N_b (interpolated in log-log) is the sample count at which curve b reaches the
// error curve a has at N = n: how many times fewer samples b needs for that error.
Measure sample_ratio(const std::string& strategy_a, const std::string& sequence_a,
                     const std::string& strategy_b, const std::string& sequence_b, uint32_t n);
}  // namespace measures

}  // namespace disklab::study
