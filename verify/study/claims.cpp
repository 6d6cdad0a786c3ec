#include "study/claims.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace disklab::study {

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::reproduced:
      return "reproduced";
    case Verdict::roughly:
      return "roughly";
    case Verdict::differs:
      return "differs";
    default:
      return "not measured";
  }
}

Verdict judge(const Rule& rule, std::optional<double> measured, double max_n) {
  if (!measured || std::isnan(*measured)) return Verdict::not_measured;
  const double m = *measured, c = rule.claimed;
  auto grade = [](bool good, bool fair) {
    return good ? Verdict::reproduced : (fair ? Verdict::roughly : Verdict::differs);
  };
  switch (rule.kind) {
    case RuleKind::slope:
      return grade(std::fabs(m - c) <= 0.10, std::fabs(m - c) <= 0.20);
    case RuleKind::factor: {
      if (!(m > 0.0)) return Verdict::differs;
      const double f = std::fabs(std::log(m / c));
      return grade(f <= std::log(1.25), f <= std::log(1.5));
    }
    case RuleKind::about_equal:
      return grade(std::fabs(m - 1.0) <= 0.10, std::fabs(m - 1.0) <= 0.25);
    case RuleKind::lower:
      return grade(m <= c, m <= 0.5 * (1.0 + c));
    case RuleKind::higher:
      return grade(m >= c, m >= 0.5 * (1.0 + c));
    case RuleKind::crossover: {
      if (std::isinf(m) && m > 0.0)
        return max_n >= 2.0 * c ? Verdict::differs : Verdict::not_measured;
      if (!(m > 0.0)) return Verdict::differs;
      const double f = std::fabs(std::log2(m / c));
      return grade(f <= 1.0, f <= 2.0);
    }
    case RuleKind::at_most:
      return grade(m <= c, m <= 1.5 * c);
  }
  return Verdict::not_measured;
}

std::string rule_text(const Rule& rule) {
  char buf[200];
  switch (rule.kind) {
    case RuleKind::slope:
      std::snprintf(buf, sizeof buf, "slope %+.2f: within 0.10 reproduced, 0.20 roughly",
                    rule.claimed);
      break;
    case RuleKind::factor:
      std::snprintf(buf, sizeof buf, "factor %.3g: within x1.25 reproduced, x1.5 roughly",
                    rule.claimed);
      break;
    case RuleKind::about_equal:
      std::snprintf(buf, sizeof buf, "ratio 1: within 0.10 reproduced, 0.25 roughly");
      break;
    case RuleKind::lower:
      std::snprintf(buf, sizeof buf, "ratio <= %.3g reproduced, <= %.3g roughly", rule.claimed,
                    0.5 * (1.0 + rule.claimed));
      break;
    case RuleKind::higher:
      std::snprintf(buf, sizeof buf, "ratio >= %.3g reproduced, >= %.3g roughly", rule.claimed,
                    0.5 * (1.0 + rule.claimed));
      break;
    case RuleKind::crossover:
      std::snprintf(buf, sizeof buf, "N %.0f: within x2 reproduced, x4 roughly", rule.claimed);
      break;
    case RuleKind::at_most:
      std::snprintf(buf, sizeof buf, "<= %.3g reproduced, <= %.3g roughly", rule.claimed,
                    1.5 * rule.claimed);
      break;
  }
  return buf;
}

namespace {
using Weights = std::span<const uint32_t>;
using Opt = std::optional<double>;

const std::string& region_name(const CurveTable& r, std::size_t region) {
  return r.axes.regions[region];
}
std::optional<std::size_t> curve(const CurveTable& r, std::size_t region,
                                 const std::string& strategy, const std::string& sequence) {
  return r.find_curve(region_name(r, region), strategy, sequence);
}
Opt log_rmse(const CurveTable& r, std::size_t c, std::size_t k, Weights w) {
  const double e = r.rmse(c, k, w);
  if (!(e > 0.0)) return std::nullopt;
  return std::log(e);
}
// exp of the mean of log_ratio(k) over the fit range: a geometric mean of RMS ratios. nullopt
// if any term is undefined.
template <class F>
Opt fit_range_geomean(const CurveTable& r, F&& log_ratio) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t k : r.fit_indices()) {
    const Opt l = log_ratio(k);
    if (!l) return std::nullopt;
    sum += *l;
    ++count;
  }
  if (count == 0) return std::nullopt;
  return std::exp(sum / count);
}
// The lowest log rmse at ns[k] over the curves of these strategies and sequences in the run.
Opt min_log_rmse(const CurveTable& r, std::size_t region,
                 const std::vector<std::string>& strategies,
                 const std::vector<std::string>& sequences, std::size_t k, Weights w) {
  Opt best;
  for (const std::string& st : strategies)
    for (const std::string& q : sequences) {
      const auto c = curve(r, region, st, q);
      if (!c) continue;
      const Opt l = log_rmse(r, *c, k, w);
      if (l && (!best || *l < *best)) best = l;
    }
  return best;
}
// log rmse(a) - log rmse(b) at ns[k].
Opt log_ratio_at(const CurveTable& r, std::size_t a, std::size_t b, std::size_t k, Weights w) {
  const Opt la = log_rmse(r, a, k, w), lb = log_rmse(r, b, k, w);
  if (!la || !lb) return std::nullopt;
  return *la - *lb;
}
}  // namespace

namespace measures {

Measure slope(const std::string& strategy, const std::string& sequence) {
  return [=](const CurveTable& r, std::size_t region, Weights w) -> Opt {
    const auto c = curve(r, region, strategy, sequence);
    if (!c) return std::nullopt;
    return r.slope(*c, w);
  };
}

Measure best_slope(const std::string& strategy) {
  return [=](const CurveTable& r, std::size_t region, Weights w) -> Opt {
    Opt best;
    for (const std::string& q : r.axes.sequences) {
      const auto c = curve(r, region, strategy, q);
      if (!c) continue;
      const Opt s = r.slope(*c, w);
      if (s && (!best || *s < *best)) best = s;
    }
    return best;
  };
}

Measure constant(std::optional<double> value) {
  return [=](const CurveTable&, std::size_t, Weights) { return value; };
}

Measure slope_difference(const std::string& strategy_a, const std::string& strategy_b,
                         const std::string& sequence) {
  return [=](const CurveTable& r, std::size_t region, Weights w) -> Opt {
    const auto a = curve(r, region, strategy_a, sequence),
               b = curve(r, region, strategy_b, sequence);
    if (!a || !b) return std::nullopt;
    const Opt sa = r.slope(*a, w), sb = r.slope(*b, w);
    if (!sa || !sb) return std::nullopt;
    return *sa - *sb;
  };
}

Measure ratio_at(const std::string& strategy_a, const std::string& sequence_a,
                 const std::string& strategy_b, const std::string& sequence_b, uint32_t n) {
  return [=](const CurveTable& r, std::size_t region, Weights w) -> Opt {
    const auto a = curve(r, region, strategy_a, sequence_a);
    const auto b = curve(r, region, strategy_b, sequence_b);
    const auto k = n == 0 ? std::optional<std::size_t>(0) : r.find_n(n);
    if (!a || !b || !k) return std::nullopt;
    const double eb = r.rmse(*b, *k, w);
    if (!(eb > 0.0)) return std::nullopt;
    return r.rmse(*a, *k, w) / eb;
  };
}

Measure mean_ratio(const std::string& strategy_a, const std::string& sequence_a,
                   const std::string& strategy_b, const std::string& sequence_b) {
  return [=](const CurveTable& r, std::size_t region, Weights w) -> Opt {
    const auto a = curve(r, region, strategy_a, sequence_a);
    const auto b = curve(r, region, strategy_b, sequence_b);
    if (!a || !b) return std::nullopt;
    return fit_range_geomean(r, [&](std::size_t k) { return log_ratio_at(r, *a, *b, k, w); });
  };
}

Measure crossover(const std::string& strategy_a, const std::string& sequence_a,
                  const std::string& strategy_b, const std::string& sequence_b) {
  return [=](const CurveTable& r, std::size_t region, Weights w) -> Opt {
    const auto a = curve(r, region, strategy_a, sequence_a);
    const auto b = curve(r, region, strategy_b, sequence_b);
    if (!a || !b) return std::nullopt;
    const auto& ns = r.ns();
    double prev = 0.0;  // log rmse_b - log rmse_a at ns[k - 1]
    for (std::size_t k = 0; k < ns.size(); ++k) {
      const Opt la = log_rmse(r, *a, k, w), lb = log_rmse(r, *b, k, w);
      if (!la || !lb) return std::nullopt;
      const double d = *lb - *la;
      if (d <= 0.0) {
        if (k == 0) return 0.0;
        const double x0 = std::log2(static_cast<double>(ns[k - 1]));
        const double x1 = std::log2(static_cast<double>(ns[k]));
        return std::exp2(x0 + (x1 - x0) * prev / (prev - d));
      }
      prev = d;
    }
    return std::numeric_limits<double>::infinity();
  };
}

Measure sample_ratio(const std::string& strategy_a, const std::string& sequence_a,
                     const std::string& strategy_b, const std::string& sequence_b, uint32_t n) {
  return [=](const CurveTable& r, std::size_t region, Weights w) -> Opt {
    const auto a = curve(r, region, strategy_a, sequence_a);
    const auto b = curve(r, region, strategy_b, sequence_b);
    const auto ka = r.find_n(n);
    if (!a || !b || !ka) return std::nullopt;
    const Opt target = log_rmse(r, *a, *ka, w);
    if (!target) return std::nullopt;
    const auto& ns = r.ns();
    for (std::size_t k = 1; k < ns.size(); ++k) {
      const Opt l0 = log_rmse(r, *b, k - 1, w), l1 = log_rmse(r, *b, k, w);
      if (!l0 || !l1) return std::nullopt;
      // The first segment of b's curve that passes the target (b decreasing through it).
      if (*l0 >= *target && *l1 <= *target && *l0 > *l1) {
        const double x0 = std::log(static_cast<double>(ns[k - 1]));
        const double x1 = std::log(static_cast<double>(ns[k]));
        const double x = x0 + (x1 - x0) * (*l0 - *target) / (*l0 - *l1);
        return static_cast<double>(n) / std::exp(x);
      }
    }
    return std::nullopt;  // b does not reach that error within the run (or starts below it)
  };
}

}  // namespace measures

namespace {

const std::vector<std::string> kLit = {"lit-axis", "lit-off"};
const std::vector<std::string> kPenumbra = {"penumbra"};

// Geometric mean over the fit range of rmse(strategy, seq) / min over `others` of rmse(other,
// seq): how a strategy compares with the best of the alternatives.
Measure ratio_to_best_other(const std::string& strategy, const std::string& sequence,
                            const std::vector<std::string>& others) {
  return [=](const CurveTable& r, std::size_t region, Weights w) -> Opt {
    const auto a = curve(r, region, strategy, sequence);
    if (!a) return std::nullopt;
    return fit_range_geomean(r, [&](std::size_t k) -> Opt {
      const Opt la = log_rmse(r, *a, k, w),
                best = min_log_rmse(r, region, others, {sequence}, k, w);
      if (!la || !best) return std::nullopt;
      return *la - *best;
    });
  };
}

// Geometric mean over the fit range of min over sequences of rmse(strategy_a, .) divided by the
// same for the best of `strategies_b`: the best curve of one strategy against the best of others.
Measure best_vs_best(const std::string& strategy_a, const std::vector<std::string>& strategies_b) {
  return [=](const CurveTable& r, std::size_t region, Weights w) -> Opt {
    const auto& qs = r.axes.sequences;
    return fit_range_geomean(r, [&](std::size_t k) -> Opt {
      const Opt la = min_log_rmse(r, region, {strategy_a}, qs, k, w);
      const Opt lb = min_log_rmse(r, region, strategies_b, qs, k, w);
      if (!la || !lb) return std::nullopt;
      return *la - *lb;
    });
  };
}

// Geometric mean over the fit range of rmse(strategy, sequence) / the median over `others`.
Measure ratio_to_median(const std::string& strategy, const std::string& sequence,
                        const std::vector<std::string>& others) {
  return [=](const CurveTable& r, std::size_t region, Weights w) -> Opt {
    const auto a = curve(r, region, strategy, sequence);
    if (!a) return std::nullopt;
    return fit_range_geomean(r, [&](std::size_t k) -> Opt {
      std::vector<double> logs;
      for (const std::string& o : others) {
        const auto c = curve(r, region, strategy, o);
        if (!c) continue;
        if (const Opt l = log_rmse(r, *c, k, w)) logs.push_back(*l);
      }
      const Opt la = log_rmse(r, *a, k, w);
      if (!la || logs.empty()) return std::nullopt;
      std::sort(logs.begin(), logs.end());
      const std::size_t m = logs.size();
      return *la - (m % 2 ? logs[m / 2] : 0.5 * (logs[m / 2 - 1] + logs[m / 2]));
    });
  };
}

struct Builder {
  std::vector<Claim> claims;
  void add(std::string id, std::string section, std::string text, std::string measured_as,
           Rule rule, std::vector<std::string> regions, std::vector<std::string> sequences,
           std::vector<std::string> strategies, Measure measure) {
    claims.push_back({std::move(id), std::move(section), std::move(text), std::move(measured_as),
                      rule, std::move(regions), std::move(sequences), std::move(strategies),
                      std::move(measure)});
  }
};

}  // namespace

std::vector<Claim> memo_claims(const std::vector<std::string>& sequences) {
  Builder b;
  // "Every other sequence" of the memo: the run's sequences (and ART, which the memo names)
  // except random and best candidates.
  std::vector<std::string> stratified;
  for (const std::string& q : sequences)
    if (q != "random" && q != "best-candidate") stratified.push_back(q);
  if (std::find(stratified.begin(), stratified.end(), "art") == stratified.end())
    stratified.insert(stratified.begin(), "art");
  const std::string lit = "fully lit", pen = "penumbra";
  const Rule slope_half{RuleKind::slope, -0.5};
  const std::vector<std::string> maps = {"polar", "concentric", "polar4", "concentric4"};
  const std::vector<std::string> all_strategies = {"pad-zero",   "rejection", "polar",
                                                   "concentric", "polar4",    "concentric4"};
  const std::vector<std::string> qmc_plain = {"halton-rotated", "halton-scrambled", "sobol-rotated",
                                              "sobol-xor"};
  const std::vector<std::string> best_nets = {"pmj02", "sobol-owen"};

  // ---- Sec. 4.1, fully lit ----
  for (const char* st : {"pad-zero", "rejection"})
    b.add(std::string("lit.") + st + ".best-slope", lit,
          std::string(st) + ": O(N^-0.75) for the best sequences (Sec. 4.1)",
          "steepest slope over every sequence", {RuleKind::slope, -0.75}, kLit, {}, {st},
          measures::best_slope(st));
  for (const char* st : {"polar", "concentric"})
    for (const char* q : {"random", "best-candidate"})
      b.add(std::string("lit.") + st + "." + q + ".slope", lit,
            std::string(st) + " with " + q + ": O(N^-0.5) (Sec. 4.1)", "slope", slope_half, kLit,
            {q}, {st}, measures::slope(st, q));
  for (const std::string& q : qmc_plain)
    b.add("lit.polar." + q + ".slope", lit,
          "polar with rotated/scrambled Halton, rotated/xor Sobol': roughly O(N^-1) (Sec. 4.1)",
          "slope (" + q + ")", {RuleKind::slope, -1.0}, kLit, {q}, {"polar"},
          measures::slope("polar", q));
  for (const std::string& q : best_nets)
    b.add("lit.polar." + q + ".slope", lit,
          "polar with pmj02, Owen-scrambled Sobol': roughly O(N^-1.25) (Sec. 4.1)",
          "slope (" + q + ")", {RuleKind::slope, -1.25}, kLit, {q}, {"polar"},
          measures::slope("polar", q));
  for (const std::string& q : best_nets) {
    b.add("lit.polar.xor-start." + q, lit,
          "polar: xor-scrambled Sobol' starts with much lower error than pmj02/Owen (Sec. 4.1)",
          "rmse(sobol-xor) / rmse(" + q + ") at the smallest N", {RuleKind::lower, 0.5}, kLit,
          {"sobol-xor", q}, {"polar"}, measures::ratio_at("polar", "sobol-xor", "polar", q, 0));
    b.add("lit.polar.xor-caught." + q, lit,
          "polar: pmj02/Owen catch up with xor-Sobol' only at about 2048 samples (Sec. 4.1)",
          "first N where rmse(" + q + ") <= rmse(sobol-xor), interpolated in log N",
          {RuleKind::crossover, 2048}, kLit, {"sobol-xor", q}, {"polar"},
          measures::crossover("polar", "sobol-xor", "polar", q));
  }
  for (const std::string& q : qmc_plain)
    b.add("lit.concentric." + q + ".slope", lit,
          "concentric with most other sequences: O(N^-1) (Sec. 4.1)", "slope (" + q + ")",
          {RuleKind::slope, -1.0}, kLit, {q}, {"concentric"}, measures::slope("concentric", q));
  for (const std::string& q : best_nets)
    b.add("lit.concentric." + q + ".slope", lit,
          "concentric with pmj02, Owen-scrambled Sobol': around O(N^-1.15) (Sec. 4.1)",
          "slope (" + q + ")", {RuleKind::slope, -1.15}, kLit, {q}, {"concentric"},
          measures::slope("concentric", q));
  b.add("lit.concentric.xor-vs-owen", lit,
        "concentric: xor scrambling is clearly worse than Owen scrambling (Sec. 4.1)",
        "rmse(sobol-xor) / rmse(sobol-owen), geometric mean over the fit range",
        {RuleKind::higher, 1.25}, kLit, {"sobol-xor", "sobol-owen"}, {"concentric"},
        measures::mean_ratio("concentric", "sobol-xor", "concentric", "sobol-owen"));
  for (const std::string& q : best_nets)
    b.add("lit.polar4." + q + ".slope", lit,
          "polar4 with pmj02, Owen-scrambled Sobol': roughly O(N^-1.4) (Sec. 4.1)",
          "slope (" + q + ")", {RuleKind::slope, -1.4}, kLit, {q}, {"polar4"},
          measures::slope("polar4", q));
  for (const std::string& q : best_nets)
    b.add("lit.n256." + q, lit,
          "N = 256: polar4 with pmj02/Owen has 3.5x lower error than polar with xor-Sobol' "
          "(memo: 8.5e-5 vs 2.5e-5) (Sec. 4.1)",
          "rmse(polar, sobol-xor) / rmse(polar4, " + q + ") at N = 256", {RuleKind::factor, 3.5},
          kLit, {"sobol-xor", q}, {"polar", "polar4"},
          measures::ratio_at("polar", "sobol-xor", "polar4", q, 256));
  for (const std::string& q : best_nets) {
    b.add("lit.reach-1e-4." + q, lit,
          "reaching 1e-4 takes 128 samples with polar4 (pmj02/Owen), 256 with polar (Sec. 4.1)",
          "256 / N at which polar4 (" + q + ") reaches the error of polar (sobol-xor) at N = 256",
          {RuleKind::factor, 2.0}, kLit, {"sobol-xor", q}, {"polar", "polar4"},
          measures::sample_ratio("polar", "sobol-xor", "polar4", q, 256));
    b.add("lit.reach-1e-5." + q, lit,
          "reaching 1e-5 takes 512 samples with polar4 (pmj02/Owen), 2048 with polar (Sec. 4.1)",
          "2048 / N at which polar4 (" + q + ") reaches the error of polar (sobol-xor) at N = 2048",
          {RuleKind::factor, 4.0}, kLit, {"sobol-xor", q}, {"polar", "polar4"},
          measures::sample_ratio("polar", "sobol-xor", "polar4", q, 2048));
  }
  // The memo compares polar4 with the strategies introduced before it; concentric4, the other
  // four-copy strategy, comes in the next paragraph (and is judged there).
  b.add("lit.polar4.random", lit,
        "polar4 makes even random's error quite a bit lower than the other strategies (Sec. 4.1)",
        "rmse(polar4, random) / the lowest one-copy strategy's (pad-zero, rejection, polar, "
        "concentric), geometric mean over the fit range",
        {RuleKind::lower, 0.8}, kLit, {"random"}, all_strategies,
        ratio_to_best_other("polar4", "random", {"pad-zero", "rejection", "polar", "concentric"}));
  // The same claim read literally, concentric4 included among the "other strategies": both are
  // shown, since the memo's wording admits either.
  b.add("lit.polar4.random.all", lit,
        "polar4 makes even random's error quite a bit lower than the other strategies (Sec. 4.1)",
        "rmse(polar4, random) / the lowest of all five other strategies' (concentric4 included), "
        "geometric mean over the fit range",
        {RuleKind::lower, 0.8}, kLit, {"random"}, all_strategies,
        ratio_to_best_other("polar4", "random",
                            {"pad-zero", "rejection", "polar", "concentric", "concentric4"}));
  for (const std::string& q : best_nets)
    b.add("lit.concentric4." + q, lit,
          "concentric4 changes pmj02/Owen errors only by a few percent (Sec. 4.1)",
          "rmse(concentric4) / rmse(concentric) (" + q + "), geometric mean over the fit range",
          {RuleKind::about_equal, 1.0}, kLit, {q}, {"concentric", "concentric4"},
          measures::mean_ratio("concentric4", q, "concentric", q));
  for (const char* q : {"random", "best-candidate"})
    b.add(std::string("lit.concentric4.lower.") + q, lit,
          "concentric4 lowers the error of random and best candidates (Sec. 4.1)",
          std::string("rmse(concentric4) / rmse(concentric) (") + q + "), geometric mean",
          {RuleKind::lower, 0.9}, kLit, {q}, {"concentric", "concentric4"},
          measures::mean_ratio("concentric4", q, "concentric", q));
  for (const char* q : {"halton-rotated", "sobol-rotated"})
    b.add(std::string("lit.concentric4.higher.") + q, lit,
          "concentric4 raises the error of rotated Halton and rotated Sobol' (Sec. 4.1)",
          std::string("rmse(concentric4) / rmse(concentric) (") + q + "), geometric mean",
          {RuleKind::higher, 1.1}, kLit, {q}, {"concentric", "concentric4"},
          measures::mean_ratio("concentric4", q, "concentric", q));

  // ---- Sec. 4.2, penumbra ----
  for (const std::string& st : maps)
    for (const char* q : {"random", "best-candidate"})
      b.add("pen." + st + "." + q + ".slope", pen,
            "random and best candidates: O(N^-0.5) (Sec. 4.2)", "slope (" + st + ", " + q + ")",
            slope_half, kPenumbra, {q}, {st}, measures::slope(st, q));
  for (const std::string& st : maps)
    for (const std::string& q : stratified)
      b.add("pen." + st + "." + q + ".slope", pen, "every other sequence: O(N^-0.75) (Sec. 4.2)",
            "slope (" + st + ", " + q + ")", {RuleKind::slope, -0.75}, kPenumbra, {q}, {st},
            measures::slope(st, q));
  b.add("pen.pad-rejection.high", pen, "pad-zero and rejection have very high error (Sec. 4.2)",
        "best pad-zero/rejection rmse / best map rmse, geometric mean over the fit range",
        {RuleKind::higher, 1.5}, kPenumbra, {}, all_strategies,
        [](const CurveTable& r, std::size_t region, Weights w) -> Opt {
          const Opt a = best_vs_best("pad-zero", {"polar", "concentric", "polar4", "concentric4"})(
              r, region, w);
          const Opt c = best_vs_best("rejection", {"polar", "concentric", "polar4", "concentric4"})(
              r, region, w);
          if (!a || !c) return std::nullopt;
          return std::min(*a, *c);
        });
  b.add("pen.pad-zero.sobol-rotated", pen,
        "rotated Sobol' performs poorly with pad-zero (Sec. 4.2)",
        "rmse(pad-zero, sobol-rotated) / median of the other stratified sequences, geometric mean",
        {RuleKind::higher, 1.25}, kPenumbra, {"sobol-rotated"}, {"pad-zero"},
        ratio_to_median("pad-zero", "sobol-rotated", [&] {
          std::vector<std::string> others;
          for (const std::string& q : stratified)
            if (q != "sobol-rotated") others.push_back(q);
          return others;
        }()));
  b.add("pen.art.polar-vs-concentric", pen,
        "ART has higher error with polar than with concentric (Sec. 4.2)",
        "rmse(polar, art) / rmse(concentric, art), geometric mean", {RuleKind::higher, 1.25},
        kPenumbra, {"art"}, {"polar", "concentric"},
        measures::mean_ratio("polar", "art", "concentric", "art"));
  for (const std::string& q : sequences) {
    if (q == "art") continue;  // its own claim above
    b.add("pen.polar-vs-concentric." + q, pen,
          "other sequences: polar or concentric does not matter (Sec. 4.2)",
          "rmse(polar) / rmse(concentric) (" + q + "), geometric mean",
          {RuleKind::about_equal, 1.0}, kPenumbra, {q}, {"polar", "concentric"},
          measures::mean_ratio("polar", q, "concentric", q));
  }
  for (const char* q : {"random", "best-candidate", "art"})
    for (const auto& [x4, x1] :
         {std::pair{"polar4", "polar"}, std::pair{"concentric4", "concentric"}})
      b.add(std::string("pen.") + x4 + ".helps." + q, pen,
            "polar4/concentric4 reduce the error of random, best candidates and ART quite "
            "significantly (Sec. 4.2)",
            std::string("rmse(") + x4 + ") / rmse(" + x1 + ") (" + q + "), geometric mean",
            {RuleKind::lower, 0.8}, kPenumbra, {q}, {x4, x1}, measures::mean_ratio(x4, q, x1, q));
  for (const char* q : {"pmj02", "sobol-rotated", "sobol-xor", "sobol-owen"})
    for (const auto& [x4, x1] :
         {std::pair{"polar4", "polar"}, std::pair{"concentric4", "concentric"}})
      b.add(std::string("pen.") + x4 + ".few-percent." + q, pen,
            "polar4/concentric4 reduce pmj02 and Sobol' errors only by a few percent (Sec. 4.2)",
            std::string("rmse(") + x4 + ") / rmse(" + x1 + ") (" + q + "), geometric mean",
            {RuleKind::about_equal, 1.0}, kPenumbra, {q}, {x4, x1},
            measures::mean_ratio(x4, q, x1, q));
  return std::move(b.claims);
}

std::vector<ClaimOutcome> evaluate_claims(const std::vector<Claim>& claims,
                                          const CurveTable& result,
                                          const SeedBootstrap& bootstrap) {
  std::vector<ClaimOutcome> out;
  const auto& ns = result.ns();
  const double max_n = ns.empty() ? 0.0 : ns.back();
  for (std::size_t i = 0; i < claims.size(); ++i) {
    const Claim& claim = claims[i];
    for (const std::string& region : claim.regions) {
      ClaimOutcome o;
      o.claim = i;
      o.region = region;
      const std::optional<std::size_t> ri = result.find_region(region);
      std::string missing;
      for (const std::string& q : claim.needs_sequences)
        if (!result.has_sequence(q)) missing += (missing.empty() ? "" : ", ") + ("sequence " + q);
      for (const std::string& m : claim.needs_methods)
        if (!result.has_method(m)) missing += (missing.empty() ? "" : ", ") + ("method " + m);
      if (!ri) missing += (missing.empty() ? "" : ", ") + ("region " + region);
      if (!missing.empty()) {
        o.note = "not in this run: " + missing;
        out.push_back(o);
        continue;
      }
      o.measured = claim.measure(result, *ri, {});
      o.verdict = judge(claim.rule, o.measured, max_n);
      // A crossover at or beyond the run's ends (0 or infinity) is a bound, not a value: no
      // standard error, and replicates that land there are left out of it.
      const bool crossover = claim.rule.kind == RuleKind::crossover;
      if (claim.bootstrap && o.measured && std::isfinite(*o.measured) &&
          (!crossover || *o.measured > 0.0))
        o.se = bootstrap.standard_error([&](std::span<const uint32_t> w) -> Opt {
          const Opt v = claim.measure(result, *ri, w);
          if (crossover && v && !(*v > 0.0 && std::isfinite(*v))) return std::nullopt;
          return v;
        });
      char buf[160] = "";
      if (!o.measured) {
        std::snprintf(buf, sizeof buf, "not measurable in this run (N = %.0f .. %.0f)",
                      ns.empty() ? 0.0 : static_cast<double>(ns.front()), max_n);
      } else if (o.verdict != Verdict::reproduced) {
        const double m = *o.measured, c = claim.rule.claimed;
        switch (claim.rule.kind) {
          case RuleKind::slope:
            std::snprintf(buf, sizeof buf, "%+.2f from the claim", m - c);
            break;
          case RuleKind::factor:
            std::snprintf(buf, sizeof buf, "x%.2f the claim", m / c);
            break;
          case RuleKind::at_most:
            std::snprintf(buf, sizeof buf, "%.3g, above %.3g", m, c);
            break;
          case RuleKind::crossover:
            if (std::isinf(m))
              std::snprintf(buf, sizeof buf, "not caught up by N = %.0f", max_n);
            else if (m == 0.0)
              std::snprintf(buf, sizeof buf, "already lower at N = %u", ns.front());
            else
              std::snprintf(buf, sizeof buf, "x%.2f the claimed N", m / c);
            break;
          default:
            std::snprintf(buf, sizeof buf, "ratio %.2f", m);
        }
      }
      o.note = buf;
      out.push_back(o);
    }
  }
  return out;
}

namespace {
std::string format_value(const Claim& c, const ClaimOutcome& o) {
  if (!o.measured) return "-";
  char buf[80];
  const double m = *o.measured;
  if (c.rule.kind == RuleKind::crossover && std::isinf(m)) return "none";
  if (c.rule.kind == RuleKind::crossover && m == 0.0) return "below N_min";
  const char* fmt = c.rule.kind == RuleKind::slope
                        ? "%+.2f"
                        : (c.rule.kind == RuleKind::crossover ? "%.0f" : "%.2f");
  std::snprintf(buf, sizeof buf, fmt, m);
  std::string s = buf;
  if (o.se) {
    std::snprintf(buf, sizeof buf, c.rule.kind == RuleKind::crossover ? " ± %.0f" : " ± %.2f",
                  *o.se);
    s += buf;
  }
  return s;
}

std::string escape(const std::string& s) {
  std::string out;
  for (char ch : s) {
    if (ch == '|')
      out += "\\|";
    else
      out += ch;
  }
  return out;
}
}  // namespace

std::vector<ClaimSection> memo_sections() {
  return {{"fully lit", "Fully lit (memo Sec. 4.1)"}, {"penumbra", "Penumbra (memo Sec. 4.2)"}};
}

std::string claims_markdown(const std::vector<Claim>& claims,
                            const std::vector<ClaimOutcome>& outcomes,
                            const std::vector<ClaimSection>& sections,
                            const std::string& ratios_note) {
  std::vector<bool> used(static_cast<int>(RuleKind::at_most) + 1, false);
  for (const Claim& c : claims)
    used[static_cast<int>(c.rule.kind)] = true;
  auto uses = [&](RuleKind k) { return used[static_cast<int>(k)]; };
  std::string md;
  md +=
      "Verdicts are computed by these rules from the measured value (± is the bootstrap "
      "standard error over the randomizations, shown but not used by the rule):\n\n";
  if (uses(RuleKind::slope))
    md +=
        "- slope: within 0.10 of the claim **reproduced**, within 0.20 **roughly**, else "
        "**differs**;\n";
  if (uses(RuleKind::factor))
    md += "- factor: within x1.25 of the claim reproduced, within x1.5 roughly;\n";
  if (uses(RuleKind::about_equal))
    md += "- \"a few percent\" (ratio 1): within 0.10 reproduced, within 0.25 roughly;\n";
  if (uses(RuleKind::lower) || uses(RuleKind::higher))
    md +=
        "- \"lower\" with threshold c: ratio <= c reproduced, <= (1 + c) / 2 roughly; \"higher\" "
        "mirrors it (>= c, >= (1 + c) / 2);\n";
  if (uses(RuleKind::crossover))
    md +=
        "- crossover sample count: within x2 reproduced, x4 roughly; none within the run "
        "differs once the run reaches twice the claimed N;\n";
  if (uses(RuleKind::at_most))
    md += "- \"up to c\": at most c reproduced, at most 1.5 c roughly;\n";
  md += "- not measured: the run lacks the sequence, method or sample count the claim needs.\n\n";
  md += ratios_note + "\n";

  std::map<std::string, int> tally;
  for (const ClaimSection& sec : sections) {
    const std::string& section = sec.key;
    std::vector<std::string> regions;
    for (const ClaimOutcome& o : outcomes)
      if (claims[o.claim].section == section &&
          std::find(regions.begin(), regions.end(), o.region) == regions.end())
        regions.push_back(o.region);
    if (regions.empty()) continue;
    md += "\n### " + sec.title + "\n\n";
    md += "| claim | measured as | rule |";
    for (const std::string& r : regions)
      md += " " + r + " | verdict |";
    md += " note |\n| --- | --- | --- |";
    for (std::size_t i = 0; i < regions.size(); ++i)
      md += " ---: | --- |";
    md += " --- |\n";
    for (std::size_t ci = 0; ci < claims.size(); ++ci) {
      const Claim& c = claims[ci];
      if (c.section != section) continue;
      md += "| " + escape(c.text) + " | " + escape(c.measured_as) + " | " +
            escape(rule_text(c.rule)) + " |";
      std::string notes;
      std::vector<Verdict> verdicts;
      for (const std::string& r : regions) {
        const ClaimOutcome* o = nullptr;
        for (const ClaimOutcome& x : outcomes)
          if (x.claim == ci && x.region == r) o = &x;
        if (!o) {
          md += " | |";
          continue;
        }
        // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on the + chain.
        md += ' ';
        md += format_value(c, *o);
        md += " | ";
        md += verdict_name(o->verdict);
        md += " |";
        ++tally[section + "|" + verdict_name(o->verdict)];
        verdicts.push_back(o->verdict);
        if (!o->note.empty())
          notes += (notes.empty() ? "" : "; ") + (regions.size() > 1 ? r + ": " : "") + o->note;
      }
      if (verdicts.size() > 1 && std::any_of(verdicts.begin(), verdicts.end(),
                                             [&](Verdict v) { return v != verdicts[0]; }))
        notes = "depends on the region; " + notes;
      md += " " + escape(notes) + " |\n";
    }
  }
  md += "\nTally (claim x region):";
  for (const ClaimSection& sec : sections) {
    const std::string& section = sec.key;
    md += " " + section + ":";
    for (Verdict v :
         {Verdict::reproduced, Verdict::roughly, Verdict::differs, Verdict::not_measured})
      md += " " + std::to_string(tally[section + "|" + verdict_name(v)]) + " " + verdict_name(v) +
            ",";
    md.back() = ';';
  }
  md.back() = '.';
  md += "\n";
  return md;
}

}  // namespace disklab::study
