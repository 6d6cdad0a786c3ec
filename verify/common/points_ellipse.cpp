#include "common/points_ellipse.h"

#include <array>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <vector>

#include "common/output.h"
#include "disklab/sequence/sequence.h"

namespace disklab::cli {
namespace {
namespace fs = std::filesystem;

// Rows between progress ticks, and the count from which progress is shown at all.
constexpr uint32_t kProgressChunk = 1u << 16;
constexpr int64_t kProgressMinCount = 1'000'000;

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
  ChunkedOutput csv(out);
  std::string& buf = csv.text();
  buf = plot_columns ? "index,u,v,x,y,z,pdf,dx,dy,lx,ly\n" : "index,u,v,x,y,z,pdf\n";
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
    csv.row_done();
  });
  csv.flush();
  return used;
}

// One panel of the ellipse picture: a map, its scene and points.
struct EllipsePanel {
  std::string label;
  const ellipse::AnyMap* map;
};

// The paper's Fig. 1 layout: one column per map, the disk on top, the directions below.
uint32_t write_ellipse_png(const PointsState& s, const std::vector<EllipsePanel>& panels,
                           const sequence::Sequence& seq, const fs::path& png,
                           const std::string& title) {
  TempFiles temp;
  std::vector<std::string> args = {"--title", title};
  uint32_t used = 0;
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const fs::path csv = temp.add("ellipse");
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

}  // namespace

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
    produce_ellipse(s, (options.dir / ("points_ellipse_" + name + ".csv")).string());
  }
  std::vector<EllipsePanel> panels;
  for (std::size_t i = 0; i < names.size(); ++i)
    panels.push_back({names[i], &maps[i]});
  const auto seq = sequence::make_sequence(s.sequence, s.seed, static_cast<uint32_t>(s.count));
  write_ellipse_png(s, panels, *seq, options.dir / "points_ellipse.png",
                    std::to_string(s.count) + " samples per map, " + s.sequence + "; " +
                        describe_scene(s.ellipse));
}

}  // namespace disklab::cli
