#pragma once
// Output pieces the studies share: a curve table's rows and fits as CSV and JSON, claims as
// JSON, and number cells for the markdown.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

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

// "+1.23 ± 0.04" ("-" when there is no slope).
std::string slope_cell(const study::CurveFit& f);

}  // namespace disklab::cli
