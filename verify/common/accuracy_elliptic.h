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

// Evaluates every implementation on every row of the tables in `reference_dir`, writes
// `dir`/elliptic_accuracy.csv (one row per function x implementation: rows, max ulp, RMS ulp,
// worst input) atomically, and returns a Markdown section with the same table.
// Throws std::runtime_error if a table is missing or malformed.
std::string write_elliptic_accuracy(
    const std::filesystem::path& dir,
    const std::filesystem::path& reference_dir = default_reference_dir());

}  // namespace disklab::cli
