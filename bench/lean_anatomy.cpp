// Where an area sample's time goes: the lean baseline (area_lean.h) beside the variants it was
// measured against, each in the plain loop a renderer writes (64K Owen-scrambled Sobol' points on
// bench_maps' "mid" scene, every field of the sample summed). Prints ns per sample; run it under
// cachegrind (scripts/lean-anatomy) for instructions and simulated branch mispredictions per
// sample, which do not depend on the machine's load.
//
// Variants:
//   baseline     ellipse::LeanAreaSampler::sample as shipped;
//   four-region  the same with Shirley and Chiu's four-region concentric form (disk/concentric.h:
//                clamped inputs, angles up to 7 pi / 4) and a finiteness test per step, the form
//                the baseline had before;
//   bare         the two-region form with no test at all (what pbrt-v4's Disk::Sample computes);
//   concentric-4, concentric-2  the disk point alone, in the four- and two-region forms.
// Usage: lean_anatomy VARIANT [REPS]   (REPS passes over the 64K points, default 200)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "disklab/disk/concentric.h"
#include "disklab/ellipse/area_lean.h"
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
}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(
        stderr, "usage: lean_anatomy baseline|four-region|bare|concentric-4|concentric-2 [REPS]\n");
    return 2;
  }
  const std::string variant = argv[1];
  const int reps = argc > 2 ? std::atoi(argv[2]) : 200;
  if (reps < 1) {
    std::fprintf(stderr, "lean_anatomy: REPS must be a positive integer\n");
    return 2;
  }
  const disklab::ellipse::Disk scene{Vec3(1.0, 0.5, 3.0), Vec3(0.3, -0.2, -1.0).normalized(), 1.0,
                                     false};
  const Vec3 o = Vec3::Zero();
  const LeanDiskLight light = LeanDiskLight::make(scene);
  const LeanAreaSampler sampler = LeanAreaSampler::make(light, o);
  const disklab::sequence::SobolOwen seq(1);
  std::vector<Point2> u(65536);
  for (uint32_t i = 0; i < u.size(); ++i)
    u[i] = seq.at(i);
  double sink = 0.0;
  const auto loop = [&](auto f) {
    for (int r = 0; r < reps; ++r)
      for (const Point2& p : u) {
        const LightSample s = f(p);
        sink += s.direction.x() + s.direction.y() + s.direction.z() + s.point.x() + s.point.y() +
                s.point.z() + s.pdf + (s.valid ? 1.0 : 0.0);
      }
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
  else {
    std::fprintf(stderr, "lean_anatomy: unknown variant '%s'\n", variant.c_str());
    return 2;
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%s %.2f ns/sample (checksum %.6g)\n", variant.c_str(),
              s * 1e9 / (double(reps) * double(u.size())), sink);
  return 0;
}
