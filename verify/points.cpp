// `disklab points`: a square sequence, optionally mapped to the disk by a strategy, as CSV or
// as a picture like the memo's Figs. 2 and 3 (Christensen 2018).
//
//   disklab points --strategy NAME --sequence NAME --seed S --count N [--format csv|png] [--out F]
//     CSV: index,u,v,x,y,weight. `index` is the disk-sample number s = 0..N-1; (u, v) is the
//     square point it used (polar4/concentric4: point s div 4, rotated by (s mod 4) * 90
//     degrees; rejection: the accepted point, rejected ones are skipped and counted on stderr);
//     weight is the estimator weight (pad-zero 4/pi or 0, else 1).
//   Without --strategy: the square points themselves, CSV index,u,v (Fig. 2).
//
//   disklab points --map NAME --center C --normal N --radius R --point O --sequence ... --count N
//     Spherical-ellipse maps (Guillén et al. 2017; ellipse/any_map.h). CSV index,u,v,x,y,z,pdf:
//     the unit direction from O and its solid-angle pdf. One row per candidate: gamito and
//     tabulated keep a rejected candidate as a row with pdf 0 (zero weight), so the mean of
//     f/pdf over all rows (0 where pdf = 0) is an unbiased estimate of the integral. radial4
//     rows s = 4i..4i+3 are the four reflections of square point i. PNG: the paper's Fig. 1
//     layout, the hit points on the disk seen from its lit side (top) and the directions in the
//     ellipse frame projected along z_e (bottom).
//
// Options live in PointsState and each output mode is one function.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "command.h"
#include "common/args.h"
#include "common/ellipse_cli.h"
#include "common/output.h"
#include "common/points_ellipse.h"
#include "disklab/disk/strategy.h"
#include "disklab/sequence/sequence.h"

namespace disklab::cli {
namespace {
namespace fs = std::filesystem;

// Large enough for any picture or study, small enough to keep a CSV on disk sane.
constexpr int64_t kMaxCount = 10'000'000;
constexpr int64_t kMaxCountPng = 1'000'000;
// Strata images are drawn when the square points form a small n x n grid's worth.
constexpr int kMaxStrataGrid = 32;
constexpr int kStrataLineSegments = 96;

struct Row {
  uint32_t index;
  Point2 uv, xy;
  double weight;
};

// Streams the rows of `s` into `emit(const Row&)` without storing them (a CSV of millions of
// points needs no more memory than one row). Returns the square points consumed.
template <class Emit>
uint32_t for_each_row(const PointsState& s, const sequence::Sequence& seq, Emit&& emit) {
  const auto n = static_cast<uint32_t>(s.count);
  if (s.strategy.empty()) {
    for (uint32_t i = 0; i < n; ++i)
      emit(Row{i, seq.at(i), {}, 1.0});
    return n;
  }
  disk::DiskSampler<sequence::Sequence> sampler(*disk::parse_strategy(s.strategy), seq);
  for (uint32_t i = 0; i < n; ++i) {
    const disk::DiskSample d = sampler.next();
    emit(Row{i, d.uv, d.point, d.weight});
  }
  return sampler.cursor();
}

// Writes the CSV to `out` in chunks; returns the square points consumed.
uint32_t write_csv(const PointsState& s, const sequence::Sequence& seq, std::ostream& out) {
  const bool mapped = !s.strategy.empty();
  ChunkedOutput csv(out);
  std::string& buf = csv.text();
  buf = mapped ? "index,u,v,x,y,weight\n" : "index,u,v\n";
  return for_each_row(s, seq, [&](const Row& r) {
    buf += std::to_string(r.index) + "," + fmt17(r.uv.x) + "," + fmt17(r.uv.y);
    if (mapped) buf += "," + fmt17(r.xy.x) + "," + fmt17(r.xy.y) + "," + fmt17(r.weight);
    buf += "\n";
    csv.row_done();
  });
}

// Images of the grid lines u = i/n and v = j/n under the strategy (polylines "line,x,y"), when
// the square points used fill an n x n grid exactly: the strata of the memo's Fig. 3.
std::string strata_lines(disk::Strategy strategy, uint32_t square_points) {
  const int n = static_cast<int>(std::lround(std::sqrt(double(square_points))));
  if (n < 2 || n > kMaxStrataGrid || uint32_t(n * n) != square_points) return {};
  std::ostringstream out;
  out << "line,x,y\n";
  int line = 0;
  auto emit = [&](auto point_of_t) {
    const std::vector<int> copies = disk::copies_per_square_point(strategy) == 4
                                        ? std::vector<int>{0, 1, 2, 3}
                                        : std::vector<int>{0};
    for (int k : copies) {
      for (int t = 0; t <= kStrataLineSegments; ++t) {
        Point2 uv = point_of_t(double(t) / kStrataLineSegments);
        Point2 p;
        switch (strategy) {
          case disk::Strategy::polar:
            p = disk::sample_polar(uv);
            break;
          case disk::Strategy::concentric:
            p = disk::sample_concentric(uv);
            break;
          case disk::Strategy::polar4:
            p = disk::rotate_quarter_turns(disk::sample_polar_quarter(uv), k);
            break;
          case disk::Strategy::concentric4:
            p = disk::rotate_quarter_turns(disk::sample_concentric_quarter(uv), k);
            break;
          default:
            p = disk::square_to_centered(uv);
            break;
        }
        out << line << ',' << fmt17(p.x) << ',' << fmt17(p.y) << '\n';
      }
      ++line;
    }
  };
  for (int i = 0; i <= n; ++i) {
    emit([&](double t) { return Point2{double(i) / n, t}; });
    emit([&](double t) { return Point2{t, double(i) / n}; });
  }
  return out.str();
}

std::string plot_title(const PointsState& s, uint32_t square_points) {
  std::string t = s.strategy.empty() ? "square" : s.strategy;
  t +=
      ": " + std::to_string(s.count) + " points, " + s.sequence + " seed " + std::to_string(s.seed);
  if (!s.strategy.empty() && int64_t(square_points) != s.count)
    t += " (" + std::to_string(square_points) + " square points)";
  return t;
}

// Returns the square points consumed.
uint32_t write_png(const PointsState& s, const sequence::Sequence& seq, const fs::path& png) {
  // The plot script reads the rows from temporary CSVs (removed whatever happens).
  TempFiles temp;
  const fs::path csv = temp.add("points"), lines = temp.add("strata");
  uint32_t square_points = 0;
  {
    std::ofstream f(csv);
    square_points = write_csv(s, seq, f);
    if (!f) throw std::runtime_error("cannot write temporary " + csv.string());
  }
  std::vector<std::string> args = {"--csv", csv.string(), "--title", plot_title(s, square_points)};
  if (!s.strategy.empty()) {
    const disk::Strategy strategy = *disk::parse_strategy(s.strategy);
    args.insert(args.end(), {"--mode", "disk"});
    if (strategy == disk::Strategy::pad_zero || strategy == disk::Strategy::rejection)
      args.insert(args.end(), {"--square-outline"});
    const std::string strata = strata_lines(strategy, square_points);
    if (!strata.empty()) {
      std::ofstream f(lines);
      f << strata;
      args.insert(args.end(), {"--lines", lines.string()});
    }
  } else {
    args.insert(args.end(), {"--mode", "square"});
  }
  run_plot("points", args, png);
  return square_points;
}

void validate(PointsState& s) {
  s.seed = parse_u64(s.seed_text, "--seed");
  check_ellipse_exclusive(s.ellipse, s.strategy);
  if (!s.ellipse.map.empty()) make_ellipse_map(s.ellipse);  // validates the scene
  if (!s.strategy.empty()) require_one_of(s.strategy, disk::strategy_names(), "--strategy");
  require_one_of(s.sequence, sequence::sequence_names(), "--sequence");
  require_one_of(s.format, {"csv", "png"}, "--format");
  if (s.count <= 0) throw UsageError("--count: " + std::to_string(s.count) + " must be positive");
  const int64_t cap = s.format == "png" ? kMaxCountPng : kMaxCount;
  if (s.count > cap)
    throw UsageError("--count: " + std::to_string(s.count) + " is above the limit " +
                     std::to_string(cap) + " for --format " + s.format);
  if (s.format == "png" && s.out.empty()) throw UsageError("--format png needs --out FILE.png");
  if (!s.out.empty()) check_out_file(s.out);
}

void produce(const PointsState& s, const std::string& out) {
  if (!s.ellipse.map.empty()) return produce_ellipse(s, out);
  const auto seq = sequence::make_sequence(s.sequence, s.seed);
  uint32_t used = 0;
  if (s.format == "png") {
    used = write_png(s, *seq, out);
  } else if (out.empty()) {
    used = write_csv(s, *seq, std::cout);
    if (!std::cout) throw std::runtime_error("writing to stdout failed");
  } else {
    AtomicFile file(out);
    used = write_csv(s, *seq, file.stream());
    file.commit();
  }
  if (s.strategy == "rejection" && std::getenv("DISKLAB_QUIET") == nullptr)
    std::fprintf(stderr, "points: rejection used %u square points for %lld disk samples\n", used,
                 static_cast<long long>(s.count));
}

int run_points(PointsState s) {
  validate(s);
  produce(s, s.out);
  return 0;
}

// `disklab report`: the six strategies with 256 random points each, as PNG and CSV.
int report_points(const ReportOptions& options) {
  for (const auto& name : disk::strategy_names()) {
    PointsState s;
    s.strategy = name;
    s.sequence = "random";
    s.seed = 1;
    s.count = 256;
    s.format = "csv";
    produce(s, (options.dir / ("points_" + name + ".csv")).string());
    s.format = "png";
    produce(s, (options.dir / ("points_" + name + ".png")).string());
  }
  report_points_ellipse(options);
  return 0;
}

std::function<int()> setup_points(Options& sub) {
  auto state = std::make_shared<PointsState>();
  std::string strategies, sequences;
  for (const auto& n : disk::strategy_names())
    strategies += " " + n;
  for (const auto& n : sequence::sequence_names())
    sequences += " " + n;
  sub.add_option("--strategy", state->strategy,
                 "Square-to-disk strategy (omit for the square points):" + strategies);
  sub.add_option("--sequence", state->sequence, "Square sequence:" + sequences)
      ->capture_default_str();
  sub.add_option("--seed", state->seed_text, "Randomization seed (unsigned 64-bit)")
      ->capture_default_str();
  sub.add_option("--count", state->count, "Number of points (disk samples with --strategy)")
      ->capture_default_str();
  sub.add_option("--format", state->format, "csv or png")->capture_default_str();
  sub.add_option("--out", state->out, "Output file (default: CSV on stdout)");
  add_ellipse_options(sub, state->ellipse);
  sub.footer(
      "CSV columns: index,u,v,x,y,weight with --strategy (weight: pad-zero 4/pi or 0, else 1;\n"
      "polar4/concentric4 reuse square point index/4 rotated by (index mod 4) * 90 degrees;\n"
      "rejection skips rejected square points and reports how many it used on stderr);\n"
      "index,u,v without. PNG: the disk like the memo's Fig. 3 (strata images when the square\n"
      "points fill an n x n grid, n <= 32), or the unit square like Fig. 2.\n"
      "With --map (spherical-ellipse maps, exclusive with --strategy): CSV index,u,v,x,y,z,pdf,\n"
      "the unit direction from --point and its pdf in solid angle; one row per square point\n"
      "(radial4: rows 4i..4i+3 are the four reflections of square point i). gamito and\n"
      "tabulated keep a REJECTED candidate as a row with pdf 0 and its (missing) direction: the\n"
      "mean over all rows of f/pdf (0 where pdf = 0) is unbiased; accepted rows carry the\n"
      "proposal pdf. PNG: like Guillen et al. 2017 Fig. 1, hit points on the disk (top) and\n"
      "directions in the ellipse frame projected along its axis (bottom), coloured by stratum.\n"
      "Examples:\n"
      "  disklab points --strategy polar4 --sequence random --seed 7 --count 64\n"
      "  disklab points --strategy concentric --count 256 --format png --out concentric.png\n"
      "  disklab points --sequence random --count 500 --format png --out square.png\n"
      "  disklab points --map radial --center 0,0,1 --normal 0,0,-1 --radius 1 --point 0.5,0,0\n"
      "    --sequence sobol-owen --count 256 --format png --out radial.png\n"
      "  disklab points --map gamito --center 1,0.5,2 --normal 0.3,-0.2,-1 --radius 1\n"
      "    --point 0,0,0 --count 16");
  return [state] { return run_points(*state); };
}

const Registrar kPoints{Command{"points", "Sample points on the square or the disk (CSV or PNG)",
                                setup_points, report_points}};

}  // namespace
}  // namespace disklab::cli
