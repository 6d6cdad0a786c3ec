// Chi-square uniformity of every strategy's disk points (docs/design.md section 4, Mitsuba-style):
// counts in a Cartesian grid of bins against expected counts from the EXACT area of each bin
// clipped to the disk (support/planar.h), low-count bins pooled, Sidak-corrected significance.
// The seed blog's linear-radius polar map is the negative control: the same test must reject it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "disklab/disk/strategy.h"
#include "disklab/math/constants.h"
#include "disklab/sequence/random.h"
#include "support/planar.h"
#include "support/stats.h"

namespace {
using disklab::Point2;
using disklab::math::kPi;
using disklab::sequence::RandomSequence;
using namespace disklab::disk;
namespace t = disklab::test;

// ---- Significance and sizes (the one place for this suite) ----
// Family-wise false-rejection probability of a correct implementation for one seed: 1e-3. The
// family is the 12 tests below: pad-zero, rejection, polar, concentric, and each of the 4
// copies of polar4 and of concentric4. Copies are tested separately: copy k (sample s with
// s mod 4 = k) is uniform on quadrant k only, and the four copies of one square point are not
// independent, so pooling them would break the multinomial model (chi2 would be inflated 4x).
constexpr double kFamilyAlpha = 1e-3;
constexpr std::size_t kTests = 12;
// 2e5 points in a 16 x 16 grid (~200 bins in the disk, ~780 expected per interior bin):
// detects density errors of a few percent in any bin region; the negative control's density
// 1 / (2 pi r) is off by a factor > 2 over most of the disk.
constexpr uint32_t kPoints = 200000;
constexpr int kGrid = 16;
// Pearson's approximation is sound when every pooled expected count is at least 5.
constexpr double kMinExpected = 5.0;
constexpr uint64_t kSeed = 20181802;  // fixed: the test is deterministic; alpha says how lucky

// Quadrant k of the disk (counter-clockwise from +x), or the whole disk.
constexpr int kWholeDisk = -1;

struct Binned {
  int quadrant = kWholeDisk;  // the support the points should be uniform on
  std::vector<double> observed = std::vector<double>(kGrid * kGrid, 0.0);
  double total = 0.0;
  void add(Point2 p) {
    const int i = std::clamp(int(std::floor((p.x + 1.0) * 0.5 * kGrid)), 0, kGrid - 1);
    const int j = std::clamp(int(std::floor((p.y + 1.0) * 0.5 * kGrid)), 0, kGrid - 1);
    observed[j * kGrid + i] += 1.0;
    total += 1.0;
  }
  t::ChiSquareResult test() const {
    std::vector<double> expected(kGrid * kGrid);
    for (int j = 0; j < kGrid; ++j) {
      for (int i = 0; i < kGrid; ++i) {
        const double x0 = -1.0 + 2.0 * i / kGrid, x1 = -1.0 + 2.0 * (i + 1) / kGrid;
        const double y0 = -1.0 + 2.0 * j / kGrid, y1 = -1.0 + 2.0 * (j + 1) / kGrid;
        // kGrid is even, so no bin straddles an axis: a bin is in one quadrant or the other.
        const bool right = i >= kGrid / 2, top = j >= kGrid / 2;
        const int q = top ? (right ? 0 : 1) : (right ? 3 : 2);
        const double support = quadrant == kWholeDisk ? kPi : kPi / 4.0;
        const bool in_support = quadrant == kWholeDisk || quadrant == q;
        expected[j * kGrid + i] =
            in_support ? total * t::disk_rect_area(x0, x1, y0, y1) / support : 0.0;
      }
    }
    return t::chi_square(observed, expected, kMinExpected);
  }
};

double per_test_alpha() {
  return t::sidak_alpha(kFamilyAlpha, kTests);
}

// Bins the points of `strategy` that carry weight, one Binned per copy index.
std::vector<Binned> bin_strategy(Strategy strategy) {
  const RandomSequence seq(kSeed);
  DiskSampler<RandomSequence> sampler(strategy, seq);
  std::vector<Binned> bins(copies_per_square_point(strategy));
  if (bins.size() == 4)
    for (int k = 0; k < 4; ++k)
      bins[k].quadrant = k;
  const uint32_t samples = kPoints * copies_per_square_point(strategy);
  for (uint32_t s = 0; s < samples; ++s) {
    const DiskSample d = sampler.next();
    if (d.weight > 0.0) bins[d.copy].add(d.point);  // pad-zero's zeros are not disk points
  }
  return bins;
}

class Uniformity : public ::testing::TestWithParam<Strategy> {};

TEST_P(Uniformity, ChiSquareAgainstExactBinAreas) {
  const Strategy strategy = GetParam();
  const std::vector<Binned> per_copy = bin_strategy(strategy);
  for (std::size_t k = 0; k < per_copy.size(); ++k) {
    const t::ChiSquareResult r = per_copy[k].test();
    std::printf("  %s copy %zu: %s\n", std::string(strategy_name(strategy)).c_str(), k,
                r.summary().c_str());
    EXPECT_GE(r.p_value, per_test_alpha())
        << std::string(strategy_name(strategy)) << " copy " << k << " (support: "
        << (per_copy[k].quadrant == kWholeDisk ? std::string("disk")
                                               : "quadrant " + std::to_string(k))
        << "): " << r.summary() << " points=" << per_copy[k].total << " seed=" << kSeed
        << " grid=" << kGrid << "x" << kGrid << " alpha=" << per_test_alpha();
  }
}

INSTANTIATE_TEST_SUITE_P(AllStrategies, Uniformity, ::testing::ValuesIn(kAllStrategies),
                         [](const auto& info) {
                           std::string n(strategy_name(info.param));
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

TEST(Uniformity, RejectsTheLinearRadiusNegativeControl) {
  const RandomSequence seq(kSeed);
  Binned b;
  for (uint32_t i = 0; i < kPoints; ++i)
    b.add(t::sample_polar_linear_radius_NOT_UNIFORM(seq.at(i)));
  const t::ChiSquareResult r = b.test();
  std::printf("  linear-radius (negative control): %s\n", r.summary().c_str());
  EXPECT_LT(r.p_value, per_test_alpha()) << "linear-radius polar was accepted: " << r.summary();
}

// The test also has the power to see a subtle error: polar with phi = 2 pi v (1 + 1/32), which
// overlaps the first 1/32 of the turn (that wedge gets density 2/pi).
TEST(Uniformity, RejectsASlightlyWrongAngleScale) {
  const RandomSequence seq(kSeed);
  Binned b;
  for (uint32_t i = 0; i < kPoints; ++i) {
    const Point2 uv = seq.at(i);
    const double r = std::sqrt(uv.x), phi = 2.0 * kPi * uv.y * (1.0 + 1.0 / 32.0);
    b.add({r * std::cos(phi), r * std::sin(phi)});
  }
  const t::ChiSquareResult r = b.test();
  EXPECT_LT(r.p_value, per_test_alpha()) << r.summary();
}

}  // namespace
