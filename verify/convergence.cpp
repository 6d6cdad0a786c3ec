// `disklab convergence`: the memo's convergence study (Christensen 2018, Secs. 4.1-4.2,
// Figs. 5-6) on a scene anyone can recompute (verify/study/convergence.h), with the memo's claims
// measured and judged (verify/study/claims.h).
//
//   disklab convergence [--out DIR] [--quick] [--seeds K] [--seed S] [--max-n N] [--min-n N]
//                       [--fit-min N] [--strategies a,b] [--sequences a,b] [--regions a,b]
//                       [--threads T] [--no-plots]
//
// Writes convergence.csv / .json (rows, fits, references, claims), convergence_fits.csv,
// convergence_references.csv, convergence.md (headline, slope tables, claims) and one PNG per
// region laid out like the memo's figures. Everything is validated before anything is computed
// or written; every file is written atomically.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "command.h"
#include "common/args.h"
#include "common/output.h"
#include "common/study_output.h"
#include "disklab/sequence/sequence.h"
#include "study/claims.h"
#include "study/convergence.h"

namespace disklab::cli {
namespace {

namespace fs = std::filesystem;
using study::ConvergenceConfig;
using study::ConvergenceResult;

constexpr int64_t kMaxSeeds = 10000;
constexpr int64_t kMaxN = 1 << 16;  // beyond it the tabulated sequences' tables grow large
constexpr int kQuickSeeds = 20;
constexpr int64_t kQuickMaxN = 1024;

struct ConvergenceState {
  std::string out = "convergence";
  bool quick = false;
  int64_t seeds = 100;
  std::string seed_text = "0";
  int64_t max_n = 4096, min_n = 16, fit_min = 64;
  std::string strategies, sequences, regions;
  int64_t threads = 0;
  bool no_plots = false;
  // Set from the parse: which options the user gave (so --quick does not override them).
  bool seeds_given = false, max_n_given = false;
};

bool power_of_two(int64_t n) {
  return n > 0 && (n & (n - 1)) == 0;
}

// The configuration the options describe; UsageError for anything invalid.
ConvergenceConfig make_config(const ConvergenceState& s) {
  ConvergenceConfig c;
  int64_t seeds = s.seeds, max_n = s.max_n;
  if (s.quick) {
    if (!s.seeds_given) seeds = kQuickSeeds;
    if (!s.max_n_given) max_n = kQuickMaxN;
  }
  if (seeds < 1 || seeds > kMaxSeeds)
    throw UsageError("--seeds: " + std::to_string(seeds) + " must be in [1, " +
                     std::to_string(kMaxSeeds) + "]");
  for (const auto& [value, name] : {std::pair{s.min_n, "--min-n"}, std::pair{max_n, "--max-n"},
                                    std::pair{s.fit_min, "--fit-min"}}) {
    if (!power_of_two(value) || value < 4 || value > kMaxN)
      throw UsageError(std::string(name) + ": " + std::to_string(value) +
                       " must be a power of two in [4, " + std::to_string(kMaxN) + "]");
  }
  if (s.min_n > max_n)
    throw UsageError("--min-n: " + std::to_string(s.min_n) + " exceeds --max-n " +
                     std::to_string(max_n));
  if (s.fit_min >= max_n || s.fit_min < s.min_n)
    throw UsageError("--fit-min: " + std::to_string(s.fit_min) +
                     " must lie in [--min-n, --max-n) so the fit has two or more N (max-n " +
                     std::to_string(max_n) + ")");
  if (s.threads < 0 || s.threads > 256)
    throw UsageError("--threads: " + std::to_string(s.threads) + " must be in [0, 256]");
  c.seeds = static_cast<uint32_t>(seeds);
  c.first_seed = parse_u64(s.seed_text, "--seed");
  for (int64_t n = s.min_n; n <= max_n; n *= 2)
    c.ns.push_back(static_cast<uint32_t>(n));
  c.fit_min = static_cast<uint32_t>(s.fit_min);
  c.threads = static_cast<int>(s.threads);
  for (const std::string& name :
       parse_name_list(s.strategies, disk::strategy_names(), "--strategies"))
    c.strategies.push_back(*disk::parse_strategy(name));
  c.sequences = parse_name_list(s.sequences, sequence::sequence_names(), "--sequences");
  std::vector<std::string> region_names;
  for (const auto& r : study::memo_regions())
    region_names.push_back(r.grid.name);
  const std::vector<std::string> chosen = parse_name_list(s.regions, region_names, "--regions");
  c.regions.clear();
  for (const std::string& name : chosen)
    for (const auto& r : study::memo_regions())
      if (r.grid.name == name) c.regions.push_back(r);
  try {
    study::finalize(c);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return c;
}

struct Outputs {
  std::string csv, fits_csv, refs_csv, json, markdown, claims_markdown, answer_markdown;
};

std::string describe_scene(const ConvergenceConfig& c) {
  const auto& l = c.scene.light;
  std::string s = "Disk light R = " + fmt17(l.radius) + " at (" + fmt17(l.center.x()) + ", " +
                  fmt17(l.center.y()) + ", " + fmt17(l.center.z()) + "), normal (" +
                  fmt17(l.normal.x()) + ", " + fmt17(l.normal.y()) + ", " + fmt17(l.normal.z()) +
                  "), one-sided, L = " + fmt17(l.radiance) +
                  "; unit-disk samples (x, y) land at world (x, y, 2). Receiver z = 0, normal +z.";
  for (const auto& o : c.scene.occluders)
    s += " Opaque sphere r = " + fmt17(o.radius) + " at (" + fmt17(o.center.x()) + ", " +
         fmt17(o.center.y()) + ", " + fmt17(o.center.z()) + ").";
  return s;
}

std::string command_line(const ConvergenceConfig& c) {
  std::string s = "disklab convergence --seeds " + std::to_string(c.seeds) + " --seed " +
                  std::to_string(c.first_seed) + " --min-n " + std::to_string(c.ns.front()) +
                  " --max-n " + std::to_string(c.ns.back()) + " --fit-min " +
                  std::to_string(c.fit_min);
  if (c.regions.size() != study::memo_regions().size()) {
    s += " --regions ";
    for (std::size_t i = 0; i < c.regions.size(); ++i)
      s += (i ? "," : "") + c.regions[i].grid.name;
  }
  if (c.strategies.size() != std::size(disk::kAllStrategies)) {
    s += " --strategies ";
    for (std::size_t i = 0; i < c.strategies.size(); ++i)
      s += (i ? "," : "") + std::string(disk::strategy_name(c.strategies[i]));
  }
  if (c.sequences != sequence::sequence_names()) {
    s += " --sequences ";
    for (std::size_t i = 0; i < c.sequences.size(); ++i)
      s += (i ? "," : "") + c.sequences[i];
  }
  return s;
}

// The headline: for each region and strategy, the sequence with the lowest RMS at the largest N,
// its slope and that RMS.
std::string headline_markdown(const ConvergenceResult& r,
                              const std::vector<study::CurveFit>& fits) {
  const auto& c = r.config;
  const std::size_t last = c.ns.size() - 1;
  std::string md = "| strategy |";
  for (const auto& region : c.regions)
    md += " " + region.grid.name + " |";
  md += "\n| --- |";
  for (std::size_t i = 0; i < c.regions.size(); ++i)
    md += " --- |";
  md += "\n";
  for (std::size_t st = 0; st < c.strategies.size(); ++st) {
    md += "| " + std::string(disk::strategy_name(c.strategies[st])) + " |";
    for (std::size_t reg = 0; reg < c.regions.size(); ++reg) {
      std::size_t best = r.curve_index(reg, st, 0);
      for (std::size_t q = 1; q < c.sequences.size(); ++q) {
        const std::size_t cur = r.curve_index(reg, st, q);
        if (r.rmse(cur, last) < r.rmse(best, last)) best = cur;
      }
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.2e", r.rmse(best, last));
      // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on + chains here.
      md += ' ';
      md += r.sequence_of(best);
      md += ": slope ";
      md += slope_cell(fits[best]);
      md += ", RMS ";
      md += buf;
      md += " |";
    }
    md += "\n";
  }
  return md;
}

// The report's first screen: per region, the strategy x sequence with the lowest RMS at the
// largest N, with its slope, and how far the best one-copy strategy (no four-copy reuse) is
// behind it.
std::string answer_markdown(const ConvergenceResult& r, const std::vector<study::CurveFit>& fits) {
  const auto& c = r.config;
  const std::size_t last = c.ns.size() - 1;
  std::string md =
      "| region | best strategy x sequence | RMS at N = " + std::to_string(c.ns.back()) +
      " | slope | best one-copy strategy (RMS ratio to the best) |\n"
      "| --- | --- | ---: | ---: | --- |\n";
  for (std::size_t reg = 0; reg < c.regions.size(); ++reg) {
    std::optional<std::size_t> best, best_one_copy;
    for (std::size_t st = 0; st < c.strategies.size(); ++st) {
      const bool four_copies = c.strategies[st] == disk::Strategy::polar4 ||
                               c.strategies[st] == disk::Strategy::concentric4;
      for (std::size_t q = 0; q < c.sequences.size(); ++q) {
        const std::size_t cur = r.curve_index(reg, st, q);
        if (!best || r.rmse(cur, last) < r.rmse(*best, last)) best = cur;
        if (!four_copies && (!best_one_copy || r.rmse(cur, last) < r.rmse(*best_one_copy, last)))
          best_one_copy = cur;
      }
    }
    if (!best) continue;
    char rms[32], ratio[32];
    std::snprintf(rms, sizeof rms, "%.2e", r.rmse(*best, last));
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on + chains here.
    const auto append_name = [&](std::size_t curve) {
      md += r.method_of(curve);
      md += " x ";
      md += r.sequence_of(curve);
    };
    md += "| " + c.regions[reg].grid.name + " | ";
    append_name(*best);
    md += " | ";
    md += rms;
    md += " | ";
    md += slope_cell(fits[*best]);
    md += " | ";
    if (best_one_copy) {
      std::snprintf(ratio, sizeof ratio, "%.2fx",
                    r.rmse(*best_one_copy, last) / r.rmse(*best, last));
      append_name(*best_one_copy);
      md += " (";
      md += ratio;
      md += ")";
    } else {
      md += "-";
    }
    md += " |\n";
  }
  return md;
}

std::string slope_tables(const ConvergenceResult& r, const std::vector<study::CurveFit>& fits) {
  const auto& c = r.config;
  std::string md;
  for (std::size_t reg = 0; reg < c.regions.size(); ++reg) {
    md += "\n#### " + c.regions[reg].grid.name + "\n\n| strategy |";
    for (const auto& q : c.sequences)
      md += " " + q + " |";
    md += "\n| --- |";
    for (std::size_t i = 0; i < c.sequences.size(); ++i)
      md += " ---: |";
    md += "\n";
    for (std::size_t st = 0; st < c.strategies.size(); ++st) {
      md += "| " + std::string(disk::strategy_name(c.strategies[st])) + " |";
      for (std::size_t q = 0; q < c.sequences.size(); ++q) {
        md += ' ';
        md += slope_cell(fits[r.curve_index(reg, st, q)]);
        md += " |";
      }
      md += "\n";
    }
  }
  return md;
}

Outputs make_outputs(const ConvergenceResult& r) {
  const auto& c = r.config;
  const study::SeedBootstrap bootstrap = study::make_bootstrap(c);
  const std::vector<study::CurveFit> fits = study::fit_all(r, bootstrap, c.threads);
  const std::vector<study::Claim> claims = study::memo_claims(c.sequences);
  const std::vector<study::ClaimOutcome> outcomes = study::evaluate_claims(claims, r, bootstrap);
  Outputs o;
  nlohmann::json j;
  nlohmann::json meta;
  meta["study"] = "Christensen 2018 (Pixar memo 18-02), Secs. 4.1-4.2";
  meta["command"] = command_line(c);
  meta["scene"] = describe_scene(c);
  meta["seeds"] = c.seeds;
  meta["first_seed"] = c.first_seed;
  meta["ns"] = c.ns;
  meta["fit_n_min"] = c.fit_min;
  meta["fit_n_max"] = c.ns.back();
  meta["bootstrap_replicates"] = c.bootstrap_replicates;
  meta["points_per_region"] = r.references.empty() ? 0 : r.references[0].points.size();
  for (const auto& region : c.regions)
    meta["regions"].push_back({{"name", region.grid.name},
                               {"x0", region.grid.x0},
                               {"x1", region.grid.x1},
                               {"y0", region.grid.y0},
                               {"y1", region.grid.y1},
                               {"nx", region.grid.nx},
                               {"ny", region.grid.ny},
                               {"reference", region.fully_lit ? "closed-form" : "quadrature"}});
  for (auto st : c.strategies)
    meta["strategies"].push_back(std::string(disk::strategy_name(st)));
  meta["sequences"] = c.sequences;
  j["meta"] = meta;

  const TableOutput rows = curve_rows(r, "strategy"), fit_table = fit_rows(r, fits, "strategy");
  o.csv = rows.csv;
  j["rows"] = rows.json;
  o.fits_csv = fit_table.csv;
  j["fits"] = fit_table.json;
  const TableOutput refs = reference_rows(r.references);
  o.refs_csv = refs.csv;
  j["references"] = refs.json;
  j["claims"] = claims_json(claims, outcomes);
  o.json = j.dump(1) + "\n";

  o.claims_markdown = study::claims_markdown(
      claims, outcomes, study::memo_sections(),
      "Ratios are of RMS errors; \"geometric mean\" is over the fit range N = " +
          std::to_string(c.fit_min) + " .. " + std::to_string(c.ns.back()) + ".");
  o.answer_markdown = answer_markdown(r, fits);
  std::string md = "# disklab convergence\n\nGenerated by `" + command_line(c) +
                   "`: the convergence study of Christensen's memo (Secs. 4.1-4.2, Figs. 5-6) "
                   "on a scene anyone can recompute.\n\n";
  md += "- Scene: " + describe_scene(c) + "\n";
  md +=
      "- Regions: 4 x 4 shading points each (`convergence_references.csv`); references: "
      "closed form (fully lit) or quadrature (penumbra), with error estimates.\n";
  double worst = 0.0;
  for (const auto& refs : r.references)
    for (const auto& p : refs.points)
      worst = std::max(worst, p.reference.error_estimate / std::fabs(p.reference.value));
  char buf[160];
  std::snprintf(buf, sizeof buf, "%.1e", worst);
  md += "- Largest reference error estimate, relative: " + std::string(buf) + ".\n";
  md += "- RMS over the points and " + std::to_string(c.seeds) + " randomizations (seeds " +
        std::to_string(c.first_seed) + ".." + std::to_string(c.first_seed + c.seeds - 1) +
        ", one per sequence instance, shared by every point and strategy); slopes fit log RMS "
        "vs log N over N = " +
        std::to_string(c.fit_min) + ".." + std::to_string(c.ns.back()) +
        ", ± the bootstrap standard error over the seeds (" +
        std::to_string(c.bootstrap_replicates) + " replicates).\n\n";
  md += "## Headline: the best sequence per strategy (lowest RMS at N = " +
        std::to_string(c.ns.back()) + ")\n\n" + headline_markdown(r, fits);
  md += "\n## Slopes (log RMS vs log N)\n" + slope_tables(r, fits);
  md += "\n## The memo's claims\n\n" + o.claims_markdown;
  o.markdown = md;
  return o;
}

// Writes every output into `dir` (created if missing). Plots are optional: a machine without
// matplotlib still gets the data and a warning.
void write_outputs(const fs::path& dir, const ConvergenceResult& r, const Outputs& o, bool plots) {
  create_out_dir(dir);
  write_file_atomic(dir / "convergence.csv", o.csv);
  write_file_atomic(dir / "convergence_fits.csv", o.fits_csv);
  write_file_atomic(dir / "convergence_references.csv", o.refs_csv);
  write_file_atomic(dir / "convergence.json", o.json);
  std::string md = o.markdown;
  if (plots) {
    md += "\n## Figures\n\n";
    for (const auto& region : r.config.regions) {
      const std::string png = "convergence_" + region.grid.name + ".png";
      md += plot_markdown(
          "convergence",
          {"--csv", (dir / "convergence.csv").string(), "--fits",
           (dir / "convergence_fits.csv").string(), "--region", region.grid.name, "--title",
           "RMS error vs N, " + region.grid.name + " (" + std::to_string(r.config.seeds) +
               " seeds)"},
          dir, png, region.grid.name);
    }
  }
  write_file_atomic(dir / "convergence.md", md);
}

ConvergenceResult run_study(ConvergenceConfig config) {
  const uint64_t total = static_cast<uint64_t>(config.sequences.size()) * config.seeds;
  return run_with_progress("convergence", total, std::move(config), [](ConvergenceConfig c) {
    return study::run_convergence(std::move(c));
  });
}

int run_convergence_command(const ConvergenceState& s) {
  const fs::path dir = check_out_dir(s.out);
  const ConvergenceConfig config = make_config(s);
  const auto start = std::chrono::steady_clock::now();
  const ConvergenceResult r = run_study(config);
  write_outputs(dir, r, make_outputs(r), !s.no_plots);
  print_finished("convergence",
                 std::to_string(r.curves()) + " curves x " + std::to_string(r.config.ns.size()) +
                     " N x " + std::to_string(r.config.seeds) + " seeds",
                 start, dir / "convergence.md");
  return 0;
}

int report_convergence(const ReportOptions& options) {
  ConvergenceState s;
  s.quick = options.quick;
  const ConvergenceResult r = run_study(make_config(s));
  const Outputs o = make_outputs(r);
  write_outputs(options.dir, r, o, true);
  if (options.answers)
    *options.answers +=
        "### Which strategy and sequence (Christensen's memo; full tables in "
        "[convergence.md](convergence.md))\n\n" +
        o.answer_markdown + "\n";
  if (options.claims)
    *options.claims += "### Christensen's memo (`disklab convergence" +
                       std::string(options.quick ? " --quick" : "") + "`, " +
                       std::to_string(r.config.seeds) +
                       " seeds, N = " + std::to_string(r.config.ns.front()) + ".." +
                       std::to_string(r.config.ns.back()) +
                       "; details in [convergence.md](convergence.md))\n\n" + o.claims_markdown;
  return 0;
}

std::function<int()> setup_convergence(Options& sub) {
  auto state = std::make_shared<ConvergenceState>();
  std::string strategies, sequences;
  for (const auto& n : disk::strategy_names())
    strategies += " " + n;
  for (const auto& n : sequence::sequence_names())
    sequences += " " + n;
  sub.add_option("--out", state->out, "Output folder (created if missing)")->capture_default_str();
  sub.add_flag("--quick", state->quick,
               "Smaller run: " + std::to_string(kQuickSeeds) + " seeds, N up to " +
                   std::to_string(kQuickMaxN) + " (explicit --seeds/--max-n win)");
  auto* seeds = sub.add_option("--seeds", state->seeds, "Randomizations per curve (1 .. 10000)")
                    ->capture_default_str();
  sub.add_option("--seed", state->seed_text,
                 "First randomization: seeds S .. S+K-1 (unsigned 64-bit)")
      ->capture_default_str();
  auto* max_n = sub.add_option("--max-n", state->max_n, "Largest N (power of two, <= 65536)")
                    ->capture_default_str();
  sub.add_option("--min-n", state->min_n, "Smallest N (power of two >= 4)")->capture_default_str();
  sub.add_option("--fit-min", state->fit_min, "Slopes fit N in [fit-min, max-n] (power of two)")
      ->capture_default_str();
  sub.add_option("--strategies", state->strategies,
                 "Comma-separated subset (default all):" + strategies);
  sub.add_option("--sequences", state->sequences,
                 "Comma-separated subset (default all):" + sequences);
  sub.add_option("--regions", state->regions,
                 "Comma-separated subset (default all): lit-axis lit-off penumbra");
  sub.add_option("--threads", state->threads,
                 "Worker threads (0: all cores); results do not depend on it")
      ->capture_default_str();
  sub.add_flag("--no-plots", state->no_plots, "Skip the PNGs (no matplotlib needed)");
  sub.footer(
      "The memo's study on an exactly recomputable scene: a disk light R = 1 at height 2 facing\n"
      "the ground, an opaque sphere (r 0.5 at (1.5, 0, 1)) casting a penumbra, and three 4 x 4\n"
      "grids of ground points: lit-axis (x, y in [-0.6, -0.3]), lit-off ([-1.6, -1.3]) and\n"
      "penumbra (x in [1.9, 2.2], y in [0.5, 0.8]). Irradiance is estimated in the area measure\n"
      "with every disk strategy over every sequence (pad-zero with weight 4/pi, rejection with N\n"
      "accepted samples, the four-copy strategies with N/4 square points), against closed-form\n"
      "(lit) and quadrature (penumbra) references. Each randomization (seed) builds one\n"
      "sequence instance shared by every point, strategy and N (progressive prefixes).\n"
      "Files in --out:\n"
      "  convergence.csv        region,strategy,sequence,n,rmse,rel_rmse: RMS over points and\n"
      "                         seeds of (estimate - reference), and of the same / reference\n"
      "  convergence_fits.csv   region,strategy,sequence,slope,slope_se,fit_n_min,fit_n_max:\n"
      "                         least-squares slope of log rmse vs log N, bootstrap s.e. over "
      "seeds\n"
      "  convergence_references.csv  region,x,y,E,error_estimate,method per shading point\n"
      "  convergence.json       {meta, rows, fits, references, claims} with the same fields\n"
      "  convergence.md         headline, slope tables, the memo's claims with verdicts\n"
      "  convergence_<region>.png  one log-log panel per strategy, one curve per sequence\n"
      "The same options give the same bytes, with any --threads. Full run: about 10 s on 2 cores.\n"
      "Examples:\n"
      "  disklab convergence --out conv\n"
      "  disklab convergence --quick --out /tmp/conv\n"
      "  disklab convergence --regions penumbra --strategies polar,polar4 --sequences "
      "pmj02,random\n");
  return [state, seeds, max_n] {
    ConvergenceState s = *state;
    s.seeds_given = seeds->count() > 0;
    s.max_n_given = max_n->count() > 0;
    return run_convergence_command(s);
  };
}

const Registrar kConvergence{Command{"convergence",
                                     "The memo's convergence study: RMS vs N, slopes, claims",
                                     setup_convergence, report_convergence}};

}  // namespace
}  // namespace disklab::cli
