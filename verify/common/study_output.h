#pragma once
// Output pieces the studies share: a curve table's rows and fits as CSV and JSON, claims as
// JSON, and number cells for the markdown.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/output.h"
#include "study/claims.h"
#include "study/curves.h"
#include "study/reference.h"

namespace disklab::cli {

struct TableOutput {
  std::string csv;
  nlohmann::json json = nlohmann::json::array();
};

// null for a missing or non-finite value.
nlohmann::json optional_json(const std::optional<double>& v);

// region,<method_column>,sequence,n,rmse,rel_rmse: one row per curve and N.
TableOutput curve_rows(const study::CurveTable& table, const std::string& method_column);
// region,<method_column>,sequence,slope,slope_se,fit_n_min,fit_n_max.
TableOutput fit_rows(const study::CurveTable& table, const std::vector<study::CurveFit>& fits,
                     const std::string& method_column);
// region,x,y,E,error_estimate,method: one row per shading point.
TableOutput reference_rows(const std::vector<study::RegionReferences>& references);
// {id, section, claim, measured_as, rule, claimed, region, measured, se, verdict, note}.
nlohmann::json claims_json(const std::vector<study::Claim>& claims,
                           const std::vector<study::ClaimOutcome>& outcomes);

// A study's --out: non-empty and not an existing non-folder (UsageError otherwise); checked
// before any work. create_out_dir makes it (UsageError when that fails).
std::filesystem::path check_out_dir(const std::string& out);
void create_out_dir(const std::filesystem::path& dir);

// Runs the plot script into dir / png and returns the Markdown that shows it, or (on a failed
// plot: a warning on stderr) the note that says it is missing.
std::string plot_markdown(const std::string& script, const std::vector<std::string>& args,
                          const std::filesystem::path& dir, const std::string& png,
                          const std::string& title);

// Runs run(config) with a progress line on stderr ticked by config.progress (cleared in the
// result, which must carry its config).
template <class Config, class Run>
auto run_with_progress(const char* label, uint64_t total, Config config, Run&& run) {
  Progress progress(label, total);
  config.progress = [&progress](uint64_t, uint64_t) { progress.tick(); };
  auto result = run(std::move(config));
  progress.finish();
  result.config.progress = nullptr;
  return result;
}

// "<label>: <what> in S s; see <markdown>" on stderr since `start`, unless DISKLAB_QUIET is set.
void print_finished(const char* label, const std::string& what,
                    std::chrono::steady_clock::time_point start,
                    const std::filesystem::path& markdown);

// "+1.23 ± 0.04" ("-" when there is no slope).
std::string slope_cell(const study::CurveFit& f);

}  // namespace disklab::cli
