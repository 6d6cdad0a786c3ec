#pragma once
// Gamito 2016: uniform solid-angle sampling of a disk by rejection. Candidates are uniform in the
// solid angle of the square circumscribing the disk (Ureña et al. 2013, rectangle.h); those whose
// hit point falls outside the disk are rejected.
//
// Two unbiased ways to use it (docs/design.md section 3, "Rejection must stay unbiased"):
//  - sample(u, rng): the first candidate from u, further ones from rng until one is accepted;
//    the accepted direction is uniform on the disk's solid angle, pdf = 1/Omega;
//  - propose(u): one candidate; valid only if accepted, with the PROPOSAL density 1/S_square.
//    An estimator that counts rejections as zero and divides by 1/S_square is unbiased.
// The authors' code instead reports 1/Omega for the zero-on-rejection estimator, which scales
// the estimate by the acceptance rate (pi/4 for distant disks); the tests detect that.
#include <cmath>
#include <cstdint>

#include "disklab/ellipse/map_geometry.h"
#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/rectangle.h"
#include "disklab/ellipse/sampler.h"
#include "disklab/sequence/random.h"

namespace disklab::ellipse {

// Candidates tried by sample() before it gives up ("no sample"). The acceptance probability is at
// least ~pi/4 - O(r/d) and never tiny for disks in front of the point; 2^10 failures in a row
// happen with probability below (1 - 0.5)^1024: never in practice, and the cap keeps the hot path
// bounded.
inline constexpr int kGamitoMaxTries = 1024;

struct GamitoSampler {
  MapGeometry g;
  SphericalRectangle rect;
  double uniform_pdf = 0.0;  // 1/Omega, density of accepted samples

  // 1/S, the density of candidates (a division, not a member: the sampler's size stays that of
  // the other maps).
  double proposal_pdf() const { return 1.0 / rect.S; }

  static GamitoSampler make(const Disk& disk, const Vec3& o) noexcept {
    GamitoSampler s;
    s.g = MapGeometry::make(disk, o);
    if (s.g.empty) return s;
    // The square around the disk in R_d (rectangle.h), from the geometry's scalars: no world
    // coordinates, so its shape does not depend on where the scene sits.
    s.rect = SphericalRectangle::make(s.g.h / s.g.radius, s.g.e / s.g.radius);
    if (!s.rect.valid() || !std::isfinite(s.proposal_pdf())) {
      s.g.empty = true;
      return s;
    }
    s.uniform_pdf = 1.0 / s.g.omega;
    return s;
  }
  bool valid() const { return !g.empty; }

  // One candidate; valid == accepted; pdf is the proposal density.
  EllipseSample propose(Point2 u) const {
    if (g.empty || !in_unit_square(u)) return {};
    double X, Y, dy;  // dy: offset from the centre along -y_d, in radii
    rect.sample(u.x, u.y, X, Y, dy);
    const math::Frame d = g.disk_frame();
    EllipseSample out;
    // p - c = r (X x_d - dy y_d); p - o = r (X x_d - Y y_d + h z_d), formed from its parts (the
    // difference of world points would cancel for points close to the disk).
    const Vec3 pc = g.radius * (X * d.x - dy * d.y);
    out.point = g.center + pc;
    out.direction = unit_vector(X * d.x - Y * d.y + (g.h / g.radius) * d.z);
    // Local direction from the closed-form c - o and the small offset (accurate far away).
    out.local = unit_vector(g.center_local() + g.to_local(pc));
    out.pdf = proposal_pdf();
    out.valid =
        X * X + dy * dy <= 1.0 && out.direction.squaredNorm() > 0.0 && out.point.allFinite();
    // A rejected candidate is "no sample": its point off the disk can overflow (a huge disk) or
    // be NaN (0 * inf near the plane), so nothing of it is returned.
    return out.valid ? out : EllipseSample{};
  }

  // Density of a direction as an accepted candidate of propose(): the proposal density inside the
  // disk's solid angle, 0 outside (it integrates to the acceptance rate Omega / S). For
  // sample(u, rng) the density is uniform_pdf inside.
  double pdf(const Vec3& direction) const { return g.contains(direction) ? proposal_pdf() : 0.0; }

  // Loops until a candidate is accepted; pdf = 1/Omega. `tries` receives the candidates used.
  EllipseSample sample(Point2 u, sequence::Pcg32& rng, int* tries = nullptr) const {
    if (tries) *tries = 0;
    if (g.empty || !in_unit_square(u)) return {};
    Point2 v = u;
    for (int i = 1; i <= kGamitoMaxTries; ++i) {
      EllipseSample s = propose(v);
      if (s.valid) {
        if (tries) *tries = i;
        s.pdf = uniform_pdf;
        return s;
      }
      v = {rng.next_double(), rng.next_double()};
    }
    if (tries) *tries = kGamitoMaxTries;
    return {};
  }
};

}  // namespace disklab::ellipse
