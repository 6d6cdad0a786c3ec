// `disklab variance`: Guillén et al.'s variance and cost study (Sec. 5, Figs. 6-7) on a scene
// anyone can recompute (verify/study/variance.h): image MSE at 16 spp, RMS vs N in three
// regions, the maps' cost per sample in the same run, error images like Fig. 7, the paper's
// claims judged (verify/study/variance_claims.cpp) and the memo's radial4 question answered.
//
//   disklab variance [--out DIR] [--quick] [--seeds K] [--images M] [--seed S] [--max-n N]
//                    [--min-n N] [--fit-min N] [--maps a,b] [--sequences a,b] [--regions a,b]
//                    [--timing-reps R] [--threads T] [--no-plots]
//
// Everything is validated before anything is computed or written; every file is atomic.
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "command.h"
#include "common/args.h"
#include "common/output.h"
#include "common/study_output.h"
#include "disklab/sequence/sequence.h"
#include "study/variance.h"

namespace disklab::cli {
namespace {

namespace fs = std::filesystem;
using study::VarianceConfig;
using study::VarianceResult;

constexpr int64_t kMaxSeeds = 10000;
constexpr int64_t kMaxN = 1 << 16;
constexpr int kQuickSeeds = 20, kQuickImages = 4, kQuickTimingReps = 3;
constexpr int64_t kQuickMaxN = 1024;

struct VarianceState {
  std::string out = "variance";
  bool quick = false;
  int64_t seeds = 100, images = 16;
  std::string seed_text = "0";
  int64_t max_n = 4096, min_n = 16, fit_min = 64;
  std::string maps, sequences, regions;
  int64_t timing_reps = 5, threads = 0;
  bool no_plots = false;
  bool seeds_given = false, images_given = false, max_n_given = false, reps_given = false;
};

const std::vector<std::string> kDefaultSequences = {"random", "sobol-owen", "pmj02"};

VarianceConfig make_config(const VarianceState& s) {
  VarianceConfig c;
  int64_t seeds = s.seeds, images = s.images, max_n = s.max_n, reps = s.timing_reps;
  if (s.quick) {
    if (!s.seeds_given) seeds = kQuickSeeds;
    if (!s.images_given) images = kQuickImages;
    if (!s.max_n_given) max_n = kQuickMaxN;
    if (!s.reps_given) reps = kQuickTimingReps;
  }
  auto in_range = [](int64_t v, int64_t lo, int64_t hi, const char* name) {
    if (v < lo || v > hi)
      throw UsageError(std::string(name) + ": " + std::to_string(v) + " must be in [" +
                       std::to_string(lo) + ", " + std::to_string(hi) + "]");
  };
  in_range(seeds, 1, kMaxSeeds, "--seeds");
  in_range(images, 1, 1000, "--images");
  in_range(reps, 1, 100, "--timing-reps");
  in_range(s.threads, 0, 256, "--threads");
  for (const auto& [value, name] : {std::pair{s.min_n, "--min-n"}, std::pair{max_n, "--max-n"},
                                    std::pair{s.fit_min, "--fit-min"}}) {
    if (value < 16 || value > kMaxN || !std::has_single_bit(static_cast<uint64_t>(value)))
      throw UsageError(std::string(name) + ": " + std::to_string(value) +
                       " must be a power of two in [16, " + std::to_string(kMaxN) + "]");
  }
  if (s.min_n > max_n)
    throw UsageError("--min-n: " + std::to_string(s.min_n) + " exceeds --max-n " +
                     std::to_string(max_n));
  if (s.fit_min >= max_n || s.fit_min < s.min_n)
    throw UsageError("--fit-min: " + std::to_string(s.fit_min) +
                     " must lie in [--min-n, --max-n) so the fit has two or more N (max-n " +
                     std::to_string(max_n) + ")");
  c.seeds = static_cast<uint32_t>(seeds);
  c.image_randomizations = static_cast<uint32_t>(images);
  c.timing_repetitions = static_cast<int>(reps);
  c.threads = static_cast<int>(s.threads);
  c.first_seed = parse_u64(s.seed_text, "--seed");
  for (int64_t n = s.min_n; n <= max_n; n *= 2)
    c.ns.push_back(static_cast<uint32_t>(n));
  c.fit_min = static_cast<uint32_t>(s.fit_min);
  for (const std::string& name : parse_name_list(s.maps, ellipse::map_names(), "--maps"))
    c.maps.push_back(*ellipse::parse_map(name));
  c.sequences = s.sequences.empty()
                    ? kDefaultSequences
                    : parse_name_list(s.sequences, sequence::sequence_names(), "--sequences");
  std::vector<std::string> region_names;
  for (const auto& r : study::variance_regions())
    region_names.push_back(r.grid.name);
  c.regions.clear();
  for (const std::string& name : parse_name_list(s.regions, region_names, "--regions"))
    for (const auto& r : study::variance_regions())
      if (r.grid.name == name) c.regions.push_back(r);
  try {
    study::finalize(c);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return c;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v)
    s += (s.empty() ? "" : ",") + x;
  return s;
}

std::string command_line(const VarianceResult& r) {
  const VarianceConfig& c = r.config;
  std::string s = "disklab variance --seeds " + std::to_string(c.seeds) + " --images " +
                  std::to_string(c.image_randomizations) + " --seed " +
                  std::to_string(c.first_seed) + " --min-n " + std::to_string(c.ns.front()) +
                  " --max-n " + std::to_string(c.ns.back()) + " --fit-min " +
                  std::to_string(c.fit_min) + " --timing-reps " +
                  std::to_string(c.timing_repetitions);
  if (r.map_names != ellipse::map_names()) s += " --maps " + join(r.map_names);
  if (c.sequences != kDefaultSequences) s += " --sequences " + join(c.sequences);
  if (c.regions.size() != study::variance_regions().size()) {
    std::vector<std::string> names;
    for (const auto& reg : c.regions)
      names.push_back(reg.grid.name);
    s += " --regions " + join(names);
  }
  return s;
}

const char* kScene =
    "Disk light R = 0.5 at (0, 0, 0.6), normal (1, 0, 0), two-sided, L = 1 (lowest point at "
    "z = 0.1); ground z = 0, normal +z; opaque sphere r = 0.25 at (-0.8, 0.5, 0.3).";

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The cost table's row of the baseline every ratio divides by.
constexpr const char* kBaselineName = "baseline";

struct ImageRow {
  std::string region, map, sequence;
  double mse = 0.0, rel_mse = 0.0, mse_se = 0.0, ns_per_sample = 0.0, ratio = 0.0, efficiency = 0.0,
         efficiency_vs_area = 0.0;
};

std::vector<ImageRow> image_rows(const VarianceResult& r) {
  const auto& t = r.image;
  const study::SeedBootstrap boot = study::make_image_bootstrap(r.config);
  std::vector<ImageRow> rows;
  const auto area = std::find(r.map_names.begin(), r.map_names.end(), "area");
  for (std::size_t reg = 0; reg < t.axes.regions.size(); ++reg)
    for (std::size_t m = 0; m < r.map_names.size(); ++m)
      for (std::size_t q = 0; q < r.config.sequences.size(); ++q) {
        const std::size_t curve = t.curve_index(reg, m, q);
        ImageRow row;
        row.region = t.axes.regions[reg];
        row.map = r.map_names[m];
        row.sequence = r.config.sequences[q];
        row.mse = std::pow(t.rmse(curve, 0), 2);
        row.rel_mse = std::pow(t.rel_rmse(curve, 0), 2);
        row.mse_se = boot.standard_error([&](std::span<const uint32_t> w) {
                           return std::optional<double>(std::pow(t.rmse(curve, 0, w), 2));
                         })
                         .value_or(0.0);
        row.ns_per_sample = r.cost[m].ns_per_sample;
        row.ratio = r.cost[m].ratio_to_baseline;
        // 1 / (MSE x time per pixel), time in seconds: who wins at equal time.
        row.efficiency = 1.0 / (row.mse * row.ns_per_sample * r.config.spp * 1e-9);
        rows.push_back(row);
      }
  if (area != r.map_names.end())
    for (ImageRow& row : rows)
      for (const ImageRow& a : rows)
        if (a.map == "area" && a.sequence == row.sequence && a.region == row.region)
          row.efficiency_vs_area = row.efficiency / a.efficiency;
  return rows;
}

struct Outputs {
  std::string csv, fits_csv, refs_csv, images_csv, cost_csv, newton_csv, json, markdown,
      claims_markdown, answer_markdown;
};

// Relative RMS below this is the sum's rounding, not sampling error: a zero-variance estimator
// (projected on unoccluded points). Ranked apart, since its efficiency is set by rounding.
constexpr double kRoundingRelRms = 1e-12;

// The report's first screen: per image and region, the map x sequence with the highest
// efficiency at equal time (1 / (MSE x time per sample), the set-up amortized over spp samples),
// as a multiple of area sampling's with the same sequence.
std::string answer_markdown(const VarianceResult& r) {
  const uint32_t spp = r.config.spp;
  std::vector<std::pair<const study::CurveTable*, std::size_t>> columns;
  for (std::size_t reg = 0; reg < r.image.axes.regions.size(); ++reg)
    columns.emplace_back(&r.image, reg);
  for (std::size_t reg = 0; reg < r.curves.axes.regions.size(); ++reg)
    columns.emplace_back(&r.curves, reg);
  const auto area = std::find(r.map_names.begin(), r.map_names.end(), "area");
  std::string md = "| region | best map x sequence at equal time (" + std::to_string(spp) +
                   " spp) | MSE | efficiency vs area | zero variance (rounding only) |\n"
                   "| --- | --- | ---: | ---: | --- |\n";
  for (const auto& [table, reg] : columns) {
    const auto k = table->find_n(spp);
    if (!k) continue;
    double best_eff = 0.0, best_mse = 0.0, best_vs_area = 0.0;
    std::string best_name, exact;
    for (std::size_t m = 0; m < r.map_names.size(); ++m)
      for (std::size_t q = 0; q < r.config.sequences.size(); ++q) {
        const std::size_t curve = table->curve_index(reg, m, q);
        const double mse = std::pow(table->rmse(curve, *k), 2);
        if (table->rel_rmse(curve, *k) < kRoundingRelRms) {
          if (exact.find(r.map_names[m]) == std::string::npos)
            exact += (exact.empty() ? "" : ", ") + r.map_names[m];
          continue;
        }
        const double eff = 1.0 / (mse * r.cost[m].ns_per_sample);
        if (eff <= best_eff) continue;
        best_eff = eff;
        best_mse = mse;
        best_name = r.map_names[m] + " x " + r.config.sequences[q];
        best_vs_area = 0.0;
        if (area != r.map_names.end()) {
          const std::size_t a = static_cast<std::size_t>(area - r.map_names.begin());
          const double area_mse = std::pow(table->rmse(table->curve_index(reg, a, q), *k), 2);
          if (area_mse > 0.0) best_vs_area = eff * area_mse * r.cost[a].ns_per_sample;
        }
      }
    md += "| " + table->axes.regions[reg] + " | " + (best_name.empty() ? "-" : best_name) + " | " +
          fmt("%.2e", best_mse) + " | " +
          (best_vs_area > 0.0 ? fmt("%.3g", best_vs_area) : std::string("-")) + " | " +
          (exact.empty() ? std::string("-") : exact) + " |\n";
  }
  return md;
}

std::string headline(const VarianceResult& r, const std::vector<ImageRow>& rows) {
  std::string md = "| map |";
  for (const std::string& q : r.config.sequences)
    md += " MSE " + q + " |";
  md += " time / sample (ns) | time vs baseline | efficiency vs area (" +
        r.config.sequences.back() + ") |\n| --- |";
  for (std::size_t i = 0; i < r.config.sequences.size() + 3; ++i)
    md += " ---: |";
  md += "\n";
  for (std::size_t m = 0; m < r.map_names.size(); ++m) {
    md += "| " + r.map_names[m] + " |";
    const ImageRow* last = nullptr;
    for (const ImageRow& row : rows)
      if (row.map == r.map_names[m] && row.region == "image") {
        md += ' ';
        md += fmt("%.3e", row.mse);
        md += " |";
        last = &row;
      }
    md += ' ';
    md += fmt("%.0f", r.cost[m].ns_per_sample);
    md += " | ";
    md += fmt("%.2f", r.cost[m].ratio_to_baseline);
    md += " | ";
    md += last ? fmt("%.3g", last->efficiency_vs_area) : "-";
    md += " |\n";
  }
  return md;
}

std::string slope_tables(const VarianceResult& r, const std::vector<study::CurveFit>& fits) {
  const auto& t = r.curves;
  const auto k256 = t.find_n(256);
  std::string md;
  for (std::size_t reg = 0; reg < t.axes.regions.size(); ++reg) {
    md += "\n#### " + t.axes.regions[reg] + "\n\n| map |";
    for (const auto& q : t.axes.sequences)
      md += " " + q + " |";
    md += "\n| --- |";
    for (std::size_t i = 0; i < t.axes.sequences.size(); ++i)
      md += " ---: |";
    md += "\n";
    for (std::size_t m = 0; m < t.axes.methods.size(); ++m) {
      md += "| " + t.axes.methods[m] + " |";
      for (std::size_t q = 0; q < t.axes.sequences.size(); ++q) {
        const std::size_t c = t.curve_index(reg, m, q);
        md += ' ';
        md += slope_cell(fits[c]);
        if (k256) {
          md += ", RMS(256) ";
          md += fmt("%.2e", t.rmse(c, *k256));
        }
        md += " |";
      }
      md += "\n";
    }
  }
  return md;
}

// MSE over the shadowed pixels per map and sequence, and its ratio to radial's.
std::string shadowed_table(const VarianceResult& r, const std::vector<ImageRow>& rows) {
  std::string md = "| map |";
  for (const std::string& q : r.config.sequences)
    md += " MSE " + q + " | vs radial |";
  md += "\n| --- |";
  for (std::size_t i = 0; i < 2 * r.config.sequences.size(); ++i)
    md += " ---: |";
  md += "\n";
  auto find = [&](const std::string& map, const std::string& q) -> const ImageRow* {
    for (const ImageRow& row : rows)
      if (row.region == "shadowed" && row.map == map && row.sequence == q) return &row;
    return nullptr;
  };
  for (const std::string& map : r.map_names) {
    md += "| " + map + " |";
    for (const std::string& q : r.config.sequences) {
      const ImageRow *row = find(map, q), *radial = find("radial", q);
      md += ' ';
      md += row ? fmt("%.3e", row->mse) : "-";
      md += " | ";
      md += row && radial && radial->mse > 0.0 ? fmt("%.2f", row->mse / radial->mse) : "-";
      md += " |";
    }
    md += "\n";
  }
  return md;
}

// Maps sorted by MSE at N = spp, per sequence (rows) and image / region (columns): where the
// ordering of Fig. 7 changes between regions, this shows how.
std::string ordering_table(const VarianceResult& r) {
  const uint32_t spp = r.config.spp;
  std::vector<std::pair<const study::CurveTable*, std::size_t>> columns{{&r.image, 0}};
  for (std::size_t reg = 0; reg < r.curves.axes.regions.size(); ++reg)
    columns.emplace_back(&r.curves, reg);
  std::string md = "| sequence | image |";
  for (const auto& name : r.curves.axes.regions)
    md += " " + name + " |";
  md += "\n| --- |";
  for (std::size_t i = 0; i < columns.size(); ++i)
    md += " --- |";
  md += "\n";
  for (std::size_t q = 0; q < r.config.sequences.size(); ++q) {
    md += "| " + r.config.sequences[q] + " |";
    for (const auto& [table, reg] : columns) {
      const auto k = table->find_n(spp);
      if (!k) {
        md += " - |";
        continue;
      }
      std::vector<std::pair<double, std::string>> order;
      for (std::size_t m = 0; m < r.map_names.size(); ++m)
        order.emplace_back(table->rmse(table->curve_index(reg, m, q), *k), r.map_names[m]);
      std::sort(order.begin(), order.end());
      std::string cell;
      for (const auto& [e, name] : order)
        cell += (cell.empty() ? "" : " < ") + name;
      md += " " + cell + " |";
    }
    md += "\n";
  }
  return md;
}

// The memo's open question, answered from the radial4 claims' outcomes.
std::string radial4_answer(const std::vector<study::Claim>& claims,
                           const std::vector<study::ClaimOutcome>& outcomes) {
  int lower = 0, total = 0;
  double lo = INFINITY, hi = 0.0;
  for (const study::ClaimOutcome& o : outcomes) {
    if (claims[o.claim].section != "radial4" || !o.measured) continue;
    ++total;
    lower += o.verdict == study::Verdict::reproduced;
    lo = std::min(lo, *o.measured);
    hi = std::max(hi, *o.measured);
  }
  if (total == 0) return "Not measured in this run (it needs radial4, radial, ld-radial, N = 256).";
  std::string s = "RMS(radial4) / RMS(radial or ld-radial) at N = 256 ranges from " +
                  fmt("%.2f", lo) + " to " + fmt("%.2f", hi) + " over " + std::to_string(total) +
                  " (region, sequence, baseline) cases; " + std::to_string(lower) +
                  " meet the memo's \"helps\" rule (ratio <= 0.8). ";
  if (lower == total)
    s += "**Yes**: radial4 carries polar4's gain to solid-angle sampling in every region.";
  else if (lower == 0)
    s += "**No**: with these stratified sequences radial4 does not lower the error.";
  else
    s += "**It depends on the region**: see the table below.";
  return s;
}

Outputs make_outputs(const VarianceResult& r) {
  const VarianceConfig& c = r.config;
  const std::vector<study::CurveFit> fits =
      study::fit_all(r.curves, study::make_curve_bootstrap(c), c.threads);
  const std::vector<study::Claim> claims = study::guillen_claims(r);
  const std::vector<study::ClaimOutcome> outcomes = study::evaluate_guillen_claims(claims, r);
  const std::vector<ImageRow> rows = image_rows(r);
  Outputs o;
  nlohmann::json j;
  nlohmann::json meta;
  meta["study"] = "Guillén et al. 2017, Sec. 5, Figs. 6-7";
  meta["command"] = command_line(r);
  meta["scene"] = kScene;
  meta["seeds"] = c.seeds;
  meta["image_randomizations"] = c.image_randomizations;
  meta["first_seed"] = c.first_seed;
  meta["ns"] = c.ns;
  meta["spp"] = c.spp;
  meta["fit_n_min"] = c.fit_min;
  meta["fit_n_max"] = c.ns.back();
  meta["bootstrap_replicates"] = c.bootstrap_replicates;
  meta["timing_repetitions"] = c.timing_repetitions;
  meta["maps"] = r.map_names;
  meta["sequences"] = c.sequences;
  meta["image"] = {{"size", c.image.size},
                   {"x0", c.image.lo},
                   {"x1", c.image.hi},
                   {"raw",
                    "variance_reference.f64: float64 little-endian, row-major, row 0 = "
                    "largest y"},
                   {"quadrature_pixels", r.image_reference.quadrature_pixels}};
  for (const auto& region : c.regions)
    meta["regions"].push_back({{"name", region.grid.name},
                               {"x0", region.grid.x0},
                               {"x1", region.grid.x1},
                               {"y0", region.grid.y0},
                               {"y1", region.grid.y1},
                               {"nx", region.grid.nx},
                               {"ny", region.grid.ny}});
  j["meta"] = meta;

  const TableOutput curve_table = curve_rows(r.curves, "map"),
                    fit_table = fit_rows(r.curves, fits, "map"),
                    refs = reference_rows(r.references);
  o.csv = curve_table.csv;
  j["rows"] = curve_table.json;
  o.fits_csv = fit_table.csv;
  j["fits"] = fit_table.json;
  o.refs_csv = refs.csv;
  j["references"] = refs.json;

  o.images_csv =
      "region,map,sequence,spp,mse,mse_se,rel_mse,ns_per_sample,ratio_to_baseline,efficiency,"
      "efficiency_vs_area\n";
  j["images"] = nlohmann::json::array();
  for (const ImageRow& row : rows) {
    o.images_csv += row.region + "," + row.map + "," + row.sequence + "," + std::to_string(c.spp) +
                    "," + fmt17(row.mse) + "," + fmt17(row.mse_se) + "," + fmt17(row.rel_mse) +
                    "," + fmt17(row.ns_per_sample) + "," + fmt17(row.ratio) + "," +
                    fmt17(row.efficiency) + "," + fmt17(row.efficiency_vs_area) + "\n";
    j["images"].push_back({{"region", row.region},
                           {"map", row.map},
                           {"sequence", row.sequence},
                           {"spp", c.spp},
                           {"mse", row.mse},
                           {"mse_se", row.mse_se},
                           {"rel_mse", row.rel_mse},
                           {"ns_per_sample", row.ns_per_sample},
                           {"ratio_to_baseline", row.ratio},
                           {"efficiency", row.efficiency},
                           {"efficiency_vs_area", row.efficiency_vs_area}});
  }
  o.cost_csv =
      "map,setup_ns,sample_ns,ns_per_sample,ratio_to_baseline,newton_mean,newton_per_sample,"
      "newton_max,root_solves\n";
  o.newton_csv = "map,iterations,solves\n";
  j["cost"] = nlohmann::json::array();
  for (std::size_t m = 0; m < r.map_names.size(); ++m) {
    const study::MapCost& k = r.cost[m];
    const study::NewtonStats& n = r.newton[m];
    o.cost_csv += r.map_names[m] + "," + fmt17(k.setup_ns) + "," + fmt17(k.sample_ns) + "," +
                  fmt17(k.ns_per_sample) + "," + fmt17(k.ratio_to_baseline) + "," + fmt17(n.mean) +
                  "," + fmt17(n.per_sample) + "," + std::to_string(n.max) + "," +
                  std::to_string(n.solves) + "\n";
    for (std::size_t b = 0; b < n.histogram.size(); ++b)
      if (n.histogram[b] > 0)
        o.newton_csv +=
            r.map_names[m] + "," + std::to_string(b) + "," + std::to_string(n.histogram[b]) + "\n";
    j["cost"].push_back({{"map", r.map_names[m]},
                         {"setup_ns", k.setup_ns},
                         {"sample_ns", k.sample_ns},
                         {"ns_per_sample", k.ns_per_sample},
                         {"ratio_to_baseline", k.ratio_to_baseline},
                         {"newton_mean", n.mean},
                         {"newton_per_sample", n.per_sample},
                         {"newton_max", n.max},
                         {"root_solves", n.solves},
                         {"newton_histogram", n.histogram}});
  }
  // The baseline the ratios divide by: the renderer's area sample (no root solves).
  const study::MapCost& base = r.baseline_cost;
  o.cost_csv += std::string(kBaselineName) + "," + fmt17(base.setup_ns) + "," +
                fmt17(base.sample_ns) + "," + fmt17(base.ns_per_sample) + "," +
                fmt17(base.ratio_to_baseline) + ",0,0,0,0\n";
  j["cost"].push_back({{"map", kBaselineName},
                       {"setup_ns", base.setup_ns},
                       {"sample_ns", base.sample_ns},
                       {"ns_per_sample", base.ns_per_sample},
                       {"ratio_to_baseline", base.ratio_to_baseline},
                       {"newton_mean", 0.0},
                       {"newton_per_sample", 0.0},
                       {"newton_max", 0},
                       {"root_solves", 0},
                       {"newton_histogram", nlohmann::json::array()}});
  j["claims"] = claims_json(claims, outcomes);
  o.json = j.dump(1) + "\n";

  o.answer_markdown = answer_markdown(r);
  o.claims_markdown = study::claims_markdown(
      claims, outcomes, study::guillen_sections(),
      "MSE ratios are of image MSEs (column image) or of the regions' MSE over their 4 x 4 "
      "points, at N = " +
          std::to_string(c.spp) + "; radial4's are of RMS errors at N = 256.");
  double worst = 0.0;
  for (std::size_t i = 0; i < r.image_reference.value.size(); ++i)
    if (r.image_reference.value[i] > 0.0)
      worst = std::max(worst, r.image_reference.error[i] / r.image_reference.value[i]);
  for (const auto& refs : r.references)
    for (const auto& p : refs.points)
      worst = std::max(worst, p.reference.error_estimate / p.reference.value);
  std::string md = "# disklab variance\n\nGenerated by `" + command_line(r) +
                   "`: the variance and cost study of Guillén et al. (Sec. 5, Figs. 6-7) on a "
                   "scene anyone can recompute.\n\n";
  md += std::string("- Scene: ") + kScene + "\n";
  md += "- Image: the ground square x, y in [-2, 2] as " + std::to_string(c.image.size) + " x " +
        std::to_string(c.image.size) + " pixels, " + std::to_string(c.spp) +
        " samples per pixel, each pixel its own randomization, " +
        std::to_string(c.image_randomizations) +
        " image randomizations. Reference: rim integral where no occluder can block the light, "
        "else quadrature (" +
        std::to_string(r.image_reference.quadrature_pixels) +
        " pixels); largest error estimate, relative: " + fmt("%.1e", worst) + ".\n";
  md += "- Regions near, mid, far: 4 x 4 unoccluded points each, " + std::to_string(c.seeds) +
        " randomizations (one sequence instance per seed shared by every point and map); "
        "slopes fit log RMS vs log N over N = " +
        std::to_string(c.fit_min) + ".." + std::to_string(c.ns.back()) +
        " ± the bootstrap standard error over the seeds.\n";
  md +=
      "- Estimators: (1/N) sum L (w . n_o) V / pdf(w); area with its solid-angle pdf; gamito and "
      "tabulated with their proposal densities (a rejected candidate is a zero sample); "
      "radial4's four copies of a square point are four samples.\n";
  md += "- Cost: single-threaded over the image's pixels (set-up + " + std::to_string(c.spp) +
        " samples per pixel), median of " + std::to_string(c.timing_repetitions) +
        " interleaved repetitions in this run, every sample consumed whole (direction, point, "
        "pdf, validity) as in bench_maps; ratios are to the same run's baseline, the area sample "
        "a renderer writes (ellipse::LeanAreaSampler); efficiency = 1 / (MSE x time per "
        "pixel).\n\n";
  md += "## Headline: image MSE at " + std::to_string(c.spp) + " spp and cost\n\n" +
        headline(r, rows);
  md += "\n### The shadowed pixels (" + std::to_string(r.image_reference.quadrature_pixels) +
        " pixels an occluder may shadow: the penumbra, where no map is zero-variance)\n\n" +
        shadowed_table(r, rows);
  md += "\n## Ordering by MSE at N = " + std::to_string(c.spp) +
        " (Fig. 7: radial < parallel ~ ld-radial < Gamito << area)\n\n" + ordering_table(r);
  md += "\n## The memo's open question: radial4\n\n" + radial4_answer(claims, outcomes) + "\n";
  md +=
      "\n## Cost and Newton-Raphson iterations\n\n| map | set-up (ns) | per sample (ns) | "
      "per sample at " +
      std::to_string(c.spp) +
      " spp (ns) | vs baseline | Newton per solve | per sample | max |\n| --- | ---: | ---: | "
      "---: | ---: | ---: | ---: | ---: |\n";
  for (std::size_t m = 0; m < r.map_names.size(); ++m) {
    const study::MapCost& k = r.cost[m];
    md += "| " + r.map_names[m] + " | " + fmt("%.0f", k.setup_ns) + " | " +
          fmt("%.1f", k.sample_ns) + " | " + fmt("%.1f", k.ns_per_sample) + " | " +
          fmt("%.2f", k.ratio_to_baseline) + " | " + fmt("%.2f", r.newton[m].mean) + " | " +
          fmt("%.2f", r.newton[m].per_sample) + " | " + std::to_string(r.newton[m].max) + " |\n";
  }
  {
    const study::MapCost& k = r.baseline_cost;
    md += std::string("| ") + kBaselineName + " (the renderer's area sample) | " +
          fmt("%.0f", k.setup_ns) + " | " + fmt("%.1f", k.sample_ns) + " | " +
          fmt("%.1f", k.ns_per_sample) + " | 1 | - | - | - |\n";
  }
  md += "\n## Slopes (log RMS vs log N) and RMS at N = 256\n" + slope_tables(r, fits);
  md += "\n## Claims\n\n" + o.claims_markdown;
  o.markdown = md;
  return o;
}

void write_raw(const fs::path& target, const std::vector<double>& values) {
  static_assert(std::endian::native == std::endian::little, "raw arrays are little-endian");
  std::string bytes(values.size() * sizeof(double), '\0');
  std::memcpy(bytes.data(), values.data(), bytes.size());
  write_file_atomic(target, bytes);
}

void write_outputs(const fs::path& dir, const VarianceResult& r, const Outputs& o, bool plots) {
  create_out_dir(dir);
  write_file_atomic(dir / "variance.csv", o.csv);
  write_file_atomic(dir / "variance_fits.csv", o.fits_csv);
  write_file_atomic(dir / "variance_references.csv", o.refs_csv);
  write_file_atomic(dir / "variance_images.csv", o.images_csv);
  write_file_atomic(dir / "variance_cost.csv", o.cost_csv);
  write_file_atomic(dir / "variance_newton.csv", o.newton_csv);
  write_file_atomic(dir / "variance.json", o.json);
  write_raw(dir / "variance_reference.f64", r.image_reference.value);
  for (std::size_t q = 0; q < r.config.sequences.size(); ++q) {
    std::vector<double> all;
    for (std::size_t m = 0; m < r.map_names.size(); ++m) {
      const auto& img = r.image_of(m, q);
      all.insert(all.end(), img.begin(), img.end());
    }
    write_raw(dir / ("variance_image_" + r.config.sequences[q] + ".f64"), all);
  }
  std::string md = o.markdown;
  if (plots) {
    std::string figures = "\n## Figures\n\n";
    auto plot = [&](const std::string& script, const std::string& png, const std::string& title,
                    const std::vector<std::string>& args) {
      figures += plot_markdown(script, args, dir, png, title);
    };
    const std::string size = std::to_string(r.config.image.size);
    plot("variance_images", "variance_reference.png", "reference",
         {"--reference", (dir / "variance_reference.f64").string(), "--size", size});
    for (const std::string& q : r.config.sequences)
      plot("variance_images", "variance_images_" + q + ".png", "16 spp images, " + q,
           {"--reference", (dir / "variance_reference.f64").string(), "--size", size, "--images",
            (dir / ("variance_image_" + q + ".f64")).string(), "--maps", join(r.map_names),
            "--table", (dir / "variance_images.csv").string(), "--sequence", q});
    for (const auto& region : r.config.regions)
      plot(
          "convergence", "variance_" + region.grid.name + ".png", region.grid.name,
          {"--csv", (dir / "variance.csv").string(), "--fits", (dir / "variance_fits.csv").string(),
           "--region", region.grid.name, "--method-column", "map", "--title",
           "RMS error vs N, " + region.grid.name + " (" + std::to_string(r.config.seeds) +
               " seeds)"});
    plot(
        "variance_time", "variance_equal_time.png", "RMS vs time",
        {"--csv", (dir / "variance.csv").string(), "--cost", (dir / "variance_cost.csv").string()});
    md += figures;
  }
  write_file_atomic(dir / "variance.md", md);
}

VarianceResult run_study(VarianceConfig config) {
  const uint64_t total = study::work_units(config);
  return run_with_progress("variance", total, std::move(config),
                           [](VarianceConfig c) { return study::run_variance(std::move(c)); });
}

int run_variance_command(const VarianceState& s) {
  const fs::path dir = check_out_dir(s.out);
  const VarianceConfig config = make_config(s);
  const auto start = std::chrono::steady_clock::now();
  const VarianceResult r = run_study(config);
  write_outputs(dir, r, make_outputs(r), !s.no_plots);
  print_finished("variance",
                 std::to_string(r.map_names.size()) + " maps x " +
                     std::to_string(r.config.sequences.size()) + " sequences",
                 start, dir / "variance.md");
  return 0;
}

int report_variance(const ReportOptions& options) {
  VarianceState s;
  s.quick = options.quick;
  const VarianceResult r = run_study(make_config(s));
  const Outputs o = make_outputs(r);
  write_outputs(options.dir, r, o, true);
  if (options.answers)
    *options.answers +=
        "### Which map (Guillén et al.'s study; full tables in "
        "[variance.md](variance.md))\n\n" +
        o.answer_markdown + "\n";
  if (options.claims)
    *options.claims +=
        "### Guillén et al. (`disklab variance" + std::string(options.quick ? " --quick" : "") +
        "`, " + std::to_string(r.config.image_randomizations) + " image randomizations, " +
        std::to_string(r.config.seeds) +
        " seeds per region; details in [variance.md](variance.md))\n\n" + o.claims_markdown;
  return 0;
}

std::function<int()> setup_variance(Options& sub) {
  auto state = std::make_shared<VarianceState>();
  std::string sequences;
  for (const auto& n : sequence::sequence_names())
    sequences += " " + n;
  sub.add_option("--out", state->out, "Output folder (created if missing)")->capture_default_str();
  sub.add_flag("--quick", state->quick,
               "Smaller run: " + std::to_string(kQuickSeeds) + " seeds, " +
                   std::to_string(kQuickImages) + " image randomizations, N up to " +
                   std::to_string(kQuickMaxN) + ", " + std::to_string(kQuickTimingReps) +
                   " timing repetitions (explicit options win)");
  auto* seeds =
      sub.add_option("--seeds", state->seeds, "Randomizations per region curve (1 .. 10000)")
          ->capture_default_str();
  auto* images = sub.add_option("--images", state->images,
                                "Image randomizations for the 16-spp MSE (1 .. 1000)")
                     ->capture_default_str();
  sub.add_option("--seed", state->seed_text, "First randomization (unsigned 64-bit)")
      ->capture_default_str();
  auto* max_n = sub.add_option("--max-n", state->max_n, "Largest N (power of two, <= 65536)")
                    ->capture_default_str();
  sub.add_option("--min-n", state->min_n, "Smallest N (power of two >= 16)")->capture_default_str();
  sub.add_option("--fit-min", state->fit_min, "Slopes fit N in [fit-min, max-n] (power of two)")
      ->capture_default_str();
  sub.add_option("--maps", state->maps,
                 "Comma-separated subset (default all): " + join(ellipse::map_names()));
  sub.add_option("--sequences", state->sequences,
                 "Comma-separated (default random,sobol-owen,pmj02):" + sequences);
  sub.add_option("--regions", state->regions, "Comma-separated subset (default all): near mid far");
  auto* reps = sub.add_option("--timing-reps", state->timing_reps,
                              "Timing repetitions; the cost is their median (1 .. 100)")
                   ->capture_default_str();
  sub.add_option("--threads", state->threads,
                 "Worker threads (0: all cores); the error numbers do not depend on it")
      ->capture_default_str();
  sub.add_flag("--no-plots", state->no_plots, "Skip the PNGs (no matplotlib needed)");
  sub.footer(
      "Guillén et al.'s study (Sec. 5, Figs. 6-7) on an exactly recomputable scene: a vertical\n"
      "two-sided disk light (R 0.5 at (0, 0, 0.6), normal +x) over the ground, an opaque sphere\n"
      "(r 0.25 at (-0.8, 0.5, 0.3)). Irradiance is estimated in solid angle with every ellipse\n"
      "map: (1/N) sum L (w . n_o) V / pdf(w); gamito and tabulated with their proposal densities\n"
      "(a rejected candidate counts as a zero sample); radial4's four copies count as four.\n"
      "References: a rim (boundary) integral where nothing can block the light, a quadrature\n"
      "elsewhere (error estimates <= 1e-10 relative). The error numbers are the same for any\n"
      "--threads; the timings are measured on one thread, in this run, as ratios to the\n"
      "baseline (the area sample a renderer writes, ellipse::LeanAreaSampler), by the rules of\n"
      "bench_maps: every sample consumed whole, methods alternated, median of the repetitions.\n"
      "Files in --out:\n"
      "  variance.csv            region,map,sequence,n,rmse,rel_rmse: RMS over the region's 16\n"
      "                          points and the seeds of (estimate - reference), and of the same\n"
      "                          divided by the reference\n"
      "  variance_fits.csv       region,map,sequence,slope,slope_se,fit_n_min,fit_n_max: slope of\n"
      "                          log rmse vs log N, bootstrap standard error over the seeds\n"
      "  variance_images.csv     region,map,sequence,spp,mse,mse_se,rel_mse,ns_per_sample,\n"
      "                          ratio_to_baseline,efficiency,efficiency_vs_area: MSE over the\n"
      "                          region's pixels (image: all; shadowed: those an occluder may\n"
      "                          shadow) and image randomizations (mse_se: bootstrap), relative\n"
      "                          MSE (each error / reference), time per sample with the\n"
      "                          per-pixel set-up amortized, its ratio to the baseline's, and\n"
      "                          efficiency = 1 / (MSE x seconds per pixel)\n"
      "  variance_cost.csv       map,setup_ns,sample_ns,ns_per_sample,ratio_to_baseline,\n"
      "                          newton_mean,newton_per_sample,newton_max,root_solves: set-up\n"
      "                          alone, each further sample, Newton iterations per root solve\n"
      "                          (and per sample: radial4 shares a solve among 4) over the image\n"
      "                          samples; a last row, baseline, is the renderer's area sample\n"
      "  variance_newton.csv     map,iterations,solves: the iteration histogram\n"
      "  variance_references.csv region,x,y,E,error_estimate,method per region point\n"
      "  variance_reference.f64  the reference image: size x size float64, little-endian,\n"
      "                          row-major, row 0 = largest y; variance_image_<sequence>.f64 the\n"
      "                          maps' first-randomization images, one after the other\n"
      "  variance.json           {meta, rows, fits, images, references, cost, claims}\n"
      "  variance.md             headline, radial4's answer, cost, slopes, claims with verdicts\n"
      "  variance_reference.png, variance_images_<sequence>.png (images and error images like\n"
      "                          Fig. 7), variance_<region>.png, variance_equal_time.png\n"
      "Full run: 1-2 minutes on 2 cores; --quick: about 14 s (9 without plots).\n"
      "Examples:\n"
      "  disklab variance --out var\n"
      "  disklab variance --quick --out /tmp/var\n"
      "  disklab variance --maps area,radial,radial4 --sequences pmj02 --regions near\n");
  return [state, seeds, images, max_n, reps] {
    VarianceState s = *state;
    s.seeds_given = seeds->count() > 0;
    s.images_given = images->count() > 0;
    s.max_n_given = max_n->count() > 0;
    s.reps_given = reps->count() > 0;
    return run_variance_command(s);
  };
}

const Registrar kVariance{Command{"variance",
                                  "Guillén's variance and cost study: image MSE, RMS vs N, cost",
                                  setup_variance, report_variance}};

}  // namespace
}  // namespace disklab::cli
