// disklab soak --samples N --seed S [--per-scene K]
//
// Random configurations (distance log-uniform over 1e-9 .. 1e9 radii, random disk orientation,
// normal length log-uniform over 1e-100 .. 1e100, radius log-uniform over 1e-100 .. 1e100, the
// point's direction from the disk uniform on the sphere, one- and two-sided disks), every map of
// ellipse::map_names(), K samples per scene and map at random u: counts samples that break the
// contracts of ellipse/contracts.h (NaN/Inf fields, directions off the disk, pdf(direction)
// differing from the sample's pdf, inverse failures). Prints the counts, exits 1 on any.
// Deterministic for a seed whatever the thread count: scene i draws from its own generator.
#include <omp.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "command.h"
#include "common/args.h"
#include "common/output.h"
#include "disklab/ellipse/any_map.h"
#include "disklab/ellipse/contracts.h"
#include "disklab/math/constants.h"
#include "disklab/sequence/random.h"

namespace disklab::cli {
namespace {

struct SoakState {
  std::string samples_text = "1000000", seed_text = "1", per_scene_text = "16";
};

struct Counts {
  uint64_t samples = 0, valid = 0, invalid_maps = 0;
  std::array<uint64_t, 7> violations{};  // by ellipse::Violation
};

// Scene i of the soak: a disk of random radius and orientation, a point at a log-uniform
// distance in a uniform direction.
struct SoakScene {
  ellipse::Disk disk;
  Vec3 o;
};

Vec3 unit_on_sphere(sequence::Pcg32& rng) {
  const double z = 2.0 * rng.next_double() - 1.0, phi = math::kTwoPi * rng.next_double();
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}
double log_uniform(sequence::Pcg32& rng, double lo_exp, double hi_exp) {
  return std::pow(10.0, lo_exp + (hi_exp - lo_exp) * rng.next_double());
}

SoakScene make_scene(sequence::Pcg32& rng) {
  SoakScene s;
  const double r = log_uniform(rng, -100, 100);
  s.disk.radius = r;
  s.disk.normal = log_uniform(rng, -100, 100) * unit_on_sphere(rng);
  s.disk.center = r * log_uniform(rng, -3, 3) * unit_on_sphere(rng);
  s.disk.two_sided = rng.next_double() < 0.5;
  s.o = s.disk.center + r * log_uniform(rng, -9, 9) * unit_on_sphere(rng);
  return s;
}

int run_soak(const SoakState& st) {
  const uint64_t samples = parse_u64(st.samples_text, "--samples");
  const uint64_t seed = parse_u64(st.seed_text, "--seed");
  const uint64_t per_scene = parse_u64(st.per_scene_text, "--per-scene");
  if (samples == 0) throw UsageError("--samples: must be positive");
  if (per_scene == 0) throw UsageError("--per-scene: must be positive");
  const auto& names = ellipse::map_names();
  const uint64_t per_scene_all = per_scene * names.size();
  const uint64_t scenes = (samples + per_scene_all - 1) / per_scene_all;
  Progress progress("soak", scenes);
  Counts total;
  std::atomic<uint64_t> first_bad{UINT64_MAX};
#pragma omp parallel
  {
    Counts local;
#pragma omp for schedule(dynamic, 64)
    for (int64_t i = 0; i < static_cast<int64_t>(scenes); ++i) {
      sequence::Pcg32 rng(seed, static_cast<uint64_t>(i));
      const SoakScene sc = make_scene(rng);
      for (std::size_t k = 0; k < names.size(); ++k) {
        const auto m = ellipse::AnyMap::make(static_cast<ellipse::MapKind>(k), sc.disk, sc.o);
        if (!m.valid()) ++local.invalid_maps;
        for (uint64_t j = 0; j < per_scene; ++j) {
          const Point2 u{rng.next_double(), rng.next_double()};
          const ellipse::EllipseSample s = m.sample(u);
          ++local.samples;
          if (!s.valid) continue;
          ++local.valid;
          ellipse::Violation v = ellipse::check_sample(m, s);
          if (v == ellipse::Violation::none) v = ellipse::check_inverse(m, s);
          if (v != ellipse::Violation::none) {
            ++local.violations[static_cast<std::size_t>(v)];
            uint64_t prev = first_bad.load();
            while (static_cast<uint64_t>(i) < prev &&
                   !first_bad.compare_exchange_weak(prev, static_cast<uint64_t>(i))) {
            }
          }
        }
      }
      progress.tick();
    }
#pragma omp critical
    {
      total.samples += local.samples;
      total.valid += local.valid;
      total.invalid_maps += local.invalid_maps;
      for (std::size_t v = 0; v < total.violations.size(); ++v)
        total.violations[v] += local.violations[v];
    }
  }
  progress.finish();
  uint64_t bad = 0;
  std::printf("samples %llu\nvalid %llu\nscenes %llu\ninvalid_maps %llu\n",
              static_cast<unsigned long long>(total.samples),
              static_cast<unsigned long long>(total.valid), static_cast<unsigned long long>(scenes),
              static_cast<unsigned long long>(total.invalid_maps));
  for (std::size_t v = 1; v < total.violations.size(); ++v) {
    std::printf("%s: %llu\n", ellipse::violation_name(static_cast<ellipse::Violation>(v)),
                static_cast<unsigned long long>(total.violations[v]));
    bad += total.violations[v];
  }
  if (bad > 0) {
    std::fprintf(
        stderr, "disklab: soak: %llu contract violation(s); first in scene %llu (seed %llu)\n",
        static_cast<unsigned long long>(bad), static_cast<unsigned long long>(first_bad.load()),
        static_cast<unsigned long long>(seed));
    return 1;
  }
  return 0;
}

std::function<int()> setup_soak(Options& sub) {
  auto state = std::make_shared<SoakState>();
  sub.add_option("--samples", state->samples_text, "Samples to draw in all (default 1000000)");
  sub.add_option("--seed", state->seed_text, "Seed (unsigned 64-bit; default 1)");
  sub.add_option("--per-scene", state->per_scene_text, "Samples per scene and map (default 16)");
  sub.footer(
      "Random scenes (distance 1e-9 .. 1e9 radii, radius and normal length 1e-100 .. 1e100,\n"
      "random orientations, one- and two-sided), every map, random u; each valid sample is\n"
      "checked against ellipse/contracts.h. Prints the counts per violation; exit 1 on any.\n"
      "Same counts for a seed whatever the number of threads (OMP_NUM_THREADS).\n"
      "Examples:\n"
      "  disklab soak --samples 1000000 --seed 1\n"
      "  OMP_NUM_THREADS=2 disklab soak --samples 100000000 --seed 7");
  return [state] { return run_soak(*state); };
}

const Registrar kSoak{
    Command{"soak", "Random scenes x every map: count contract violations", setup_soak, {}}};

}  // namespace
}  // namespace disklab::cli
