#pragma once
// The contracts every spherical-ellipse map keeps (sampler.h, any_map.h), as one checker shared
// by the robustness tests, the adversarial suite, `disklab soak` and the fuzz harnesses. Not a
// hot path: it re-evaluates pdf, contains and the inverse of each sample.
//
// For a valid sample of a valid map:
//  - finite: direction, local, point and pdf are finite, and pdf > 0;
//  - unit: | |direction| - 1 | <= kUnitTol;
//  - on the disk: contains(direction), i.e. inside the spherical ellipse to the resolution of a
//    unit direction (map_geometry.h, kDirectionAbsError: a disk seen edge-on from within ~eps d
//    of its plane cannot be hit better than that), or, for a disk point at |x - o| << r, the
//    point is on the disk and the direction points at it to ~eps (r + |c - o|) / |x - o|, the
//    resolution of a direction formed from coordinates of that size;
//  - pdf: pdf(direction) equals the sample's pdf (uniform maps and gamito exactly; projected to
//    kProjectedPdfRel plus the cosine's resolution; tabulated
//    exactly unless the direction lies on a table cell's edge, where either cell's density is
//    accepted; area to kAreaPdfRel + 3 kDirectionAbsError / cos theta_l, the cosine of a unit
//    direction being known to an absolute ~eps only, and not at all where that bound reaches 1);
//  - inverse (maps that have one): invert(direction) exists, and sample(invert(direction)) points
//    the same way to kInverseAngleTol plus the direction's own resolution in the map's
//    coordinates, inverse_resolution(): a unit direction known to kDirectionAbsError fixes the
//    ellipse's thin coordinate only to ~kDirectionAbsError / b and, near the disk's plane, its
//    height above the rim to ~kDirectionAbsError / cos(alpha); the recovered u, and the direction
//    it maps to, inherit that (times the long semi-axis a). Where the resolution reaches pi (a
//    sliver 1e-300 thin, a point 1e-300 above the disk), nothing is required of the inverse; nor
//    at a tabulated cell's edge, where that map is discontinuous.
// A map that is not valid() gives no sample for every u.
#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "disklab/ellipse/any_map.h"
#include "disklab/math/frame.h"

namespace disklab::ellipse {

// |direction| is one correctly rounded normalization: a few ulps.
inline constexpr double kUnitTol = 8 * std::numeric_limits<double>::epsilon();
// area: sample() and pdf(direction) round |x - o| and the cosine differently (a few ulps each),
// on top of the cosine's resolution, which the check adds separately.
inline constexpr double kAreaPdfRel = 1e-12;
// projected: pdf(direction) renormalizes the direction before its cosine, a few ulps.
inline constexpr double kProjectedPdfRel = 8 * std::numeric_limits<double>::epsilon();
// A tabulated direction within this many radians (plus eps / rho at distance rho from the
// centre, where the azimuth is undefined) of a cell edge may be found in the neighbour cell.
inline constexpr double kCellEdgeSlack = 1e-12;
// The angle between a sample's direction and the one sample(invert(direction)) gives. The
// inverse and the root solves are exact to ~1e-15 in u; the forward maps' sensitivity to u is
// bounded by a few radians per unit of u except at the centre of the radial maps (eps2^(1/2)),
// where a 1e-15 change in u moves the direction by up to ~1e-8: 1e-7 leaves a margin of 10.
inline constexpr double kInverseAngleTol = 1e-7;

enum class Violation { none, non_finite, not_unit, miss, pdf_mismatch, inverse_failure, bad_pdf };

inline const char* violation_name(Violation v) {
  switch (v) {
    case Violation::none:
      return "none";
    case Violation::non_finite:
      return "non-finite field";
    case Violation::not_unit:
      return "direction not unit";
    case Violation::miss:
      return "direction misses the disk";
    case Violation::pdf_mismatch:
      return "pdf(direction) differs from the sample's pdf";
    case Violation::inverse_failure:
      return "inverse failed";
    case Violation::bad_pdf:
      return "pdf not positive";
  }
  return "?";
}

// Whether a tabulated direction lies on a cell edge to within what rounding can move it.
inline bool tabulated_near_cell_edge(const TabulatedMap& t, const Vec3& direction) {
  const Vec3 l = t.g.to_local(unit_vector(direction));
  const double phi = std::atan2(std::abs(l.y()), std::abs(l.x()));
  const double rho = std::hypot(l.x(), l.y());
  const double slack = kCellEdgeSlack + 16 * std::numeric_limits<double>::epsilon() / rho;
  for (int j = 0; j <= t.table->n_eps; ++j)
    if (std::abs(phi - t.phi_at(j)) <= slack) return true;
  return false;
}

// The absolute error of an area sample's direction: kDirectionAbsError, or more for a disk point
// close to o, whose direction comes from coordinates of size r + |c - o| relative to o: a
// difference of that size known to ~eps, over the distance |x - o|.
inline double area_direction_error(const MapGeometry& g, const EllipseSample& s) {
  const double dist = math::safe_norm(s.point - g.origin);
  const double scale = g.radius + math::safe_norm(g.center - g.origin);
  return kDirectionAbsError * std::max(1.0, scale / dist);
}

// For a disk point close to o (|x - o| << r) the direction is known only to
// area_direction_error: the sample then keeps the "on the disk" contract if its point lies on the
// disk to its coordinates' rounding and its direction points at it to that error.
inline bool points_at_its_disk_point(const MapGeometry& g, const EllipseSample& s) {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const Vec3 off = s.point - g.center;
  const double scale = g.center.cwiseAbs().maxCoeff() + g.radius;
  if (!(math::safe_norm(off) <= g.radius + 16 * kEps * scale)) return false;
  if (!(std::abs(off.dot(g.normal)) <= 16 * kEps * scale)) return false;
  const Vec3 to_point = unit_vector(s.point - g.origin);
  return (to_point - s.direction).norm() <= 16 * area_direction_error(g, s);
}

// The first violated contract of sample s of map m (Violation::none if it keeps them all). An
// invalid sample keeps them trivially.
inline Violation check_sample(const AnyMap& m, const EllipseSample& s) {
  if (!s.valid) return Violation::none;
  if (!s.direction.allFinite() || !s.local.allFinite() || !s.point.allFinite() ||
      !std::isfinite(s.pdf))
    return Violation::non_finite;
  if (!(s.pdf > 0.0)) return Violation::bad_pdf;
  if (!(std::abs(s.direction.norm() - 1.0) <= kUnitTol)) return Violation::not_unit;
  if (!m.contains(s.direction)) {
    // On the rim to the direction's resolution: pdf(direction) may then read either side of it.
    return points_at_its_disk_point(m.geometry(), s) ? Violation::none : Violation::miss;
  }
  const double p = m.pdf(s.direction);
  if (m.kind() == MapKind::area) {
    const double cos_light = std::abs(s.direction.dot(m.geometry().normal));
    const double tol = kAreaPdfRel + 3.0 * area_direction_error(m.geometry(), s) / cos_light;
    // Where the cosine is no larger than its own resolution the direction does not fix it, nor
    // the density (a point within ~eps d of the disk's plane): nothing to compare.
    if (tol < 1.0 && !(std::abs(p - s.pdf) <= tol * s.pdf)) return Violation::pdf_mismatch;
  } else if (m.kind() == MapKind::tabulated) {
    if (p != s.pdf && !tabulated_near_cell_edge(std::get<TabulatedMap>(m.variant()), s.direction))
      return Violation::pdf_mismatch;
  } else if (m.kind() == MapKind::projected) {
    // cos(w, n_o) / P from a direction renormalized in pdf(direction): a few ulps, plus the
    // cosine's resolution kDirectionAbsError near the receiver's horizon.
    const double cosine = s.pdf * std::get<ProjectedMap>(m.variant()).projected_solid_angle();
    const double tol = kProjectedPdfRel + kDirectionAbsError / cosine;
    if (tol < 1.0 && !(std::abs(p - s.pdf) <= tol * s.pdf)) return Violation::pdf_mismatch;
  } else if (p != s.pdf) {
    return Violation::pdf_mismatch;
  }
  return Violation::none;
}

// Multiple of kDirectionAbsError (a / b + 1 / cos(alpha)) the inverse may be off by in angle:
// the factor covers the maps' gradients (at most ~2 pi per unit of the thin coordinate's
// fraction) with a margin.
inline constexpr double kResolutionFactor = 64;
inline double inverse_resolution(const MapGeometry& g) {
  return kResolutionFactor * kDirectionAbsError * (g.a / g.b + 1.0 / g.cos_alpha);
}

// The inverse contract for a valid sample (none for maps without an inverse).
inline Violation check_inverse(const AnyMap& m, const EllipseSample& s) {
  if (!s.valid || !m.has_inverse()) return Violation::none;
  // invert() answers only where contains() is true; a sample outside it is on the rim to the
  // direction's resolution (check_sample's rule), where there is no inverse to ask for.
  if (!m.contains(s.direction)) return Violation::none;
  const MapGeometry& g = m.geometry();
  double resolution = inverse_resolution(g);
  if (m.kind() == MapKind::area) {
    // area inverts through the hit point, which a direction fixes only to ~its error times
    // |x - o| / cos(theta_l) in the plane: relative to r, the documented bound of area.h.
    const double cos_light = std::abs(s.direction.dot(g.normal));
    const double dist = math::safe_norm(s.point - g.origin);
    const double hit_error = area_direction_error(g, s) * dist / (cos_light * g.radius);
    if (!(hit_error < 1e-6)) return Violation::none;
    // The hit's error over |x - o|, seen from o: the direction's error over cos(theta_l).
    resolution += kResolutionFactor * area_direction_error(g, s) / cos_light;
  }
  // tabulated scales eps2 by its cell's bound, so the map jumps across a cell edge: there the
  // inverse may answer for the neighbour cell (as pdf(direction) may), a different u and direction.
  if (m.kind() == MapKind::tabulated &&
      tabulated_near_cell_edge(std::get<TabulatedMap>(m.variant()), s.direction))
    return Violation::none;
  if (!(resolution < math::kPi)) return Violation::none;
  const auto u = m.invert(s.direction);
  if (!u || !(u->x >= 0.0 && u->x <= 1.0 && u->y >= 0.0 && u->y <= 1.0))
    return Violation::inverse_failure;
  const EllipseSample back = m.sample(*u);
  if (!back.valid) {
    // A rejection map's inverse may land on a rejected candidate only within rounding of the rim.
    return m.kind() == MapKind::tabulated ? Violation::none : Violation::inverse_failure;
  }
  const double angle = 2.0 * std::asin(std::min(1.0, 0.5 * (back.direction - s.direction).norm()));
  return angle <= kInverseAngleTol + resolution ? Violation::none : Violation::inverse_failure;
}

}  // namespace disklab::ellipse
