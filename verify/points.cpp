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
// Rows between progress ticks, and the count from which progress is shown at all.
constexpr uint32_t kProgressChunk = 1u << 16;
constexpr int64_t kProgressMinCount = 1'000'000;

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
  std::string buf = mapped ? "index,u,v,x,y,weight\n" : "index,u,v\n";
  const uint32_t used = for_each_row(s, seq, [&](const Row& r) {
    buf += std::to_string(r.index) + "," + fmt17(r.uv.x) + "," + fmt17(r.uv.y);
    if (mapped) buf += "," + fmt17(r.xy.x) + "," + fmt17(r.xy.y) + "," + fmt17(r.weight);
    buf += "\n";
    if (buf.size() > (1u << 16)) {
      out << buf;
      buf.clear();
    }
  });
  out << buf;
  out.flush();
  return used;
}

// One spherical-ellipse row: sample number, square point used, and the sample (pdf 0 when it
// is "no sample": a rejected candidate).
struct EllipseRow {
  uint32_t index;
  Point2 uv;
  const ellipse::EllipseSample* s;
};

// Streams the rows of the ellipse map `m` into `emit`; returns the square points consumed.
template <class Emit>
uint32_t for_each_ellipse_row(const PointsState& s, const ellipse::AnyMap& m,
                              const sequence::Sequence& seq, Emit&& emit) {
  const auto n = static_cast<uint32_t>(s.count);
  std::optional<Progress> progress;
  if (s.count >= kProgressMinCount) progress.emplace("points " + s.ellipse.map, n);
  std::array<ellipse::EllipseSample, 4> out;
  uint32_t square = 0, i = 0;
  while (i < n) {
    const Point2 u = seq.at(square++);
    const int copies = m.sample_copies(u, out);
    for (int k = 0; k < copies && i < n; ++k, ++i) {
      if (!out[k].valid) out[k].pdf = 0.0;
      emit(EllipseRow{i, u, &out[k]});
      if (progress && (i + 1) % kProgressChunk == 0) progress->tick(kProgressChunk);
    }
  }
  if (progress) {
    progress->tick(n % kProgressChunk);
    progress->finish();
  }
  return square;
}

// CSV index,u,v,x,y,z,pdf; with `plot_columns` also dx,dy (hit point in the disk's frame
// (x_e, n x x_e), in radii) and lx,ly (the direction's x_e, y_e parts divided by a = sin alpha).
uint32_t write_ellipse_csv(const PointsState& s, const ellipse::AnyMap& m,
                           const sequence::Sequence& seq, std::ostream& out,
                           bool plot_columns = false) {
  std::string buf = plot_columns ? "index,u,v,x,y,z,pdf,dx,dy,lx,ly\n" : "index,u,v,x,y,z,pdf\n";
  const ellipse::MapGeometry& g = m.geometry();
  const Vec3 e1 = g.frame.x, e2 = g.normal.cross(g.frame.x);
  const uint32_t used = for_each_ellipse_row(s, m, seq, [&](const EllipseRow& r) {
    const ellipse::EllipseSample& e = *r.s;
    buf += std::to_string(r.index) + "," + fmt17(r.uv.x) + "," + fmt17(r.uv.y) + "," +
           fmt17(e.direction.x()) + "," + fmt17(e.direction.y()) + "," + fmt17(e.direction.z()) +
           "," + fmt17(e.pdf);
    if (plot_columns) {
      const Vec3 off = e.point - g.center;
      buf += "," + fmt17(off.dot(e1) / g.radius) + "," + fmt17(off.dot(e2) / g.radius) + "," +
             fmt17(e.local.x() / g.a) + "," + fmt17(e.local.y() / g.a);
    }
    buf += "\n";
    if (buf.size() > (1u << 16)) {
      out << buf;
      buf.clear();
    }
  });
  out << buf;
  out.flush();
  return used;
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
  // The plot script reads the rows from a temporary CSV (removed whatever happens).
  const fs::path tmp = fs::temp_directory_path();
  const std::string tag = std::to_string(::getpid());
  const fs::path csv = tmp / ("disklab-points-" + tag + ".csv");
  const fs::path lines = tmp / ("disklab-strata-" + tag + ".csv");
  struct Cleanup {
    std::vector<fs::path> files;
    ~Cleanup() {
      std::error_code ec;
      for (const auto& f : files)
        fs::remove(f, ec);
    }
  } cleanup{{csv, lines}};
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

// Temporary files removed whatever happens.
struct TempFiles {
  std::vector<fs::path> files;
  ~TempFiles() {
    std::error_code ec;
    for (const auto& f : files)
      fs::remove(f, ec);
  }
};

// One panel of the ellipse picture: a map, its scene and points.
struct EllipsePanel {
  std::string label;
  const ellipse::AnyMap* map;
};

// The paper's Fig. 1 layout: one column per map, the disk on top, the directions below.
uint32_t write_ellipse_png(const PointsState& s, const std::vector<EllipsePanel>& panels,
                           const sequence::Sequence& seq, const fs::path& png,
                           const std::string& title) {
  const fs::path tmp = fs::temp_directory_path();
  const std::string tag = std::to_string(::getpid());
  TempFiles cleanup;
  std::vector<std::string> args = {"--title", title};
  uint32_t used = 0;
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const fs::path csv = tmp / ("disklab-ellipse-" + tag + "-" + std::to_string(p) + ".csv");
    cleanup.files.push_back(csv);
    {
      std::ofstream f(csv);
      used = write_ellipse_csv(s, *panels[p].map, seq, f, true);
      if (!f) throw std::runtime_error("cannot write temporary " + csv.string());
    }
    const ellipse::MapGeometry& g = panels[p].map->geometry();
    args.insert(args.end(), {"--panel", csv.string(), panels[p].label, fmt17(g.a_t), fmt17(g.b_t)});
  }
  run_plot("points_ellipse", args, png);
  return used;
}

std::string ellipse_title(const PointsState& s) {
  return s.ellipse.map + ": " + std::to_string(s.count) + " samples, " + s.sequence + " seed " +
         std::to_string(s.seed) + "; " + describe_scene(s.ellipse);
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

// Writes the CSV or PNG for `s` to `out` (atomically), or the CSV to stdout when out is empty.
void produce_ellipse(const PointsState& s, const std::string& out) {
  const ellipse::AnyMap m = make_ellipse_map(s.ellipse);
  const auto seq = sequence::make_sequence(s.sequence, s.seed,
                                           static_cast<uint32_t>(std::max<int64_t>(s.count, 1)));
  if (s.format == "png") {
    write_ellipse_png(s, {{s.ellipse.map, &m}}, *seq, out, ellipse_title(s));
  } else if (out.empty()) {
    write_ellipse_csv(s, m, *seq, std::cout);
    if (!std::cout) throw std::runtime_error("writing to stdout failed");
  } else {
    AtomicFile file(out);
    write_ellipse_csv(s, m, *seq, file.stream());
    file.commit();
  }
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

// The Fig. 1-like picture: several maps at one configuration (a tilted disk seen off-axis, the
// tilted-mid scene of the ellipse suites), sobol-owen points, plus each map's CSV.
void report_points_ellipse(const ReportOptions& options) {
  PointsState s;
  s.sequence = "sobol-owen";
  s.seed = 1;
  s.count = options.quick ? 128 : 512;
  s.ellipse.center = "1,0.5,2";
  s.ellipse.normal = "0.3,-0.2,-1";
  s.ellipse.radius = "1";
  s.ellipse.point = "0,0,0";
  const std::vector<std::string> names = {"area",   "gamito",    "parallel",
                                          "radial", "ld-radial", "tabulated"};
  std::vector<ellipse::AnyMap> maps;
  for (const auto& name : names) {
    s.ellipse.map = name;
    maps.push_back(make_ellipse_map(s.ellipse));
    s.format = "csv";
    produce(s, (options.dir / ("points_ellipse_" + name + ".csv")).string());
  }
  std::vector<EllipsePanel> panels;
  for (std::size_t i = 0; i < names.size(); ++i)
    panels.push_back({names[i], &maps[i]});
  const auto seq = sequence::make_sequence(s.sequence, s.seed, static_cast<uint32_t>(s.count));
  write_ellipse_png(s, panels, *seq, options.dir / "points_ellipse.png",
                    std::to_string(s.count) + " samples per map, " + s.sequence + "; " +
                        describe_scene(s.ellipse));
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

std::function<int()> setup_points(CLI::App& sub) {
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
