#pragma once
// radial4 (beyond both seed papers): Christensen's polar4 idea applied to the radial map. The
// spherical ellipse is mirror-symmetric about the x_e and y_e planes (not rotation-symmetric), so
// each square sample is mapped into the first quadrant (eps1 = the quadrant's cumulative
// fraction, eps2 as in radial.h) and reused in all four quadrants through the reflections
// (x, y) -> (+-x, +-y). Each of the four directions has pdf 1/Omega; one root solve serves four
// samples (sample4). A single sample (sample) is a full-ellipse one: the radial map itself, so an
// estimator that draws one direction per u stays unbiased.
#include <array>

#include "disklab/ellipse/radial.h"

namespace disklab::ellipse {

struct Radial4Map {
  RadialMap radial;

  static Radial4Map make(const Disk& disk, const Vec3& o) noexcept {
    return Radial4Map{RadialMap::make(disk, o)};
  }
  bool valid() const { return radial.valid(); }
  double pdf(const Vec3& direction) const { return radial.pdf(direction); }

  // One full-ellipse sample and its inverse (the radial map's).
  EllipseSample sample(Point2 u, int* iterations = nullptr) const {
    return radial.sample(u, iterations);
  }
  Point2 invert_local(const Vec3& l) const { return radial.invert_local(l); }
  Point2 invert(const Vec3& direction) const { return radial.invert(direction); }

  // The first-quadrant point of u (the map [0,1]^2 -> quadrant 0, measure Omega/4).
  EllipseSample sample_quadrant(Point2 u, int* iterations = nullptr) const {
    if (iterations) *iterations = 0;
    if (!radial.valid() || !in_unit_square(u)) return {};
    const RadialQuadrant q = radial.quadrant();
    const RadialQuadrant::Angle s = q.solve(std::clamp(u.x, 0.0, 1.0), iterations);
    return finish_sample(radial.g, q.local_point(0, s, std::clamp(u.y, 0.0, 1.0)),
                         radial.uniform_pdf);
  }

  // The four reflections of sample_quadrant(u), counter-clockwise from quadrant 0.
  std::array<EllipseSample, 4> sample4(Point2 u, int* iterations = nullptr) const {
    std::array<EllipseSample, 4> out{};
    const EllipseSample s0 = sample_quadrant(u, iterations);
    if (!s0.valid) return out;
    const Vec3 l = s0.local;
    const std::array<Vec3, 4> locals = {l, Vec3(-l.x(), l.y(), l.z()), Vec3(-l.x(), -l.y(), l.z()),
                                        Vec3(l.x(), -l.y(), l.z())};
    out[0] = s0;
    for (int k = 1; k < 4; ++k)
      out[k] = finish_sample(radial.g, locals[k], radial.uniform_pdf);
    return out;
  }

  // Inverse of sample4: the u of which a direction (any quadrant) is a copy, and which copy
  // (its quadrant k, counter-clockwise from +x_e).
  Point2 invert_copy_local(const Vec3& l, int& k) const {
    return radial.quadrant().invert_local(l, k);  // folds |x|, |y| and reports the quadrant
  }
};

}  // namespace disklab::ellipse
