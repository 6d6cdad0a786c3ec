// `disklab sequences`: L2-star discrepancy (Warnock's formula) of every square sequence of the
// registry (Christensen 2018, Sec. 2), mean over seeds, next to the exact RMS for random points,
// sqrt(5 / (36 N)).
//
//   disklab sequences --count N [--seeds K] [--seed S] [--sequences a,b,..] [--format md|csv|json]
//                     [--out FILE]
//
// The report part writes that table (CSV + Markdown), a grid of the first 500 points of each
// sequence, like the memo's Fig. 2, and the radial power spectrum of random, art and pmj02
// (sequences_spectrum.csv/.png; `--spectrum PNG` draws it for the chosen --sequences instead of
// the table).
#include <unistd.h>

#include <charconv>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "command.h"
#include "common/args.h"
#include "common/output.h"
#include "disklab/sequence/discrepancy.h"
#include "disklab/sequence/sequence.h"

namespace disklab::cli {
namespace {
namespace fs = std::filesystem;

// Warnock's formula is O(N^2): 2^16 points is ~2e9 pair terms per seed and sequence (seconds).
constexpr int64_t kMaxCount = 1 << 16;
constexpr int64_t kMaxSeeds = 1000;
constexpr int kFigurePoints = 500;  // the memo's Fig. 2
// Radial power spectrum: integer frequencies up to kSpectrumReach sqrt(N) per axis (beyond the
// blue-noise peak near sqrt(N), where every spectrum has flattened to 1), and the sequences the
// report shows (ART's spectrum, like Ahmed et al. 2017, next to random's and pmj02's).
constexpr double kSpectrumReach = 3.0;
const char* const kSpectrumSequences = "random,art,pmj02";

struct SequencesState {
  int64_t count = 1024;
  int64_t seeds = 8;
  std::string seed_text = "1";  // first seed; parsed strictly (CLI11 would wrap "-1")
  uint64_t seed = 1;
  std::string only;  // comma-separated subset, empty: all
  std::string format = "md";
  std::string out;
  std::string spectrum;  // PNG of the radial power spectrum instead of the table
};

struct Row {
  std::string name;
  double mean = 0.0, std_error = 0.0, min = 0.0, max = 0.0;
};

// Mean, standard error, min and max of the discrepancy over seeds seed .. seed + seeds - 1.
// Parallel over (sequence, seed) pairs; each builds its own instance (thread-safe by contract).
std::vector<Row> compute(const std::vector<std::string>& names, uint32_t count, int seeds,
                         uint64_t first_seed) {
  const int jobs = static_cast<int>(names.size()) * seeds;
  std::vector<double> d(jobs, 0.0);
  Progress progress("sequences", static_cast<uint64_t>(jobs));
#pragma omp parallel for schedule(dynamic, 1)
  for (int job = 0; job < jobs; ++job) {
    const auto seq = sequence::make_sequence(names[job / seeds], first_seed + job % seeds, count);
    std::vector<Point2> points(count);
    for (uint32_t i = 0; i < count; ++i)
      points[i] = seq->at(i);
    d[job] = sequence::l2_star_discrepancy(points);
    progress.tick();
  }
  progress.finish();
  std::vector<Row> rows;
  for (std::size_t k = 0; k < names.size(); ++k) {
    Row r{names[k]};
    double sum = 0.0, sum2 = 0.0;
    r.min = d[k * seeds];
    r.max = d[k * seeds];
    for (int s = 0; s < seeds; ++s) {
      const double v = d[k * seeds + s];
      sum += v;
      sum2 += v * v;
      r.min = std::min(r.min, v);
      r.max = std::max(r.max, v);
    }
    r.mean = sum / seeds;
    r.std_error =
        seeds > 1 ? std::sqrt(std::max(0.0, (sum2 - sum * r.mean) / (seeds - 1)) / seeds) : 0.0;
    rows.push_back(r);
  }
  return rows;
}

// Averaged periodogram P(f) = |sum_j exp(-2 pi i f.x_j)|^2 / N over integer frequencies f, mean
// over seeds, then over rings round(|f|) = r (r >= 1; P = 1 on average for random points at every
// f != 0). P(-f) = P(f), so the half plane f_y >= 0 suffices. Parallel over (sequence, seed).
struct Spectrum {
  std::string name;
  std::vector<double> power;  // power[r], r = 0 .. reach (r = 0 unused)
};
std::vector<Spectrum> radial_spectra(const std::vector<std::string>& names, uint32_t count,
                                     int seeds, uint64_t first_seed) {
  const int reach = static_cast<int>(std::ceil(kSpectrumReach * std::sqrt(double(count))));
  const int width = 2 * reach + 1;
  const int jobs = static_cast<int>(names.size()) * seeds;
  std::vector<std::vector<double>> ring(static_cast<std::size_t>(jobs));
  std::vector<double> ring_count(static_cast<std::size_t>(reach) + 1, 0.0);
  for (int fy = 0; fy <= reach; ++fy)
    for (int fx = -reach; fx <= reach; ++fx) {
      const auto r = static_cast<int>(std::lround(std::hypot(fx, fy)));
      if ((fy > 0 || fx > 0) && r <= reach) ring_count[static_cast<std::size_t>(r)] += 1.0;
    }
  Progress progress("spectrum", static_cast<uint64_t>(jobs));
#pragma omp parallel for schedule(dynamic, 1)
  for (int job = 0; job < jobs; ++job) {
    const auto seq = sequence::make_sequence(names[job / seeds], first_seed + job % seeds, count);
    std::vector<std::complex<double>> sum(static_cast<std::size_t>(width) * (reach + 1));
    std::vector<std::complex<double>> ex(static_cast<std::size_t>(width)),
        ey(static_cast<std::size_t>(reach) + 1);
    const double two_pi = 6.283185307179586476925;
    for (uint32_t i = 0; i < count; ++i) {
      const Point2 p = seq->at(i);
      for (std::size_t k = 0; k < ex.size(); ++k)  // frequency f = k - reach
        ex[k] = std::polar(1.0, -two_pi * (static_cast<int>(k) - reach) * p.x);
      for (int f = 0; f <= reach; ++f)
        ey[static_cast<std::size_t>(f)] = std::polar(1.0, -two_pi * f * p.y);
      for (int fy = 0; fy <= reach; ++fy)
        for (int k = 0; k < width; ++k)
          sum[static_cast<std::size_t>(fy) * width + k] +=
              ex[static_cast<std::size_t>(k)] * ey[static_cast<std::size_t>(fy)];
    }
    std::vector<double> acc(static_cast<std::size_t>(reach) + 1, 0.0);
    for (int fy = 0; fy <= reach; ++fy)
      for (int fx = -reach; fx <= reach; ++fx) {
        const auto r = static_cast<int>(std::lround(std::hypot(fx, fy)));
        if ((fy == 0 && fx <= 0) || r > reach) continue;
        acc[static_cast<std::size_t>(r)] +=
            std::norm(sum[static_cast<std::size_t>(fy) * width + fx + reach]) / count;
      }
    ring[static_cast<std::size_t>(job)] = std::move(acc);
    progress.tick();
  }
  progress.finish();
  std::vector<Spectrum> out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    Spectrum s{names[k], std::vector<double>(static_cast<std::size_t>(reach) + 1, 0.0)};
    for (int r = 1; r <= reach; ++r) {
      double total = 0.0;
      for (int j = 0; j < seeds; ++j)
        total += ring[k * static_cast<std::size_t>(seeds) + j][static_cast<std::size_t>(r)];
      s.power[static_cast<std::size_t>(r)] =
          total / (seeds * ring_count[static_cast<std::size_t>(r)]);
    }
    out.push_back(std::move(s));
  }
  return out;
}

std::string spectrum_csv(const std::vector<Spectrum>& spectra, uint32_t count, int seeds) {
  std::string s = "sequence,count,seeds,frequency,frequency_over_sqrt_n,power\n";
  for (const Spectrum& sp : spectra)
    for (std::size_t r = 1; r < sp.power.size(); ++r) {
      s += sp.name;
      s += ',';
      s += std::to_string(count);
      s += ',';
      s += std::to_string(seeds);
      s += ',';
      s += std::to_string(r);
      s += ',';
      s += fmt17(static_cast<double>(r) / std::sqrt(double(count)));
      s += ',';
      s += fmt17(sp.power[r]);
      s += '\n';
    }
  return s;
}

void write_spectrum(const std::vector<std::string>& names, uint32_t count, int seeds,
                    uint64_t first_seed, const fs::path& png, const fs::path* csv_out) {
  const std::string text =
      spectrum_csv(radial_spectra(names, count, seeds, first_seed), count, seeds);
  if (csv_out) write_file_atomic(*csv_out, text);
  TempFiles temp;
  const fs::path csv = temp.add("spectrum");
  {
    std::ofstream f(csv);
    f << text;
    if (!f) throw std::runtime_error("cannot write temporary " + csv.string());
  }
  std::string title = "Radial power spectrum, N = ";
  title += std::to_string(count);
  title += ", mean over ";
  title += std::to_string(seeds);
  title += " seeds";
  run_plot("spectrum", {"--csv", csv.string(), "--title", title}, png);
}

std::string to_csv(const std::vector<Row>& rows, uint32_t count, int seeds) {
  const double random_rms = std::sqrt(sequence::expected_random_l2_star_squared(count));
  std::string s = "sequence,count,seeds,mean_l2_star,std_error,min,max,random_rms\n";
  for (const Row& r : rows)
    s += r.name + "," + std::to_string(count) + "," + std::to_string(seeds) + "," + fmt17(r.mean) +
         "," + fmt17(r.std_error) + "," + fmt17(r.min) + "," + fmt17(r.max) + "," +
         fmt17(random_rms) + "\n";
  return s;
}

std::string to_markdown(const std::vector<Row>& rows, uint32_t count, int seeds,
                        uint64_t first_seed) {
  const double random_rms = std::sqrt(sequence::expected_random_l2_star_squared(count));
  char buf[256];
  std::string s = "L2-star discrepancy (Warnock), N = " + std::to_string(count) + ", mean over " +
                  std::to_string(seeds) + " seeds from " + std::to_string(first_seed) +
                  "; random points have RMS sqrt(5/(36N)) = " + fmt17(random_rms) + ".\n\n";
  s += "| sequence | mean D | std. error | min | max | mean / random RMS |\n";
  s += "| --- | ---: | ---: | ---: | ---: | ---: |\n";
  for (const Row& r : rows) {
    std::snprintf(buf, sizeof buf, "| %s | %.4e | %.1e | %.4e | %.4e | %.3f |\n", r.name.c_str(),
                  r.mean, r.std_error, r.min, r.max, r.mean / random_rms);
    s += buf;
  }
  return s;
}

std::string to_json(const std::vector<Row>& rows, uint32_t count, int seeds, uint64_t first_seed) {
  nlohmann::json j;
  j["count"] = count;
  j["seeds"] = seeds;
  j["first_seed"] = first_seed;
  j["random_rms"] = std::sqrt(sequence::expected_random_l2_star_squared(count));
  j["sequences"] = nlohmann::json::array();
  for (const Row& r : rows)
    j["sequences"].push_back({{"name", r.name},
                              {"mean_l2_star", r.mean},
                              {"std_error", r.std_error},
                              {"min", r.min},
                              {"max", r.max}});
  // nlohmann prints the shortest decimal form that reads back to the same double.
  return j.dump(2) + "\n";
}

int run_sequences(SequencesState s) {
  s.seed = parse_u64(s.seed_text, "--seed");
  if (s.count <= 0 || s.count > kMaxCount)
    throw UsageError("--count: " + std::to_string(s.count) + " must be in [1, " +
                     std::to_string(kMaxCount) + "] (the discrepancy costs N^2)");
  if (s.seeds <= 0 || s.seeds > kMaxSeeds)
    throw UsageError("--seeds: " + std::to_string(s.seeds) + " must be in [1, " +
                     std::to_string(kMaxSeeds) + "]");
  require_one_of(s.format, {"md", "csv", "json"}, "--format");
  if (!s.spectrum.empty() && !s.out.empty())
    throw UsageError("--spectrum and --out: give one (the spectrum is a PNG, --out the table)");
  const std::vector<std::string> names =
      parse_name_list(s.only.empty() && !s.spectrum.empty() ? kSpectrumSequences : s.only,
                      sequence::sequence_names(), "--sequences");
  if (!s.out.empty()) check_out_file(s.out);
  const auto count = static_cast<uint32_t>(s.count);
  const int seeds = static_cast<int>(s.seeds);
  if (!s.spectrum.empty()) {
    check_out_file(s.spectrum);
    write_spectrum(names, count, seeds, s.seed, s.spectrum, nullptr);
    return 0;
  }
  const std::vector<Row> rows = compute(names, count, seeds, s.seed);
  const std::string text = s.format == "csv"    ? to_csv(rows, count, seeds)
                           : s.format == "json" ? to_json(rows, count, seeds, s.seed)
                                                : to_markdown(rows, count, seeds, s.seed);
  if (s.out.empty())
    std::fwrite(text.data(), 1, text.size(), stdout);
  else
    write_file_atomic(s.out, text);
  return 0;
}

// The first kFigurePoints points of every sequence (seed 1) as one CSV, drawn as a grid.
void write_figure(const fs::path& png, uint64_t seed) {
  TempFiles temp;
  const fs::path csv = temp.add("sequences");
  {
    std::ofstream f(csv);
    f << "sequence,index,u,v\n";
    for (const std::string& name : sequence::sequence_names()) {
      const auto seq = sequence::make_sequence(name, seed, kFigurePoints);
      for (uint32_t i = 0; i < kFigurePoints; ++i) {
        const Point2 p = seq->at(i);
        f << name << ',' << i << ',' << fmt17(p.x) << ',' << fmt17(p.y) << '\n';
      }
    }
    if (!f) throw std::runtime_error("cannot write temporary " + csv.string());
  }
  run_plot("sequences",
           {"--csv", csv.string(), "--title",
            "First " + std::to_string(kFigurePoints) + " points, seed " + std::to_string(seed)},
           png);
}

int report_sequences(const ReportOptions& options) {
  const uint32_t count = options.quick ? 256 : 4096;
  const int seeds = options.quick ? 4 : 16;
  const std::vector<Row> rows = compute(sequence::sequence_names(), count, seeds, 1);
  write_file_atomic(options.dir / "sequences_discrepancy.csv", to_csv(rows, count, seeds));
  write_file_atomic(options.dir / "sequences_discrepancy.md", to_markdown(rows, count, seeds, 1));
  write_figure(options.dir / "sequences_first500.png", 1);
  const fs::path spectrum_csv_path = options.dir / "sequences_spectrum.csv";
  write_spectrum(parse_name_list(kSpectrumSequences, sequence::sequence_names(), "spectrum"), 1024,
                 options.quick ? 4 : 16, 1, options.dir / "sequences_spectrum.png",
                 &spectrum_csv_path);
  return 0;
}

std::function<int()> setup_sequences(Options& sub) {
  auto state = std::make_shared<SequencesState>();
  std::string names;
  for (const auto& n : sequence::sequence_names())
    names += " " + n;
  sub.add_option("--count", state->count, "Number of points N (1 .. 65536; cost ~N^2)")
      ->capture_default_str();
  sub.add_option("--seeds", state->seeds, "Number of seeds averaged (1 .. 1000)")
      ->capture_default_str();
  sub.add_option("--seed", state->seed_text, "First seed (unsigned 64-bit)")->capture_default_str();
  sub.add_option("--sequences", state->only, "Comma-separated subset (default all):" + names);
  sub.add_option("--format", state->format, "md, csv or json")->capture_default_str();
  sub.add_option("--out", state->out, "Output file (default: stdout)");
  std::string spectrum_help =
      "Draw the radial power spectrum (averaged periodogram) of the first N points into this PNG "
      "instead of the table (default --sequences: ";
  spectrum_help += kSpectrumSequences;
  spectrum_help += ")";
  sub.add_option("--spectrum", state->spectrum, spectrum_help);
  sub.footer(
      "L2-star discrepancy by Warnock's formula of the first N points, mean over seeds\n"
      "seed .. seed+K-1, with standard error, min and max; random points have expected\n"
      "D^2 = 5/(36N) exactly, printed as random_rms for comparison.\n"
      "Examples:\n"
      "  disklab sequences --count 1024\n"
      "  disklab sequences --count 4096 --seeds 16 --format csv --out disc.csv\n"
      "  disklab sequences --count 256 --sequences sobol-owen,pmj02 --format json\n"
      "  disklab sequences --count 1024 --seeds 16 --spectrum spectrum.png");
  return [state] { return run_sequences(*state); };
}

const Registrar kSequences{Command{"sequences", "L2-star discrepancy table of the square sequences",
                                   setup_sequences, report_sequences}};

}  // namespace
}  // namespace disklab::cli
