// Area preservation of stratum images (docs/design.md section 4): the image of every stratum of an
// n x n grid of the unit square has area pi / n^2 under the polar and concentric maps and
// pi / (4 n^2) under their quarter-disk variants (polar4, concentric4 before rotation).
// The area comes from Green's theorem on the mapped boundary (support/planar.h), computed from
// map values only, never from the Jacobian the maps were derived with.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "disklab/disk/concentric.h"
#include "disklab/disk/polar.h"
#include "disklab/math/constants.h"
#include "support/planar.h"

namespace {
using disklab::Point2;
using disklab::math::kPi;
using namespace disklab::disk;
using disklab::test::AreaEstimate;
using disklab::test::stratum_image_area;

// ---- Tolerances (the one place for this suite) ----
// A stratum's image area must match the exact value to 1e-9 relative. Rounding in the maps
// (a few ulps of position) moves an image's area by ~1e-15 relative to its perimeter-times-
// error, far below this; a wrong map (missing sqrt, wrong angle scale, a region off by a
// constant) is off by O(1), and even a 1e-6 slip in a constant would be caught.
constexpr double kAreaRel = 1e-9;
// The quadrature must be far more accurate than what it checks: its own Romberg error
// estimate is driven below kAreaRel / 1000 of the stratum area, and the test asserts that the
// estimate it reached is at most kAreaRel / 100, so a failure is the map's and not Green's.
constexpr double kQuadratureRel = kAreaRel / 1000.0;
constexpr double kQuadratureMaxRel = kAreaRel / 100.0;
// The Green's-theorem quadrature on maps with closed-form image areas: driven to 1e-14 (1e-13
// relative for the warp), checked to ten times that; a reflection's signed area to its rounding.
constexpr double kGreenTarget = 1e-14, kGreenCheck = 1e-13;
constexpr double kGreenWarpTargetRel = 1e-13, kGreenWarpCheckRel = 1e-12;
constexpr double kGreenReflection = 1e-15;
// Exact disk-rectangle areas (segments by asin and square roots): a few ulps of pi; the 37 x 37
// tiling sums 1369 of them.
constexpr double kDiskRectAbs = 1e-15, kDiskTilingAbs = 1e-13;
// Grid sizes: n up to 32 (1024 strata), as the issue asks; 1 checks the whole domain.
constexpr int kGrids[] = {1, 2, 3, 4, 8, 16, 32};

struct MapCase {
  const char* name;
  Point2 (*map)(Point2);
  double total;  // area of the image of the whole square
};

void check_strata(const MapCase& mc) {
  int worst_level = 0;
  double worst_rel = 0.0;
  for (int n : kGrids) {
    const double expected = mc.total / (n * n);
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const double u0 = double(i) / n, u1 = double(i + 1) / n;
        const double v0 = double(j) / n, v1 = double(j + 1) / n;
        const AreaEstimate a =
            stratum_image_area(mc.map, u0, u1, v0, v1, kQuadratureRel * expected);
        const double rel = std::fabs(a.area - expected) / expected;
        worst_rel = std::fmax(worst_rel, rel);
        worst_level = std::max(worst_level, a.max_level);
        char where[400];
        std::snprintf(where, sizeof where,
                      "%s n=%d stratum [%.17g,%.17g]x[%.17g,%.17g]: area %.17g expected %.17g "
                      "(quadrature error %.3g, level %d)",
                      mc.name, n, u0, u1, v0, v1, a.area, expected, a.error, a.max_level);
        ASSERT_LE(a.error, kQuadratureMaxRel * expected) << where;
        ASSERT_LE(rel, kAreaRel) << where;
      }
    }
  }
  std::printf("%s: worst relative area error %.3g, deepest refinement 2^%d chords per edge\n",
              mc.name, worst_rel, worst_level);
}

TEST(StratumArea, Polar) {
  check_strata({"polar", sample_polar, kPi});
}
TEST(StratumArea, Concentric) {
  check_strata({"concentric", sample_concentric, kPi});
}
TEST(StratumArea, PolarQuarter) {
  check_strata({"polar-quarter", sample_polar_quarter, kPi / 4.0});
}
TEST(StratumArea, ConcentricQuarter) {
  check_strata({"concentric-quarter", sample_concentric_quarter, kPi / 4.0});
}

// Elementary intervals of base 2 with 2^m cells, the strata a (0,2)-sequence fills one point
// each (Christensen et al. 2018): [i/2^k, (i+1)/2^k) x [j/2^(m-k), (j+1)/2^(m-k)), every k.
// Thin slabs test the maps along whole rows and columns of the square, not just squares.
TEST(StratumArea, ElementaryIntervalsOfEveryShape) {
  constexpr int m = 6;
  const MapCase cases[] = {{"polar", sample_polar, kPi},
                           {"concentric", sample_concentric, kPi},
                           {"polar-quarter", sample_polar_quarter, kPi / 4.0},
                           {"concentric-quarter", sample_concentric_quarter, kPi / 4.0}};
  for (const MapCase& mc : cases) {
    const double expected = mc.total / (1 << m);
    for (int k = 0; k <= m; ++k) {
      const int nu = 1 << k, nv = 1 << (m - k);
      for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
          const AreaEstimate a =
              stratum_image_area(mc.map, double(i) / nu, double(i + 1) / nu, double(j) / nv,
                                 double(j + 1) / nv, kQuadratureRel * expected);
          ASSERT_LE(a.error, kQuadratureMaxRel * expected)
              << mc.name << " k=" << k << " cell " << i << "," << j;
          ASSERT_LE(std::fabs(a.area - expected), kAreaRel * expected)
              << mc.name << " k=" << k << " cell (" << i << ", " << j << ") of " << nu << "x" << nv
              << ": area " << a.area << " expected " << expected;
        }
      }
    }
  }
}

// The same comparison must fail for a map that is not area-preserving: the seed blog's
// linear-radius polar map gives the inner ring of an n x n grid far too little area (radius v
// instead of sqrt(v)). The blog's (u, v) = (angle, radius) order reverses the orientation, so
// its signed areas are negative: compare magnitudes.
TEST(StratumArea, RejectsTheLinearRadiusNegativeControl) {
  const int n = 4;
  const double expected = kPi / (n * n);
  int rejected = 0;
  for (int j = 0; j < n; ++j) {  // radius band [j/n, (j+1)/n], angle [0, 2 pi / n]
    const AreaEstimate a =
        stratum_image_area(disklab::test::sample_polar_linear_radius_NOT_UNIFORM, 0.0, 1.0 / n,
                           double(j) / n, double(j + 1) / n, kQuadratureRel * expected);
    // Exact: (1/2)((j+1)^2 - j^2)/n^2 * (2 pi / n).
    const double exact = 0.5 * ((j + 1) * (j + 1) - j * j) / double(n * n) * (2 * kPi / n);
    EXPECT_NEAR(-a.area, exact, kAreaRel * exact) << "band " << j;
    if (std::fabs(std::fabs(a.area) - expected) / expected > kAreaRel) ++rejected;
  }
  // Band j has area (2j + 1) pi / n^3: none equals pi / n^2 when n = 4.
  EXPECT_EQ(rejected, n);
}

// ---- the area helper itself, on maps whose image areas are known in closed form ----

// A shear with a curved boundary, (u, v) -> (u, v + u^2): area-preserving, edges are parabolas.
Point2 shear(Point2 p) {
  return {p.x, p.y + p.x * p.x};
}
// (u, v) -> (u^2, v sin(u) + v): area of [u0,u1]x[v0,v1] is int 2u (1 + sin u) du * (v1 - v0).
Point2 warp(Point2 p) {
  return {p.x * p.x, p.y * (1.0 + std::sin(p.x))};
}

TEST(GreenArea, MatchesClosedFormsOnCurvedImages) {
  const AreaEstimate s = stratum_image_area(shear, 0.25, 0.75, 0.1, 0.6, kGreenTarget);
  EXPECT_NEAR(s.area, 0.25, kGreenCheck) << "error estimate " << s.error;
  const double u0 = 0.2, u1 = 1.3, v0 = 0.0, v1 = 2.0;
  // int 2u(1 + sin u) du = u^2 + 2(sin u - u cos u)
  auto F = [](double u) { return u * u + 2.0 * (std::sin(u) - u * std::cos(u)); };
  const double exact = (F(u1) - F(u0)) * (v1 - v0);
  const AreaEstimate w = stratum_image_area(warp, u0, u1, v0, v1, kGreenWarpTargetRel * exact);
  EXPECT_NEAR(w.area, exact, kGreenWarpCheckRel * exact) << "error estimate " << w.error;
  // A reflection reverses orientation: the signed area is negative.
  const AreaEstimate r = stratum_image_area(
      [](Point2 p) {
        return Point2{p.y, p.x};
      },
      0.0, 0.5, 0.0, 0.25, kGreenReflection);
  EXPECT_NEAR(r.area, -0.125, kGreenReflection);
}

TEST(DiskRectArea, TilesTheDiskAndMatchesKnownPieces) {
  // Whole disk, a half, a quadrant, a thin band through the centre, and an empty corner cell.
  EXPECT_NEAR(disklab::test::disk_rect_area(-2, 2, -2, 2), kPi, kDiskRectAbs);
  EXPECT_NEAR(disklab::test::disk_rect_area(0, 1, -1, 1), kPi / 2, kDiskRectAbs);
  EXPECT_NEAR(disklab::test::disk_rect_area(0, 1, 0, 1), kPi / 4, kDiskRectAbs);
  EXPECT_NEAR(disklab::test::disk_rect_area(0.9, 1.0, 0.9, 1.0), 0.0, 0.0);
  // The square inscribed in the disk is fully inside.
  const double h = std::sqrt(0.5);
  EXPECT_NEAR(disklab::test::disk_rect_area(-h, h, -h, h), 2.0, kDiskRectAbs);
  // A 37 x 37 grid (odd, cells straddling the axes and the rim) sums to pi.
  const int m = 37;
  double sum = 0.0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      sum += disklab::test::disk_rect_area(-1 + 2.0 * i / m, -1 + 2.0 * (i + 1) / m,
                                           -1 + 2.0 * j / m, -1 + 2.0 * (j + 1) / m);
  EXPECT_NEAR(sum, kPi, kDiskTilingAbs);
}

}  // namespace
