#include "common/study_output.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "command.h"
#include "common/output.h"

namespace disklab::cli {

nlohmann::json optional_json(const std::optional<double>& v) {
  if (!v || !std::isfinite(*v)) return nullptr;
  return *v;
}

TableOutput curve_rows(const study::CurveTable& t, const std::string& method_column) {
  TableOutput o;
  o.csv = "region," + method_column + ",sequence,n,rmse,rel_rmse\n";
  for (std::size_t curve = 0; curve < t.curves(); ++curve) {
    const std::string& region = t.axes.regions[t.region_of(curve)];
    const std::string &m = t.method_of(curve), &q = t.sequence_of(curve);
    for (std::size_t k = 0; k < t.ns().size(); ++k) {
      const double e = t.rmse(curve, k), rel = t.rel_rmse(curve, k);
      o.csv += region + "," + m + "," + q + "," + std::to_string(t.ns()[k]) + "," + fmt17(e) + "," +
               fmt17(rel) + "\n";
      o.json.push_back({{"region", region},
                        {method_column, m},
                        {"sequence", q},
                        {"n", t.ns()[k]},
                        {"rmse", e},
                        {"rel_rmse", rel}});
    }
  }
  return o;
}

TableOutput fit_rows(const study::CurveTable& t, const std::vector<study::CurveFit>& fits,
                     const std::string& method_column) {
  TableOutput o;
  o.csv = "region," + method_column + ",sequence,slope,slope_se,fit_n_min,fit_n_max\n";
  const uint32_t n_max = t.ns().empty() ? 0 : t.ns().back();
  for (const study::CurveFit& f : fits) {
    const std::string& region = t.axes.regions[t.region_of(f.curve)];
    const std::string &m = t.method_of(f.curve), &q = t.sequence_of(f.curve);
    o.csv += region + "," + m + "," + q + "," + (f.slope ? fmt17(*f.slope) : "") + "," +
             (f.slope_se ? fmt17(*f.slope_se) : "") + "," + std::to_string(t.axes.fit_min) + "," +
             std::to_string(n_max) + "\n";
    o.json.push_back({{"region", region},
                      {method_column, m},
                      {"sequence", q},
                      {"slope", optional_json(f.slope)},
                      {"slope_se", optional_json(f.slope_se)},
                      {"fit_n_min", t.axes.fit_min},
                      {"fit_n_max", n_max}});
  }
  return o;
}

TableOutput reference_rows(const std::vector<study::RegionReferences>& references) {
  TableOutput o;
  o.csv = "region,x,y,E,error_estimate,method\n";
  for (const auto& refs : references)
    for (const auto& p : refs.points) {
      o.csv += refs.region + "," + fmt17(p.point.position.x()) + "," + fmt17(p.point.position.y()) +
               "," + fmt17(p.reference.value) + "," + fmt17(p.reference.error_estimate) + "," +
               refs.method + "\n";
      o.json.push_back({{"region", refs.region},
                        {"x", p.point.position.x()},
                        {"y", p.point.position.y()},
                        {"E", p.reference.value},
                        {"error_estimate", p.reference.error_estimate},
                        {"method", refs.method}});
    }
  return o;
}

nlohmann::json claims_json(const std::vector<study::Claim>& claims,
                           const std::vector<study::ClaimOutcome>& outcomes) {
  nlohmann::json j = nlohmann::json::array();
  for (const study::ClaimOutcome& out : outcomes) {
    const study::Claim& cl = claims[out.claim];
    j.push_back({{"id", cl.id},
                 {"section", cl.section},
                 {"claim", cl.text},
                 {"measured_as", cl.measured_as},
                 {"rule", study::rule_text(cl.rule)},
                 {"claimed", cl.rule.claimed},
                 {"region", out.region},
                 {"measured", optional_json(out.measured)},
                 {"se", optional_json(out.se)},
                 {"verdict", study::verdict_name(out.verdict)},
                 {"note", out.note}});
  }
  return j;
}

std::filesystem::path check_out_dir(const std::string& out) {
  if (out.empty()) throw UsageError("--out: empty folder name");
  std::filesystem::path dir(out);
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw UsageError("--out: '" + out + "' exists and is not a folder");
  return dir;
}

void create_out_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw UsageError("--out: cannot create folder '" + dir.string() + "': " + ec.message());
}

std::string plot_markdown(const std::string& script, const std::vector<std::string>& args,
                          const std::filesystem::path& dir, const std::string& png,
                          const std::string& title) {
  try {
    run_plot(script, args, dir / png);
    return "![" + title + "](" + png + ")\n\n";
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "disklab: warning: %s not written: %s\n", png.c_str(), e.what());
    return "(" + png + " not written: the plot script failed; see stderr.)\n\n";
  }
}

void print_finished(const char* label, const std::string& what,
                    std::chrono::steady_clock::time_point start,
                    const std::filesystem::path& markdown) {
  if (std::getenv("DISKLAB_QUIET")) return;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "%s: %s in %.1f s; see %s\n", label, what.c_str(), seconds,
               markdown.c_str());
}

std::string slope_cell(const study::CurveFit& f) {
  if (!f.slope) return "-";
  char buf[64];
  if (f.slope_se)
    std::snprintf(buf, sizeof buf, "%+.2f ± %.2f", *f.slope, *f.slope_se);
  else
    std::snprintf(buf, sizeof buf, "%+.2f", *f.slope);
  return buf;
}

}  // namespace disklab::cli
