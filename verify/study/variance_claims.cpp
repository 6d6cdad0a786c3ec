// Guillén et al.'s claims (Sec. 5, Figs. 6-7) and Christensen's radial4 question, measured on
// the variance study.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "study/variance.h"

namespace disklab::study {

namespace {
using Weights = std::span<const uint32_t>;
using Opt = std::optional<double>;

// MSE at N = n of one curve (nullopt when missing).
Opt mse(const CurveTable& t, std::size_t region, const std::string& map, const std::string& seq,
        uint32_t n, Weights w) {
  const auto c = t.find_curve(t.axes.regions[region], map, seq);
  const auto k = t.find_n(n);
  if (!c || !k) return std::nullopt;
  const double e = t.rmse(*c, *k, w);
  return e * e;
}

Measure mse_ratio(const std::string& a, const std::string& b, const std::string& seq, uint32_t n) {
  return [=](const CurveTable& t, std::size_t region, Weights w) -> Opt {
    const Opt ma = mse(t, region, a, seq, n, w), mb = mse(t, region, b, seq, n, w);
    if (!ma || !mb || !(*mb > 0.0)) return std::nullopt;
    return *ma / *mb;
  };
}

// Fig. 7's ordering radial < {parallel, ld-radial} < gamito < area: how many of its five
// pairwise inequalities the measured MSEs violate.
Measure ordering_violations(const std::string& seq, uint32_t n) {
  return [=](const CurveTable& t, std::size_t region, Weights w) -> Opt {
    const std::vector<std::pair<std::string, std::string>> less = {{"radial", "parallel"},
                                                                   {"radial", "ld-radial"},
                                                                   {"parallel", "gamito"},
                                                                   {"ld-radial", "gamito"},
                                                                   {"gamito", "area"}};
    double violated = 0.0;
    for (const auto& [a, b] : less) {
      const Opt ma = mse(t, region, a, seq, n, w), mb = mse(t, region, b, seq, n, w);
      if (!ma || !mb) return std::nullopt;
      violated += *ma < *mb ? 0.0 : 1.0;
    }
    return violated;
  };
}

// Geometric mean over the table's N of max / min MSE among `maps` with sequence `seq` (the
// image table has one N).
Measure mse_spread(const std::vector<std::string>& maps, const std::string& seq) {
  return [=](const CurveTable& t, std::size_t region, Weights w) -> Opt {
    double log_sum = 0.0;
    for (uint32_t n : t.ns()) {
      double lo = INFINITY, hi = 0.0;
      for (const std::string& m : maps) {
        const Opt v = mse(t, region, m, seq, n, w);
        if (!v || !(*v > 0.0)) return std::nullopt;
        lo = std::min(lo, *v);
        hi = std::max(hi, *v);
      }
      log_sum += std::log(hi / lo);
    }
    if (t.ns().empty()) return std::nullopt;
    return std::exp(log_sum / static_cast<double>(t.ns().size()));
  };
}

std::optional<std::size_t> map_index(const VarianceResult& r, const std::string& name) {
  const auto it = std::find(r.map_names.begin(), r.map_names.end(), name);
  if (it == r.map_names.end()) return std::nullopt;
  return static_cast<std::size_t>(it - r.map_names.begin());
}
}  // namespace

std::vector<ClaimSection> guillen_sections() {
  return {{"fig7", "Fig. 7: MSE at 16 samples per pixel (Guillén et al., Sec. 5)"},
          {"iid", "Independent input: the uniform maps are alike"},
          {"newton", "Newton-Raphson iterations (Sec. 5)"},
          {"cost", "Cost per sample (Sec. 5, Fig. 6)"},
          {"radial4", "Christensen's open question: does radial4 carry polar4's gain?"}};
}

std::vector<Claim> guillen_claims(const VarianceResult& r) {
  std::vector<Claim> out;
  const VarianceConfig& c = r.config;
  const uint32_t spp = c.spp;
  const std::vector<std::string> all_regions = [&] {
    std::vector<std::string> v{"image"};
    for (const auto& reg : c.regions)
      v.push_back(reg.grid.name);
    return v;
  }();
  std::vector<std::string> region_names(all_regions.begin() + 1, all_regions.end());
  auto add = [&](std::string id, std::string section, std::string text, std::string measured_as,
                 Rule rule, std::vector<std::string> regions, std::vector<std::string> seqs,
                 std::vector<std::string> maps, Measure m, bool bootstrap = true) {
    out.push_back({std::move(id), std::move(section), std::move(text), std::move(measured_as), rule,
                   std::move(regions), std::move(seqs), std::move(maps), std::move(m), bootstrap});
  };
  const std::string n_text = std::to_string(spp);
  // Fig. 7's MSEs: area 0.0043451, Gamito 3.7234e-5, parallel 1.2195e-5, radial 3.1013e-6,
  // ld-radial 1.2655e-5; the claims are their ratios to radial.
  const std::vector<std::pair<std::string, double>> fig7 = {{"parallel", 1.2195e-5 / 3.1013e-6},
                                                            {"ld-radial", 1.2655e-5 / 3.1013e-6},
                                                            {"gamito", 3.7234e-5 / 3.1013e-6},
                                                            {"area", 0.0043451 / 3.1013e-6}};
  for (const std::string& q : c.sequences) {
    add("fig7.order." + q, "fig7",
        "Fig. 7: radial < parallel ~ ld-radial < Gamito << area (" + q + ")",
        "violated pairwise inequalities of the MSEs at N = " + n_text + " (of 5)",
        {RuleKind::at_most, 0.0}, all_regions, {q},
        {"radial", "parallel", "ld-radial", "gamito", "area"}, ordering_violations(q, spp));
    for (const auto& [map, ratio] : fig7) {
      char text[160];
      std::snprintf(text, sizeof text, "Fig. 7: MSE(%s) / MSE(radial) = %.3g (%s)", map.c_str(),
                    ratio, q.c_str());
      add("fig7." + map + "." + q, "fig7", text, "MSE(" + map + ") / MSE(radial) at N = " + n_text,
          {RuleKind::factor, ratio}, all_regions, {q}, {map, "radial"},
          mse_ratio(map, "radial", q, spp));
    }
  }
  std::vector<std::string> uniform;
  for (ellipse::MapKind k : c.maps)
    if (ellipse::map_is_uniform(k) && ellipse::map_copies(k) == 1)
      uniform.emplace_back(ellipse::map_name(k));
  if (std::find(c.sequences.begin(), c.sequences.end(), "random") != c.sequences.end() &&
      uniform.size() >= 2) {
    std::string list;
    for (const std::string& m : uniform)
      list += (list.empty() ? "" : ", ") + m;
    add("iid.same-variance", "iid",
        "With iid (random) input every uniform solid-angle map has the same variance per sample "
        "(" +
            list + ")",
        "max / min image MSE over those maps (the regions' 16 points share each seed's "
        "points, too few randomizations to resolve 10%)",
        {RuleKind::about_equal, 1.0}, {"image"}, {"random"}, uniform,
        mse_spread(uniform, "random"));
  }
  for (const auto& [map, iters] : {std::pair{"parallel", 3.0}, std::pair{"radial", 4.0}}) {
    const auto m = map_index(r, map);
    const Opt value = m ? Opt(static_cast<double>(r.newton[*m].max)) : std::nullopt;
    add(std::string("newton.") + map, "newton",
        std::string("Newton-Raphson takes 1-") + (iters == 3.0 ? "3" : "4") + " iterations (" +
            map + ")",
        "largest iteration count of a root solve over every image sample",
        {RuleKind::at_most, iters}, {"image"}, {}, {map}, measures::constant(value), false);
  }
  // "Area sampling" is measured as a renderer writes it: the baseline of bench_maps
  // (ellipse::LeanAreaSampler), timed in the same run by the same rules.
  auto cost_ratio = [&](const std::string& map) -> Opt {
    const auto m = map_index(r, map);
    if (!m || r.cost.size() <= *m) return std::nullopt;
    return r.cost[*m].ratio_to_baseline;
  };
  add("cost.tabulated", "cost", "Tabulated is almost as fast as area sampling",
      "time per sample at " + n_text +
          " spp (set-up included) / the renderer's area sample's; \"almost\": <= 1.25",
      {RuleKind::at_most, 1.25}, {"image"}, {}, {"tabulated"},
      measures::constant(cost_ratio("tabulated")), false);
  for (const char* map : {"parallel", "radial", "ld-radial"})
    add(std::string("cost.") + map, "cost",
        std::string("The fully numerical maps are up to 10x slower than area sampling (") + map +
            ")",
        "time per sample at " + n_text + " spp (set-up included) / the renderer's area sample's",
        {RuleKind::at_most, 10.0}, {"image"}, {}, {map}, measures::constant(cost_ratio(map)),
        false);
  for (const std::string q : {"pmj02", "sobol-owen"})
    for (const std::string base : {"radial", "ld-radial"})
      add("radial4." + base + "." + q, "radial4",
          "radial4 lowers the error of " + base + " as polar4 does polar's (" + q + ")",
          "RMS(radial4) / RMS(" + base + ") at N = 256; the memo's \"helps\" rule",
          {RuleKind::lower, 0.8}, region_names, {q}, {"radial4", base},
          measures::ratio_at("radial4", q, base, q, 256));
  return out;
}

std::vector<ClaimOutcome> evaluate_guillen_claims(const std::vector<Claim>& claims,
                                                  const VarianceResult& r) {
  std::vector<ClaimOutcome> out;
  for (ClaimOutcome& o : evaluate_claims(claims, r.image, make_image_bootstrap(r.config)))
    if (o.region == "image") out.push_back(std::move(o));
  for (ClaimOutcome& o : evaluate_claims(claims, r.curves, make_curve_bootstrap(r.config)))
    if (o.region != "image") out.push_back(std::move(o));
  return out;
}

}  // namespace disklab::study
