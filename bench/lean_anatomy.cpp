// Where a light sample's time goes: the lean baseline (area_lean.h) beside the variants it was
// measured against, and the maps whose cost floors docs/benchmarks.md shows, each in the plain
// loop a renderer writes (64K Owen-scrambled Sobol' points on one of bench_maps' scenes, every
// field of the sample summed). Prints ns per sample and, for the maps that solve for roots, the
// mean root-function evaluations per sample and the radial series' terms; run it under
// cachegrind (scripts/lean-anatomy) for instructions and simulated branch mispredictions per
// sample, which do not depend on the machine's load.
//
// Variants:
//   baseline     ellipse::LeanAreaSampler::sample as shipped;
//   four-region  the same with Shirley and Chiu's four-region concentric form (disk/concentric.h:
//                clamped inputs, angles up to 7 pi / 4) and a finiteness test per step, the form
//                the baseline had before;
//   bare         the two-region form with no test at all (what pbrt-v4's Disk::Sample computes);
//   concentric-4, concentric-2  the disk point alone, in the four- and two-region forms;
//   area         ellipse::AreaSampler, the full-accuracy area map;
//   radial       ellipse::RadialMap::sample; radial-start and radial-solve its stages: the
//                root solve's start alone (quarter-range sincos + series reversion), the whole
//                solve (start + Newton), each consumed as a sample's point;
//   radial-fast, radial4 (per direction: sample4 / 4), projected  those maps' samples;
//   projected-azimuth  projected's first root solve alone (u.x -> the azimuth s);
//   radial-setup, radial-setup-1, baseline-setup-1, radial-shape  per point a new shading point
//                (o moved by up to 1e-3 radii): radial's make alone, its make and one sample,
//                the baseline's make and one sample, the spherical ellipse's shape alone.
// Usage: lean_anatomy VARIANT [REPS] [SCENE] [ORDER]   (REPS passes over the 64K points, default
//        200; SCENE one of bench_maps' near, mid, far, grazing: default mid; ORDER "sobol", the
//        sequence's own order (default), or "shuffled", the same points in a fixed random order,
//        where a branch on the point cannot learn the sequence's pattern)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "disklab/disk/concentric.h"
#include "disklab/ellipse/area.h"
#include "disklab/ellipse/area_lean.h"
#include "disklab/ellipse/projected.h"
#include "disklab/ellipse/radial4.h"
#include "disklab/ellipse/radial_fast.h"
#include "disklab/sequence/sobol.h"

namespace {
using disklab::Point2;
using disklab::Vec3;
using disklab::ellipse::LeanAreaSampler;
using disklab::ellipse::LeanDiskLight;
using disklab::ellipse::LightSample;
namespace disk = disklab::disk;

using disklab::ellipse::detail::concentric_two_region;

LightSample four_region(const LeanDiskLight& l, const Vec3& o, Point2 u) {
  LightSample out;
  if (!(u.x >= 0.0 && u.x <= 1.0 && u.y >= 0.0 && u.y <= 1.0)) return out;
  const Point2 d = disk::sample_concentric(u);
  out.point = l.center + d.x * l.t1 + d.y * l.t2;
  const Vec3 v = out.point - o;
  const double dist2 = v.squaredNorm();
  if (!(dist2 > 0.0) || !std::isfinite(dist2)) return out;
  out.direction = v / std::sqrt(dist2);
  const double cos_l = std::abs(out.direction.dot(l.normal));
  if (!(cos_l > 0.0)) return out;
  out.pdf = dist2 * l.inv_area / cos_l;
  out.valid = std::isfinite(out.pdf);
  if (!out.valid) out.pdf = 0.0;
  return out;
}

LightSample bare(const LeanDiskLight& l, const Vec3& o, Point2 u) {
  LightSample out;
  const Point2 d = concentric_two_region(u);
  out.point = l.center + d.x * l.t1 + d.y * l.t2;
  const Vec3 v = out.point - o;
  const double dist2 = v.squaredNorm();
  out.direction = v / std::sqrt(dist2);
  out.pdf = dist2 * l.inv_area / std::abs(out.direction.dot(l.normal));
  out.valid = true;
  return out;
}

LightSample disk_only(Point2 d) {
  LightSample out;
  out.point = Vec3(d.x, d.y, 0.0);
  return out;
}

// Every field a renderer reads from a sample, summed (bench_maps' rule).
template <class S>
double consume(const S& s) {
  return s.direction.x() + s.direction.y() + s.direction.z() + s.point.x() + s.point.y() +
         s.point.z() + s.pdf + (s.valid ? 1.0 : 0.0);
}

// A map's sample as the loop consumes it (the fields a renderer reads).
LightSample as_light(const disklab::ellipse::EllipseSample& e) {
  LightSample out;
  out.point = e.point;
  out.direction = e.direction;
  out.pdf = e.pdf;
  out.valid = e.valid;
  return out;
}

// bench_maps' scenes (its configs()), the disk's radius 1 and the point at the origin.
bool scene_of(const std::string& name, disklab::ellipse::Disk& d) {
  const Vec3 tilted = Vec3(0.3, -0.2, -1.0).normalized();
  if (name == "near")
    d = {Vec3(0.3, 0.2, 0.5), Vec3(0, 0, -1), 1.0, false};
  else if (name == "mid")
    d = {Vec3(1.0, 0.5, 3.0), tilted, 1.0, false};
  else if (name == "far")
    d = {Vec3(300.0, 200.0, 1000.0), tilted, 1.0, false};
  else if (name == "grazing")
    d = {Vec3(3.0, 0.0, 0.05), Vec3(0, 0, -1), 1.0, false};
  else
    return false;
  return true;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(
        stderr,
        "usage: lean_anatomy VARIANT [REPS] [SCENE]\n  VARIANT: baseline four-region bare "
        "concentric-4 concentric-2 area radial radial-start radial-solve radial-fast "
        "radial4 projected projected-azimuth\n  SCENE: near mid far grazing (default mid)\n");
    return 2;
  }
  const std::string variant = argv[1];
  const int reps = argc > 2 ? std::atoi(argv[2]) : 200;
  std::string extra;  // what the variant adds to the report line
  if (reps < 1) {
    std::fprintf(stderr, "lean_anatomy: REPS must be a positive integer\n");
    return 2;
  }
  const std::string scene_name = argc > 3 ? argv[3] : "mid";
  disklab::ellipse::Disk scene;
  if (!scene_of(scene_name, scene)) {
    std::fprintf(stderr, "lean_anatomy: unknown scene '%s' (near, mid, far, grazing)\n",
                 scene_name.c_str());
    return 2;
  }
  const Vec3 o = Vec3::Zero();
  namespace ell = disklab::ellipse;
  const LeanDiskLight light = LeanDiskLight::make(scene);
  const LeanAreaSampler sampler = LeanAreaSampler::make(light, o);
  const disklab::sequence::SobolOwen seq(1);
  std::vector<Point2> u(65536);
  for (uint32_t i = 0; i < u.size(); ++i)
    u[i] = seq.at(i);
  const std::string order = argc > 4 ? argv[4] : "sobol";
  if (order != "sobol" && order != "shuffled") {
    std::fprintf(stderr, "lean_anatomy: ORDER is sobol or shuffled, not '%s'\n", order.c_str());
    return 2;
  }
  if (order == "shuffled") {  // a fixed LCG's Fisher-Yates shuffle
    std::uint64_t x = 12345;
    for (std::size_t i = u.size() - 1; i > 0; --i) {
      x = x * 6364136223846793005ULL + 1442695040888963407ULL;
      std::swap(u[i], u[(x >> 33) % (i + 1)]);
    }
  }
  double sink = 0.0;
  long long evaluations = 0;  // root-function evaluations of the maps that solve
  const auto loop = [&](auto f) {
    for (int r = 0; r < reps; ++r)
      for (const Point2& p : u) {
        sink += consume(f(p));
      }
  };
  // The same for f(p, &iterations), counting the root-function evaluations.
  const auto counted = [&](auto f) {
    loop([&](Point2 p) {
      int it = 0;
      LightSample s = f(p, &it);
      evaluations += it;
      return s;
    });
  };
  const auto t0 = std::chrono::steady_clock::now();
  if (variant == "baseline")
    loop([&](Point2 p) { return sampler.sample(p); });
  else if (variant == "four-region")
    loop([&](Point2 p) { return four_region(light, o, p); });
  else if (variant == "bare")
    loop([&](Point2 p) { return bare(light, o, p); });
  else if (variant == "concentric-4")
    loop([&](Point2 p) { return disk_only(disk::sample_concentric(p)); });
  else if (variant == "concentric-2")
    loop([&](Point2 p) { return disk_only(concentric_two_region(p)); });
  else if (variant == "area") {
    const auto m = ell::AreaSampler::make(scene, o);
    loop([&](Point2 p) { return as_light(m.sample(p)); });
  } else if (variant == "radial" || variant == "radial-start" || variant == "radial-solve") {
    const auto m = ell::RadialMap::make(scene, o);
    const ell::RadialQuadrant q = m.quadrant();
    extra = " series terms " + std::to_string(m.series.n);
    if (variant == "radial") {
      counted([&](Point2 p, int* it) { return as_light(m.sample(p, it)); });
    } else if (variant == "radial-start") {
      loop([&](Point2 p) {
        const auto a =
            m.series.reverted_start(disklab::math::quarter_sincos(p.x * 1.5707963267948966));
        return disk_only({a.cs, a.ss});
      });
    } else {
      counted([&](Point2 p, int* it) {
        const auto a = q.solve(p.x, it);
        return disk_only({a.cs, a.ss});
      });
    }
  } else if (variant == "radial-setup" || variant == "radial-setup-1" ||
             variant == "baseline-setup-1" || variant == "radial-shape") {
    // A new shading point per point (o moved by up to 1e-3 radii): every make sees a new
    // point, and the series keeps the scene's length. The choice is made outside the loops.
    const auto at = [&](Point2 p) -> Vec3 { return o + Vec3(1e-3 * p.x, 1e-3 * p.y, 0.0); };
    if (variant == "baseline-setup-1")
      loop([&](Point2 p) { return LeanAreaSampler::make(light, at(p)).sample(p); });
    else if (variant == "radial-shape")
      loop([&](Point2 p) {
        const auto g = ell::MapGeometry::make_shape(scene, at(p));
        return disk_only({g.a, g.b});
      });
    else if (variant == "radial-setup-1")
      loop([&](Point2 p) { return as_light(ell::RadialMap::make(scene, at(p)).sample(p)); });
    else
      loop([&](Point2 p) {
        const auto m = ell::RadialMap::make(scene, at(p));
        return disk_only({m.series.a0, m.g.omega});
      });
  } else if (variant == "radial-fast") {
    const auto m = ell::RadialFastMap::make(scene, o);
    counted([&](Point2 p, int* it) { return as_light(m.sample(p, it)); });
  } else if (variant == "radial4") {
    const auto m = ell::Radial4Map::make(scene, o);
    // A quarter of the points, four directions each: as many samples as the other variants.
    for (int r = 0; r < reps; ++r)
      for (std::size_t i = 0; i < u.size() / 4; ++i) {
        int it = 0;
        for (const auto& e : m.sample4(u[i], &it))
          sink += consume(e);
        evaluations += it;
      }
  } else if (variant == "projected-azimuth") {
    const auto m = ell::ProjectedMap::make(scene, o, Vec3::UnitZ());
    counted([&](Point2 p, int* it) {
      const auto a = m.solve_s(p.x, it);
      return disk_only({a.cs, a.ss});
    });
  } else if (variant == "projected") {
    const auto m = ell::ProjectedMap::make(scene, o, Vec3::UnitZ());
    counted([&](Point2 p, int* it) { return as_light(m.sample(p, it)); });
  } else {
    std::fprintf(stderr, "lean_anatomy: unknown variant '%s'\n", variant.c_str());
    return 2;
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double samples = double(reps) * double(u.size());
  std::printf("%s %.2f ns/sample (checksum %.6g) evaluations/sample %.3f%s\n", variant.c_str(),
              s * 1e9 / samples, sink, double(evaluations) / samples, extra.c_str());
  return 0;
}
