#pragma once
// The estimator harness shared by the studies (docs/design.md, section 5): a scene, shading points,
// a sampler over a randomized square sequence, and one estimate per sample count N. Sequences
// are progressive, so one pass over the first N_max samples gives every N as a prefix.
//
// Disk strategies sample the unit disk independently of the shading point, so their samples
// are drawn once per randomization and reused for every shading point of every region.
#include <cstdint>
#include <span>
#include <vector>

#include "disklab/disk/strategy.h"
#include "disklab/ellipse/any_map.h"
#include "disklab/sequence/sequence.h"
#include "study/scene.h"

namespace disklab::study {

// A disk strategy's sample in the area measure: the unit-disk point and the estimator weight
// (1 for the maps, 4/pi or 0 for pad-zero): (1/N) sum w f(point) estimates the disk average.
struct AreaSample {
  Point2 point;
  double weight = 1.0;
};

// The first `count` disk samples of `strategy` over `seq` (copies of the four-copy strategies
// and rejection's accepted points counted as samples, as DiskSampler yields them).
std::vector<AreaSample> disk_samples(disk::Strategy strategy, const sequence::Sequence& seq,
                                     uint32_t count);

// Square points a strategy may consume for `count` disk samples: enough for rejection's
// acceptance rate pi/4 with a wide margin (the sequence stays valid past it, only less
// stratified), count / 4 for the four-copy strategies.
uint32_t square_points_needed(disk::Strategy strategy, uint32_t count);

// Area-measure estimates of the irradiance at `sp` for every N in `ns` (increasing, each at most
// samples.size()): out[k] = (pi R^2 / N) sum_{i < N} w_i f(x_i), f the irradiance integrand.
void progressive_irradiance(const Scene& scene, const ShadingPoint& sp,
                            std::span<const AreaSample> samples, std::span<const uint32_t> ns,
                            std::span<double> out);

// The ellipse map of the light seen from `sp` (its two-sidedness included; projected samples
// sp's cosine).
ellipse::AnyMap light_map(ellipse::MapKind kind, const Scene& scene, const ShadingPoint& sp);

// Solid-angle estimates of the irradiance at `sp` with `map` (built for sp) for every N in `ns`
// (increasing): out[k] = (1/N) sum_{i < N} L max(0, w_i . n_o) V(o, x_i) / pdf_i, x_i the
// sample's point on the disk. A rejected candidate (gamito, tabulated) is a sample of value 0;
// radial4's four copies of a square point are four samples, so N/4 points of `u` are used.
// When `newton` is not empty, newton[min(it, size - 1)] counts each root solve's iterations.
void progressive_irradiance(const Scene& scene, const ShadingPoint& sp, const ellipse::AnyMap& map,
                            std::span<const Point2> u, std::span<const uint32_t> ns,
                            std::span<double> out, std::span<uint64_t> newton = {});

}  // namespace disklab::study
