#pragma once
// Quarter-turn rotations shared by polar4 and concentric4 (Christensen 2018, Appendix A).
//
// The memo's pseudocode adds k pi/2 to phi. Rotating the Cartesian point instead,
// (x, y) -> (-y, x), is exact (a swap and a sign flip): the four copies are exact rotations of
// each other, with no cos/sin of a shifted angle to round differently.
#include <array>
#include <cstdint>

#include "disklab/types.h"

namespace disklab::disk {

// Rotates p counter-clockwise by k quarter turns (k taken mod 4). Exact.
inline Point2 rotate_quarter_turns(Point2 p, uint32_t k) {
  switch (k & 3u) {
    case 0:
      return p;
    case 1:
      return {-p.y, p.x};
    case 2:
      return {-p.x, -p.y};
    default:
      return {p.y, -p.x};
  }
}

// The four copies of a first-quadrant point: copy k is rotated by k * 90 degrees.
inline std::array<Point2, 4> four_rotations(Point2 q) {
  return {rotate_quarter_turns(q, 0), rotate_quarter_turns(q, 1), rotate_quarter_turns(q, 2),
          rotate_quarter_turns(q, 3)};
}

// A disk point folded into the closed first quadrant, and the copy index k that unfolds it:
// rotate_quarter_turns(q, k) == p (up to the sign of zeros).
struct Folded {
  Point2 q;
  uint32_t k = 0;
};

// Half-open quadrants so every point has exactly one k: k=0 holds x > 0, y >= 0; k=1 holds
// x <= 0, y > 0; and so on counter-clockwise. The centre folds to itself with k = 0.
// Zeros come out as +0.0 so inverse maps never see -0.0 (atan2 would give -pi for it).
inline Folded fold_to_first_quadrant(Point2 p) {
  Folded f;
  if (p.x > 0.0 && p.y >= 0.0) {
    f = {p, 0};
  } else if (p.x <= 0.0 && p.y > 0.0) {
    f = {{p.y, -p.x}, 1};
  } else if (p.x < 0.0 && p.y <= 0.0) {
    f = {{-p.x, -p.y}, 2};
  } else if (p.x >= 0.0 && p.y < 0.0) {
    f = {{-p.y, p.x}, 3};
  } else {
    f = {{0.0, 0.0}, 0};  // the centre, or NaN input: a defined answer
  }
  f.q.x = f.q.x > 0.0 ? f.q.x : 0.0;
  f.q.y = f.q.y > 0.0 ? f.q.y : 0.0;
  return f;
}

// What the inverse of a four-copy strategy returns: the square point and which copy k of it
// (rotation by k * 90 degrees) is the given disk point.
struct Inverse4 {
  Point2 uv;
  uint32_t k = 0;
};

}  // namespace disklab::disk
