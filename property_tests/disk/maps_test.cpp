// Bijectivity, equivalences and edge cases of the planar maps (Christensen 2018, Sec. 3 and
// Appendix A; Shirley and Chiu 1997; the seed blog's one-branch concentric form).
//
// Replay a failing property with RC_PARAMS="seed=<seed printed by rapidcheck>".
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "disklab/disk/concentric.h"
#include "disklab/disk/polar.h"
#include "disklab/math/constants.h"
#include "disklab/sequence/random.h"

namespace {
using disklab::Point2;
using namespace disklab::disk;
namespace math = disklab::math;

// ---- Tolerances (the one place for this suite) ----
constexpr double kEps = 0x1p-52;  // ulp(1)
// Round trip u -> x -> u'. Each map is a handful of correctly rounded or <= 1-ulp operations
// (sqrt, cos, sin, atan/atan2, hypot, one division, a few products). Disk points have magnitude
// <= 1 and the inverses are well conditioned in absolute terms (atan2 gives the angle to ~1 ulp
// whatever the radius; the concentric ratios b/a, a/b are <= 1 in magnitude), so each step adds
// at most a few ulp(1) of absolute error: 8 ulp(1) bounds the chain with margin, and a wrong
// formula (a swapped region, a missing sqrt) is off by O(1).
constexpr double kRoundTripAbs = 8.0 * kEps;
// u = r^2 of the polar maps is computed as x*x + y*y from coordinates with relative error
// <= ~2.5 ulp each, so u keeps a RELATIVE accuracy of ~5 ulp: 8 ulp relative, at every radius.
constexpr double kPolarURel = 8.0 * kEps;
// Below this u the coordinates sqrt(u) cos(phi) become subnormal and their squares underflow:
// the angle (v) is no longer carried by the point; the centre is one point for every v.
constexpr double kTinyU = 1e-290;
// Two implementations of the same formula (blog vs paper form; the memo's phi + k pi/2 vs an
// exact rotation) differ by the rounding of an angle near 2 pi: ulp(2 pi) ~ 8.9e-16 < 8 ulp(1).
constexpr double kSameMapAbs = 8.0 * kEps;

double dist(Point2 a, Point2 b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}
// v of the full polar map is an angle: 0 and 1 are the same seam.
double periodic_dist(double a, double b) {
  const double d = std::fabs(a - b);
  return std::fmin(d, 1.0 - d);
}
bool finite(Point2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}
std::string str(Point2 p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
  return buf;
}

// Edges, the centre (u = 1/2 for concentric) and its neighbours, quadrant seams.
const std::vector<double> kSpecial = {
    0.0,  0x1p-1074,     1e-300, 1e-17,         0x1p-53, 0.125,         0.25 - 0x1p-54,
    0.25, 0.5 - 0x1p-54, 0.5,    0.5 + 0x1p-53, 0.75,    1.0 - 0x1p-20, math::kOneMinusEpsilon,
    1.0};

// A unit-interval double: 53-bit uniform, or one of the special values.
rc::Gen<double> gen_unit() {
  return rc::gen::weightedOneOf<double>(
      {{4, rc::gen::map(rc::gen::inRange<uint64_t>(0, (uint64_t{1} << 53) + 1),
                        [](uint64_t k) { return static_cast<double>(k) * 0x1p-53; })},
       {1, rc::gen::elementOf(kSpecial)}});
}
rc::Gen<Point2> gen_uv() {
  return rc::gen::apply([](double u, double v) { return Point2{u, v}; }, gen_unit(), gen_unit());
}
// A point of the closed unit disk: a square point rejected until inside, plus the centre, the
// axes and the rim.
rc::Gen<Point2> gen_disk_point() {
  auto square = rc::gen::suchThat(rc::gen::apply(
                                      [](double a, double b) {
                                        return Point2{2.0 * a - 1.0, 2.0 * b - 1.0};
                                      },
                                      gen_unit(), gen_unit()),
                                  [](Point2 p) { return p.x * p.x + p.y * p.y <= 1.0; });
  auto special = rc::gen::elementOf(std::vector<Point2>{{0.0, 0.0},
                                                        {1.0, 0.0},
                                                        {0.0, 1.0},
                                                        {-1.0, 0.0},
                                                        {0.0, -1.0},
                                                        {-0.0, -0.0},
                                                        {0.5, -0.0},
                                                        {-0.5, -0.0},
                                                        {1e-300, -1e-300},
                                                        {0.6, 0.8},
                                                        {-0.6, 0.8},
                                                        {0.5, 0.5},
                                                        {-0.5, -0.5}});
  return rc::gen::weightedOneOf<Point2>({{4, square}, {1, special}});
}
Point2 first_quadrant(Point2 p) {
  return {std::fabs(p.x), std::fabs(p.y)};
}

// ---- polar ----

void check_polar_uv(Point2 uv) {
  const Point2 p = sample_polar(uv);
  const Point2 back = invert_polar(p);
  const std::string chain = "uv=" + str(uv) + " -> p=" + str(p) + " -> uv'=" + str(back);
  RC_ASSERT(finite(p));
  RC_ASSERT(std::fabs(back.x - uv.x) <= kPolarURel * uv.x + 0x1p-1022);
  if (uv.x >= kTinyU) {
    if (!(periodic_dist(back.y, uv.y) <= kRoundTripAbs)) RC_FAIL(chain);
  }
  RC_ASSERT(back.x >= 0.0 && back.x <= 1.0 && back.y >= 0.0 && back.y <= 1.0);
}

RC_GTEST_PROP(Polar, InverseOfForwardIsIdentity, ()) {
  check_polar_uv(*gen_uv());
}

RC_GTEST_PROP(Polar, ForwardOfInverseIsIdentity, ()) {
  const Point2 p = *gen_disk_point();
  const Point2 uv = invert_polar(p);
  const Point2 q = sample_polar(uv);
  RC_ASSERT(finite(q));
  if (!(dist(p, q) <= kRoundTripAbs))
    RC_FAIL("p=" + str(p) + " -> uv=" + str(uv) + " -> p'=" + str(q));
}

RC_GTEST_PROP(PolarQuarter, InverseOfForwardIsIdentity, ()) {
  const Point2 uv = *gen_uv();
  const Point2 q = sample_polar_quarter(uv);
  const Point2 back = invert_polar_quarter(q);
  RC_ASSERT(finite(q) && q.x >= 0.0 && q.y >= 0.0);
  RC_ASSERT(std::fabs(back.x - uv.x) <= kPolarURel * uv.x + 0x1p-1022);
  if (uv.x >= kTinyU && !(std::fabs(back.y - uv.y) <= kRoundTripAbs))
    RC_FAIL("uv=" + str(uv) + " -> q=" + str(q) + " -> uv'=" + str(back));
}

RC_GTEST_PROP(PolarQuarter, ForwardOfInverseIsIdentity, ()) {
  const Point2 p = first_quadrant(*gen_disk_point());
  const Point2 uv = invert_polar_quarter(p);
  const Point2 q = sample_polar_quarter(uv);
  if (!(dist(p, q) <= kRoundTripAbs))
    RC_FAIL("p=" + str(p) + " -> uv=" + str(uv) + " -> p'=" + str(q));
}

// Appendix A as printed: phi = (pi/2) v + (pi/2) (s mod 4), in polar coordinates.
RC_GTEST_PROP(Polar4, EqualsTheMemoPseudocode, ()) {
  const Point2 uv = *gen_uv();
  const auto pts = sample_polar4(uv);
  for (int k = 0; k < 4; ++k) {
    const double r = std::sqrt(uv.x);
    const double phi = 0.5 * math::kPi * uv.y + 0.5 * math::kPi * k;
    const Point2 memo{r * std::cos(phi), r * std::sin(phi)};
    if (!(dist(pts[k], memo) <= kSameMapAbs))
      RC_FAIL("uv=" + str(uv) + " k=" + std::to_string(k) + " lib=" + str(pts[k]) +
              " memo=" + str(memo));
  }
}

// Each copy inverts to the same square point and names its own copy index.
template <class Sample4, class Invert4>
void check_four_copy_inverse(Sample4 sample4, Invert4 invert4, Point2 uv, bool polar_v) {
  const auto pts = sample4(uv);
  const bool centre = pts[0].x == 0.0 && pts[0].y == 0.0;
  for (uint32_t k = 0; k < 4; ++k) {
    const Inverse4 inv = invert4(pts[k]);
    const std::string chain = "uv=" + str(uv) + " copy " + std::to_string(k) + " p=" + str(pts[k]) +
                              " -> uv'=" + str(inv.uv) + " k'=" + std::to_string(inv.k);
    RC_ASSERT(finite(pts[k]));
    if (centre) continue;  // all four copies are the centre: any k is right
    if (inv.k != k) {
      // A point exactly on an axis lies on the seam shared by two copies' closures (the quarter
      // maps send an edge of the square onto the axis; only cos(pi/2) ~ 6e-17 normally keeps it
      // off, and that underflows for radii below ~1e-307). There the inverse may name the
      // neighbour, provided its square point reproduces the same disk point.
      const bool seam = pts[k].x == 0.0 || pts[k].y == 0.0;
      if (!seam || !(dist(sample4(inv.uv)[inv.k], pts[k]) <= kRoundTripAbs)) RC_FAIL(chain);
      continue;
    }
    const double du = polar_v ? std::fabs(inv.uv.x - uv.x) - kPolarURel * uv.x
                              : std::fabs(inv.uv.x - uv.x) - kRoundTripAbs;
    if (!(du <= 0x1p-1022)) RC_FAIL(chain);
    if ((!polar_v || uv.x >= kTinyU) && !(std::fabs(inv.uv.y - uv.y) <= kRoundTripAbs))
      RC_FAIL(chain);
  }
}

RC_GTEST_PROP(Polar4, EveryCopyInvertsToItsSquarePointAndIndex, ()) {
  check_four_copy_inverse(sample_polar4, invert_polar4, *gen_uv(), true);
}

RC_GTEST_PROP(Concentric4, EveryCopyInvertsToItsSquarePointAndIndex, ()) {
  check_four_copy_inverse(sample_concentric4, invert_concentric4, *gen_uv(), false);
}

// ---- concentric ----

RC_GTEST_PROP(Concentric, InverseOfForwardIsIdentity, ()) {
  const Point2 uv = *gen_uv();
  const Point2 p = sample_concentric(uv);
  const Point2 back = invert_concentric(p);
  RC_ASSERT(finite(p));
  if (!(dist(uv, back) <= kRoundTripAbs))
    RC_FAIL("uv=" + str(uv) + " -> p=" + str(p) + " -> uv'=" + str(back));
}

RC_GTEST_PROP(Concentric, ForwardOfInverseIsIdentity, ()) {
  const Point2 p = *gen_disk_point();
  const Point2 uv = invert_concentric(p);
  const Point2 q = sample_concentric(uv);
  if (!(dist(p, q) <= kRoundTripAbs))
    RC_FAIL("p=" + str(p) + " -> uv=" + str(uv) + " -> p'=" + str(q));
}

RC_GTEST_PROP(ConcentricQuarter, InverseOfForwardIsIdentity, ()) {
  const Point2 uv = *gen_uv();
  const Point2 q = sample_concentric_quarter(uv);
  const Point2 back = invert_concentric_quarter(q);
  RC_ASSERT(finite(q) && q.x >= 0.0 && q.y >= 0.0);
  if (!(dist(uv, back) <= kRoundTripAbs))
    RC_FAIL("uv=" + str(uv) + " -> q=" + str(q) + " -> uv'=" + str(back));
}

RC_GTEST_PROP(ConcentricQuarter, ForwardOfInverseIsIdentity, ()) {
  const Point2 p = first_quadrant(*gen_disk_point());
  const Point2 uv = invert_concentric_quarter(p);
  const Point2 q = sample_concentric_quarter(uv);
  if (!(dist(p, q) <= kRoundTripAbs))
    RC_FAIL("p=" + str(p) + " -> uv=" + str(uv) + " -> p'=" + str(q));
}

// The seed blog's one-branch form (Cline's variant), transcribed with r = 1. The blog guards
// R1 == 0 && R2 == 0, i.e. the CORNER (a, b) = (-1, -1), which needs no guard, and leaves the
// centre a = b = 0 to divide 0 by 0. `as_printed` keeps that guard; otherwise the guard is
// moved to the centre, which is the one-branch formula proper.
Point2 blog_concentric(Point2 uv, bool as_printed = false) {
  const double R1 = uv.x, R2 = uv.y;
  if (as_printed && R1 == 0 && R2 == 0) return {0.0, 0.0};
  if (!as_printed && R1 == 0.5 && R2 == 0.5) return {0.0, 0.0};
  double phi = 0, radius = 1.0;
  const double a = (2 * R1) - 1;
  const double b = (2 * R2) - 1;
  if ((a * a) > (b * b)) {
    radius *= a;
    phi = (math::kPi / 4) * (b / a);
  } else {
    radius *= b;
    phi = (math::kPi / 2) - ((math::kPi / 4) * (a / b));
  }
  return {std::cos(phi) * radius, std::sin(phi) * radius};
}

// The two forms are one map: region 3 (r = -a, phi + pi) is the blog's negative radius, and on
// the diagonals both formulas are continuous so the tie-breaking does not matter.
RC_GTEST_PROP(Concentric, BlogOneBranchFormIsTheSameMap, ()) {
  const Point2 uv = *gen_uv();
  const Point2 lib = sample_concentric(uv), blog = blog_concentric(uv);
  if (!(dist(lib, blog) <= kSameMapAbs))
    RC_FAIL("uv=" + str(uv) + " lib=" + str(lib) + " blog=" + str(blog));
}

// Seams: the diagonals a = +-b (region boundaries) and the two axes through the centre.
RC_GTEST_PROP(Concentric, SameMapOnTheSeams, ()) {
  const double t = *gen_unit();
  for (Point2 uv : {Point2{t, t}, Point2{t, 1.0 - t}, Point2{t, 0.5}, Point2{0.5, t}}) {
    const Point2 lib = sample_concentric(uv), blog = blog_concentric(uv);
    const Point2 back = invert_concentric(lib);
    if (!(dist(lib, blog) <= kSameMapAbs) || !(dist(back, uv) <= kRoundTripAbs))
      RC_FAIL("uv=" + str(uv) + " lib=" + str(lib) + " blog=" + str(blog) + " uv'=" + str(back));
  }
}

TEST(Concentric, CentreIsDefinedWhereTheBlogAsPrintedFails) {
  const Point2 centre{0.5, 0.5};
  const Point2 lib = sample_concentric(centre);
  EXPECT_EQ(lib.x, 0.0);
  EXPECT_EQ(lib.y, 0.0);
  const Point2 back = invert_concentric({0.0, 0.0});
  EXPECT_EQ(back.x, 0.5);
  EXPECT_EQ(back.y, 0.5);
  // The blog as printed: 0/0 at the centre, and its guard sends the corner (0, 0) to the centre
  // although the formula maps it to the rim point at 225 degrees, as the library does.
  const Point2 blog_centre = blog_concentric(centre, true);
  EXPECT_TRUE(std::isnan(blog_centre.x) || std::isnan(blog_centre.y)) << str(blog_centre);
  const Point2 corner = sample_concentric({0.0, 0.0});
  EXPECT_LE(dist(corner, {-std::sqrt(0.5), -std::sqrt(0.5)}), kSameMapAbs) << str(corner);
  EXPECT_LE(dist(corner, blog_concentric({0.0, 0.0})), kSameMapAbs);
  const Point2 blog_corner = blog_concentric({0.0, 0.0}, true);
  EXPECT_EQ(blog_corner.x, 0.0);
  EXPECT_EQ(blog_corner.y, 0.0);
}

// ---- adversarial grid: every pair of special values, every map ----

TEST(Maps, SpecialInputsGiveFiniteRoundTrips) {
  for (double u : kSpecial) {
    for (double v : kSpecial) {
      const Point2 uv{u, v};
      SCOPED_TRACE("uv=" + str(uv));
      const Point2 pp = sample_polar(uv), pc = sample_concentric(uv);
      const Point2 qp = sample_polar_quarter(uv), qc = sample_concentric_quarter(uv);
      for (Point2 p : {pp, pc, qp, qc}) {
        ASSERT_TRUE(finite(p)) << str(p);
        EXPECT_LE(p.x * p.x + p.y * p.y, 1.0 + kRimSlack) << str(p);
      }
      const Point2 bp = invert_polar(pp);
      EXPECT_LE(std::fabs(bp.x - u), kPolarURel * u + 0x1p-1022) << "p=" << str(pp);
      if (u >= kTinyU) {
        EXPECT_LE(periodic_dist(bp.y, v), kRoundTripAbs) << "p=" << str(pp);
      }
      EXPECT_LE(dist(invert_concentric(pc), uv), kRoundTripAbs) << "p=" << str(pc);
      EXPECT_LE(dist(invert_concentric_quarter(qc), uv), kRoundTripAbs) << "q=" << str(qc);
      const Point2 bq = invert_polar_quarter(qp);
      EXPECT_LE(std::fabs(bq.x - u), kPolarURel * u + 0x1p-1022) << "q=" << str(qp);
      if (u >= kTinyU) {
        EXPECT_LE(std::fabs(bq.y - v), kRoundTripAbs) << "q=" << str(qp);
      }
    }
  }
}

TEST(Maps, CentreAndDegenerateInputsHaveDefinedInverses) {
  const Point2 zero{0.0, 0.0}, negzero{-0.0, -0.0};
  for (Point2 c : {zero, negzero}) {
    EXPECT_EQ(invert_polar(c).x, 0.0);
    EXPECT_EQ(invert_polar(c).y, 0.0);
    EXPECT_EQ(invert_polar_quarter(c).x, 0.0);
    EXPECT_EQ(invert_polar_quarter(c).y, 0.0);
    EXPECT_EQ(invert_concentric_quarter(c).x, 0.0);
    EXPECT_EQ(invert_concentric(c).x, 0.5);
    EXPECT_EQ(invert_polar4(c).k, 0u);
  }
  // -0.0 in y on the positive x axis is angle 0, not 2 pi: v = +0.
  EXPECT_EQ(invert_polar({0.5, -0.0}).y, 0.0);
  EXPECT_FALSE(std::signbit(invert_polar({0.5, -0.0}).y));
  // NaN in, finite out (inverses clamp; samplers clamp their inputs).
  const double nan = std::nan("");
  for (Point2 r : {invert_polar({nan, nan}), invert_concentric({nan, nan}),
                   invert_polar_quarter({nan, 0.5}), invert_concentric_quarter({nan, nan}),
                   sample_polar({nan, nan}), sample_concentric({nan, nan}),
                   sample_polar_quarter({nan, nan}), sample_concentric_quarter({nan, nan})})
    EXPECT_TRUE(finite(r)) << str(r);
  // Points slightly outside the disk (rounding) invert onto the rim, not past u = 1.
  EXPECT_EQ(invert_polar({1.0 + 4 * kEps, 0.0}).x, 1.0);
  EXPECT_EQ(invert_concentric({1.0 + 4 * kEps, 0.0}).x, 1.0);
}

TEST(Maps, PdfsAreTheUniformDensitiesWithRespectToArea) {
  EXPECT_EQ(pdf_polar({0.3, 0.4}), 1.0 / math::kPi);
  EXPECT_EQ(pdf_concentric({-0.3, 0.4}), 1.0 / math::kPi);
  EXPECT_EQ(pdf_polar({0.8, 0.8}), 0.0);
  EXPECT_EQ(pdf_polar_quarter({0.3, 0.4}), 4.0 / math::kPi);
  EXPECT_EQ(pdf_polar_quarter({-0.3, 0.4}), 0.0);
  EXPECT_EQ(pdf_concentric_quarter({0.3, -0.4}), 0.0);
  // Every sample the maps produce on the rim counts as inside.
  for (double v : kSpecial) {
    EXPECT_GT(pdf_polar(sample_polar({1.0, v})), 0.0);
    EXPECT_GT(pdf_concentric(sample_concentric({1.0, v})), 0.0);
    EXPECT_GT(pdf_concentric_quarter(sample_concentric_quarter({1.0, v})), 0.0);
    EXPECT_GT(pdf_polar_quarter(sample_polar_quarter({1.0, v})), 0.0);
  }
}

TEST(Quadrant, FoldUndoesEveryRotationExactly) {
  const std::vector<Point2> qs = {{0.25, 0.5}, {0.7, 0.0}, {0.0, 0.7}, {1e-300, 2e-300}};
  for (Point2 q : qs) {
    for (uint32_t k = 0; k < 4; ++k) {
      const Point2 p = rotate_quarter_turns(q, k);
      SCOPED_TRACE("q=" + str(q) + " k=" + std::to_string(k));
      const Folded f = fold_to_first_quadrant(p);
      // Points on an axis belong to the half-open quadrant counter-clockwise of it: a point on
      // the +y axis is copy 1 of a +x-axis point, so the (q, k) pair may shift by one turn.
      const Point2 back = rotate_quarter_turns(f.q, f.k);
      EXPECT_EQ(back.x, p.x + 0.0);
      EXPECT_EQ(back.y, p.y + 0.0);
      EXPECT_GE(f.q.x, 0.0);
      EXPECT_GE(f.q.y, 0.0);
      if (q.x > 0.0 && q.y > 0.0) {
        EXPECT_EQ(f.k, k);
      }
    }
  }
}

// ---- a dense sweep: 2^20 random square points and 2^20 random disk points per map ----
// rapidcheck tries ~100 cases per property; this sweep backs the same tolerances with a million
// and reports the worst error found, in ulps of 1 (absolute) or of u (relative, polar u).
constexpr uint32_t kSweep = 1u << 20;

struct Worst {
  double err = 0.0;
  Point2 at;
  void update(double e, Point2 where) {
    if (e > err) {
      err = e;
      at = where;
    }
  }
};

TEST(Sweep, RoundTripErrorsStayWithinTheArguedBounds) {
  const disklab::sequence::RandomSequence seq(12345);
  Worst polar_u, polar_v, pq_v, conc, cq, fwd_polar, fwd_conc, fwd_pq, fwd_cq;
  for (uint32_t i = 0; i < kSweep; ++i) {
    const Point2 uv = seq.at(i);
    const Point2 bp = invert_polar(sample_polar(uv));
    polar_u.update(std::fabs(bp.x - uv.x) / uv.x, uv);
    polar_v.update(periodic_dist(bp.y, uv.y), uv);
    pq_v.update(std::fabs(invert_polar_quarter(sample_polar_quarter(uv)).y - uv.y), uv);
    conc.update(dist(invert_concentric(sample_concentric(uv)), uv), uv);
    cq.update(dist(invert_concentric_quarter(sample_concentric_quarter(uv)), uv), uv);
    const Point2 p = {2.0 * uv.x - 1.0, 2.0 * uv.y - 1.0};
    if (p.x * p.x + p.y * p.y > 1.0) continue;
    fwd_polar.update(dist(sample_polar(invert_polar(p)), p), p);
    fwd_conc.update(dist(sample_concentric(invert_concentric(p)), p), p);
    const Point2 q = first_quadrant(p);
    fwd_pq.update(dist(sample_polar_quarter(invert_polar_quarter(q)), q), q);
    fwd_cq.update(dist(sample_concentric_quarter(invert_concentric_quarter(q)), q), q);
  }
  struct Line {
    const char* what;
    const Worst& w;
    double bound;
  };
  const Line lines[] = {{"polar u (relative)", polar_u, kPolarURel},
                        {"polar v (periodic)", polar_v, kRoundTripAbs},
                        {"polar-quarter v", pq_v, kRoundTripAbs},
                        {"concentric uv", conc, kRoundTripAbs},
                        {"concentric-quarter uv", cq, kRoundTripAbs},
                        {"polar x from disk point", fwd_polar, kRoundTripAbs},
                        {"concentric x from disk point", fwd_conc, kRoundTripAbs},
                        {"polar-quarter x", fwd_pq, kRoundTripAbs},
                        {"concentric-quarter x", fwd_cq, kRoundTripAbs}};
  for (const Line& l : lines) {
    std::printf("  %-30s worst %.2f ulp (bound %.0f) at %s\n", l.what, l.w.err / kEps,
                l.bound / kEps, str(l.w.at).c_str());
    EXPECT_LE(l.w.err, l.bound) << l.what << " at " << str(l.w.at);
  }
}

}  // namespace
