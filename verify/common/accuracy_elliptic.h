#pragma once
// Accuracy of the elliptic integrals against the committed 50-digit reference tables
// (reference/elliptic_f.csv, reference/elliptic_pi.csv): own F and Pi, Boost.Math with the
// double policy (promote_double<false>) and Boost.Math's default policy (long double inside).
#include <filesystem>
#include <string>

namespace disklab::cli {

// The folder holding the committed reference tables: $DISKLAB_REFERENCE_DIR if set, else the
// source tree's reference/ (known at build time).
std::filesystem::path default_reference_dir();

struct EllipticAccuracy {
  std::string markdown;  // a Markdown section with the table
  std::string csv;       // elliptic_accuracy.csv: one row per function x implementation x subset
                         // (rows, failures, max ulp, RMS ulp, worst input)
};

// Evaluates every implementation on every row of the tables in `reference_dir` (nothing is
// written). Throws std::runtime_error if a table is missing or malformed.
EllipticAccuracy elliptic_accuracy(
    const std::filesystem::path& reference_dir = default_reference_dir());

}  // namespace disklab::cli
