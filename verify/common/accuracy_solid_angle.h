#pragma once
// Accuracy of the disk's solid angle against the committed 50-digit table
// (reference/solid_angle.csv: boundary quadrature in cpp_bin_float_50, no ellipse formula),
// formula by formula, binned by decade of distance: the production (cancellation-free) form,
// Guillén et al. 2017 eq. (19) and eq. (11) as printed, the on-axis closed form (on-axis rows)
// and the double-precision boundary quadrature.
#include <filesystem>
#include <string>

namespace disklab::cli {

// The target for the production form: relative error <= 1e-14 (~45 ulp) at every
// configuration of the table.
inline constexpr double kSolidAngleTarget = 1e-14;

struct SolidAngleAccuracy {
  std::string markdown;       // a Markdown section: per-decade table, verdict, degenerate rows
  std::string rows_csv;       // solid_angle_accuracy_rows.csv: one line per table row and formula
  std::string decades_csv;    // solid_angle_accuracy.csv: max relative error per decade
  double production_max = 0;  // worst relative error of the production form over all rows
  bool meets_target = false;  // production_max <= kSolidAngleTarget and degenerate rows exact 0
};

// Evaluates every formula on every row of `reference_dir`/solid_angle.csv (nothing is written).
// Throws std::runtime_error if the table is missing or malformed.
SolidAngleAccuracy solid_angle_accuracy(const std::filesystem::path& reference_dir);

}  // namespace disklab::cli
