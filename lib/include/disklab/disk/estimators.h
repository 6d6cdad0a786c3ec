#pragma once
// Pad-zero and rejection (Christensen 2018, Sec. 3): estimators, not maps.
//
// Both scale the square to [-1,1]^2 (x = 2u - 1, y = 2v - 1). They differ in what happens to a
// point outside the unit disk, and the API makes that explicit:
//  - pad-zero keeps every square point and gives it a WEIGHT: 4/pi inside the disk, 0 outside
//    (the ratio of the domain areas), so that mean(weight * f(point)) over uniform square points
//    estimates the disk average (1/pi) int_D f dA without bias. The zero is the padding: no
//    shadow ray is traced for it, but it still counts as one of the N samples.
//  - rejection CONSUMES square points from a sequence until one lands in the disk; each accepted
//    point has weight 1 (it is uniform on the disk), and the number of square points it used is
//    reported, because a progressive sequence's later points shift along when points are
//    rejected. It loops over the sequence (never returns a zero sample with pdf 1/pi, which
//    would bias the estimate by the acceptance rate pi/4; see docs/design.md "Rejection must stay
//    unbiased"). A cap on the tries keeps a degenerate sequence from looping forever.
#include <cstdint>

#include "disklab/disk/common.h"
#include "disklab/types.h"

namespace disklab::disk {

// [0,1]^2 -> [-1,1]^2 and back. 2u is exact and 2u - 1 is exact for u >= 1/4 (Sterbenz).
inline Point2 square_to_centered(Point2 uv) {
  return {2.0 * clamp01(uv.x) - 1.0, 2.0 * clamp01(uv.y) - 1.0};
}
inline Point2 centered_to_square(Point2 p) {
  return {clamp01(0.5 * (p.x + 1.0)), clamp01(0.5 * (p.y + 1.0))};
}

// A point of [-1,1]^2 is in the disk when x^2 + y^2 <= 1 (closed: the rim counts as inside).
inline bool in_disk_exactly(Point2 p) {
  return p.x * p.x + p.y * p.y <= 1.0;
}

// ---- pad-zero ----

struct PadZeroSample {
  Point2 point;         // in [-1,1]^2, possibly outside the disk
  double weight = 0.0;  // 4/pi inside the disk, 0 outside
};

inline PadZeroSample sample_pad_zero(Point2 uv) {
  const Point2 p = square_to_centered(uv);
  return {p, in_disk_exactly(p) ? kFourOverPi : 0.0};
}

// ---- rejection ----

// One try with one square point.
struct RejectionTry {
  Point2 point;  // in [-1,1]^2
  bool accepted = false;
};
inline RejectionTry try_rejection(Point2 uv) {
  const Point2 p = square_to_centered(uv);
  return {p, in_disk_exactly(p)};
}

// Each try is accepted with probability pi/4 for uniform points, so 64 failures in a row happen
// with probability (1 - pi/4)^64 < 1e-42: the cap only stops degenerate sequences.
inline constexpr uint32_t kMaxRejectionTries = 64;

struct RejectionSample {
  Point2 point;           // uniform on the disk when accepted; the centre when not
  Point2 uv;              // the accepted square point (the last one tried when not accepted)
  uint32_t index = 0;     // sequence index of that square point
  uint32_t consumed = 0;  // square points used: the caller's next index is first + consumed
  bool accepted = false;  // false only when max_tries points in a row were outside
  double weight() const { return accepted ? 1.0 : 0.0; }
};

// Draws seq.at(first), seq.at(first + 1), ... until a point is inside the disk.
// Seq is anything with `Point2 at(uint32_t) const` (a concrete sequence or sequence::Sequence).
template <class Seq>
RejectionSample sample_rejection(const Seq& seq, uint32_t first,
                                 uint32_t max_tries = kMaxRejectionTries) {
  RejectionSample s;
  for (uint32_t t = 0; t < max_tries; ++t) {
    const uint32_t index = first + t;
    const Point2 uv = seq.at(index);
    const RejectionTry r = try_rejection(uv);
    s.uv = uv;
    s.index = index;
    s.consumed = t + 1;
    if (r.accepted) {
      s.point = r.point;
      s.accepted = true;
      return s;
    }
  }
  s.point = {0.0, 0.0};
  return s;
}

}  // namespace disklab::disk
