#pragma once
// Guillén et al. 2017's study (Sec. 5, Figs. 6-7) on a scene anyone can recompute: irradiance
// from a vertical two-sided disk light over the ground, estimated in the solid-angle measure
// with every ellipse map, as image MSE at a fixed sample count, RMS error vs N in three
// regions, and the maps' cost per sample measured in the same run.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "disklab/ellipse/any_map.h"
#include "study/claims.h"
#include "study/convergence.h"
#include "study/curves.h"
#include "study/reference.h"
#include "study/scene.h"

namespace disklab::study {

// Disk R = 0.5 at (0, 0, 0.6), normal (1, 0, 0), two-sided, L = 1; ground z = 0 (normal +z);
// an opaque sphere r = 0.25 at (-0.8, 0.5, 0.3).
Scene variance_scene();
// near (x in [0.05, 0.2], y in [-0.15, 0.15]), mid (x in [0.6, 0.9], same y), far (x, y in
// [1.7, 2.0]); 4 x 4 grids with endpoints, all unoccluded.
std::vector<StudyRegion> variance_regions();

// The ground square [lo, hi]^2 as size x size pixels, one shading point at each pixel centre;
// row 0 is the top of the image (largest y), as a renderer writes it.
struct ImageGrid {
  int size = 128;
  double lo = -2.0, hi = 2.0;
  ShadingPoint pixel(int row, int col) const;
};

// Could an occluder block a segment from sp to the light? Conservative: the sphere meets the
// cone from sp around the light's bounding sphere. False means unoccluded for certain.
bool may_be_shadowed(const Scene& scene, const ShadingPoint& sp);

// Unoccluded points by the rim integral, others by the quadrature (error estimate <= 1e-10
// relative is checked: std::runtime_error otherwise).
ReferenceValue irradiance_reference(const Scene& scene, const ShadingPoint& sp, bool* quadrature);

struct ImageReference {
  ImageGrid grid;
  std::vector<double> value, error;  // row-major, grid.size^2
  std::vector<uint8_t> shadowed;     // may_be_shadowed: these pixels use the quadrature
  uint64_t quadrature_pixels = 0;    // how many
};

struct VarianceConfig {
  Scene scene = variance_scene();
  std::vector<StudyRegion> regions = variance_regions();
  std::vector<ellipse::MapKind> maps;  // empty: every map of the registry
  std::vector<std::string> sequences;  // empty: random, sobol-owen, pmj02
  std::vector<uint32_t> ns;            // increasing powers of two >= 16; default 16 .. 4096
  uint32_t fit_min = 64;
  uint32_t seeds = 100;  // randomizations of the regions' curves
  uint32_t image_randomizations = 16;
  uint32_t spp = 16;  // image samples per pixel (a multiple of 4)
  ImageGrid image;
  int timing_repetitions = 5;  // the cost is the median over repetitions
  uint64_t first_seed = 0;
  int bootstrap_replicates = 400;
  int threads = 0;  // 0: OpenMP's default
  // Called from any thread after each unit of work with (done, total).
  std::function<void(uint64_t, uint64_t)> progress;
};

// Fills defaults and checks the configuration (std::invalid_argument naming the field).
void finalize(VarianceConfig& config);

// Cost of a map per shading point, single-threaded over the image's pixels, by bench_maps'
// rules (docs/benchmarks.md): medians over the repetitions; ratio_to_baseline is the median of
// the same-repetition ratios to the area sample a renderer writes (ellipse::LeanAreaSampler).
struct MapCost {
  double setup_ns = 0.0;           // make() alone
  double sample_ns = 0.0;          // each further sample
  double ns_per_sample = 0.0;      // (set-up + spp samples) / spp
  double ratio_to_baseline = 0.0;  // (set-up + spp samples) / the baseline's
};

struct NewtonStats {
  std::vector<uint64_t> histogram;  // [iterations] root solves (the last bin: that many or more)
  uint64_t solves = 0;
  double mean = 0.0;        // per root solve
  double per_sample = 0.0;  // per sample (radial4: one solve serves its four copies)
  int max = 0;
};

struct VarianceResult {
  VarianceConfig config;
  std::vector<std::string> map_names;  // the methods of both tables, in config.maps' order
  std::vector<RegionReferences> references;
  CurveTable curves;  // regions x maps x sequences, N = config.ns
  // Regions "image" (every pixel) and "shadowed" (the pixels an occluder may shadow, where
  // even projected has variance), N = spp, seeds = image randomizations.
  CurveTable image;
  ImageReference image_reference;
  // The first image randomization's estimate per pixel: [map][sequence] row-major.
  std::vector<std::vector<double>> images;
  std::vector<MapCost> cost;        // per map
  MapCost baseline_cost;            // ellipse::LeanAreaSampler, timed with the maps
  std::vector<NewtonStats> newton;  // per map, over every image sample
  const std::vector<double>& image_of(std::size_t map, std::size_t sequence) const {
    return images[map * config.sequences.size() + sequence];
  }
};

ImageReference compute_image_reference(const Scene& scene, const ImageGrid& grid, int threads,
                                       const std::function<void()>& row_done = {});

// How many progress calls a run of the (finalized) configuration makes.
uint64_t work_units(const VarianceConfig& config);

// Runs the study on both cores (every job writes its own slots: the numbers do not depend on
// the thread count), then times the maps on one thread.
VarianceResult run_variance(VarianceConfig config);

// The bootstrap of the regions' curves and of the image randomizations.
SeedBootstrap make_curve_bootstrap(const VarianceConfig& config);
SeedBootstrap make_image_bootstrap(const VarianceConfig& config);

}  // namespace disklab::study

namespace disklab::study {

// Guillén et al.'s claims (Sec. 5, Figs. 6-7) and Christensen's open question (does radial4 carry
// polar4's gain to solid-angle sampling?), measured on a VarianceResult. Sections: "fig7",
// "iid", "newton", "cost", "radial4". Claims on the region "image" are measured on the image
// table (MSE at spp), the others on the regions' curves.
std::vector<Claim> guillen_claims(const VarianceResult& result);
std::vector<ClaimSection> guillen_sections();
// Both tables' outcomes of the claims, image first, each with its own bootstrap.
std::vector<ClaimOutcome> evaluate_guillen_claims(const std::vector<Claim>& claims,
                                                  const VarianceResult& result);

}  // namespace disklab::study
