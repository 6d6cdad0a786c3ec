#pragma once
// The memo's convergence study (Christensen 2018, Secs. 4.1-4.2, Figs. 5-6) on a scene anyone
// can recompute: RMS error of the area-measure irradiance estimate against exact references,
// for every (region, disk strategy, sequence, N), over independent randomizations, and the
// log-log slopes with bootstrap standard errors.
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "disklab/disk/strategy.h"
#include "study/curves.h"
#include "study/fit.h"
#include "study/reference.h"
#include "study/scene.h"

namespace disklab::study {

// Disk light R = 1 at (0, 0, 2) facing down (one-sided, L = 1) over the ground z = 0 (normal +z);
// an opaque sphere of radius 0.5 at (1.5, 0, 1). Unit-disk samples (p.x, p.y) land at world
// (p.x, p.y, 2): the light's in-plane axes are world x and y.
Scene memo_scene();

// lit-axis (x, y in [-0.6, -0.3]), lit-off (x, y in [-1.6, -1.3]), penumbra (x in [1.9, 2.2],
// y in [0.5, 0.8]); 4 x 4 grids with endpoints.
struct StudyRegion {
  Region grid;
  bool fully_lit = false;  // reference by the closed form (else by quadrature)
};
std::vector<StudyRegion> memo_regions();

struct ConvergenceConfig {
  Scene scene = memo_scene();
  std::vector<StudyRegion> regions = memo_regions();
  std::vector<disk::Strategy> strategies;  // empty: all six
  std::vector<std::string> sequences;      // empty: every sequence of the registry
  std::vector<uint32_t> ns;                // increasing; default 16 .. 4096 by powers of two
  uint32_t fit_min = 64;                   // slopes fit N in [fit_min, ns.back()]
  uint32_t seeds = 100;
  uint64_t first_seed = 0;  // randomizations first_seed .. first_seed + seeds - 1
  int bootstrap_replicates = 400;
  int threads = 0;  // 0: OpenMP's default
  // Called after each (sequence, seed) job, from any thread, with (done, total).
  std::function<void(uint64_t, uint64_t)> progress;
};

// Fills defaults and checks the configuration (std::invalid_argument with a message naming the
// field for: unknown sequence, N not an increasing list of powers of two >= 4 that are
// multiples of 4, seeds == 0, fewer than two N in the fit range).
void finalize(ConvergenceConfig& config);

// References of every region (closed form for fully lit regions, quadrature otherwise).
std::vector<RegionReferences> compute_references(const ConvergenceConfig& config);

// The study's curves (methods: the strategies' names) with the configuration and references.
class ConvergenceResult : public CurveTable {
 public:
  ConvergenceConfig config;
  std::vector<RegionReferences> references;

  std::size_t points_per_region(std::size_t region) const {
    return references[region].points.size();
  }
  // Sets the curve axes from config and references and sizes the per-seed sums (zeros).
  // Filled by run_convergence; a test may fill them to make a synthetic result.
  void allocate();
};

// Runs the study (both cores: jobs are (sequence, seed) pairs; each writes its own slots, so
// the numbers do not depend on the thread count). The config is finalized first.
ConvergenceResult run_convergence(ConvergenceConfig config);

// The bootstrap every output of a run uses (replicates and seed from the config).
SeedBootstrap make_bootstrap(const ConvergenceConfig& config);

}  // namespace disklab::study
