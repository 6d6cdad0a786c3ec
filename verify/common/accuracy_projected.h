#pragma once
// Accuracy of the projected solid angle P of ellipse/projected.h against the committed 50-digit
// table (reference/projected_P.csv: chord quadrature in cpp_bin_float_50, no ellipse formula),
// split by the map's form: unclipped (P = pi a b n_z) and clipped (the disk straddles the
// receiver's horizon; the reduced boundary form, whose pieces are O(P) for small ellipses).
#include <filesystem>
#include <string>

namespace disklab::cli {

// Issue 19's target: relative error <= 1e-14 against the reference at every configuration.
inline constexpr double kProjectedTarget = 1e-14;

struct ProjectedAccuracy {
  std::string markdown;      // a Markdown section: per-form table, rows above the target
  std::string summary_csv;   // projected_accuracy.csv: one line per form and in total
  std::string rows_csv;      // projected_accuracy_rows.csv: one line per table row
  double unclipped_max = 0;  // worst relative error of the unclipped form
  double clipped_max = 0;    // worst relative error of the clipped form (or lost: inf)
  int rows_over_target = 0;  // rows above kProjectedTarget
  // Every row within the target, P = 0 exact where it is 0.
  bool within_bounds = false;
};

// Evaluates ProjectedMap on every row of `reference_dir`/projected_P.csv (nothing is written).
// Throws std::runtime_error if the table is missing or malformed.
ProjectedAccuracy projected_accuracy(const std::filesystem::path& reference_dir);

}  // namespace disklab::cli
