#pragma once
// `disklab points`, its options, and the spherical-ellipse half of the command (--map): rows of
// directions and pdfs as CSV, and the picture like Guillén et al. 2017 Fig. 1. The square and
// disk half is in verify/points.cpp.
#include <cstdint>
#include <string>

#include "command.h"
#include "common/ellipse_cli.h"

namespace disklab::cli {

// The options of `disklab points`.
struct PointsState {
  std::string strategy;  // empty: square points
  std::string sequence = "random";
  std::string seed_text = "1";  // parsed strictly: CLI11 would wrap "-1" to 2^64 - 1
  uint64_t seed = 1;
  int64_t count = 256;
  std::string format = "csv";
  std::string out;         // empty: stdout (CSV only)
  EllipseOptions ellipse;  // --map and its scene (exclusive with --strategy)
};

// Writes the CSV or PNG of the ellipse map of `s` to `out` (atomically), or the CSV to stdout
// when out is empty.
void produce_ellipse(const PointsState& s, const std::string& out);

// The report's Fig. 1-like picture of several maps, with each map's CSV.
void report_points_ellipse(const ReportOptions& options);

}  // namespace disklab::cli
