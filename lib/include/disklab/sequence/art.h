#pragma once
// ART, adaptive regular tiles (Ahmed, Niese, Huang and Deussen 2017, "An adaptive point sampler
// on a regular lattice", ACM TOG 36(4)), with a tile table built here: the offline construction
// is reference/generate/art.cpp, its output reference/art_tiles.csv, compiled into the library
// (lib/CMakeLists.txt turns the CSV into an initializer; nothing is read at run time). How the
// table differs from the published one (fewer tile types, no word-based IDs, our optimizer) is
// in the README's ART section.
//
// Each tile type has a point (in tile coordinates), 16 child types for its 4 x 4 subdivision and
// a visiting order of the 16 cells whose first cell holds the tile's own point (that child shares
// it). Point `index`: from the root tile, take cell order[index & 15], descend into that child,
// index >>= 4, until the index is 0; the point is the final tile's point mapped back. So the
// first 16^k points put exactly one point in every tile of level k (a 4^k x 4^k grid), and the
// first m 16^k points the first m children of each (the paper's progressive traversal).
//
// Randomization per seed: the root tile type, and a toroidal (Cranley-Patterson) shift of the
// whole lattice, so the strata are the cells of the 4^k grid shifted by shift(). All integer
// arithmetic on 32-bit fractions: at(i) lies in [0, 1 - 2^-32].
#include <cstdint>

#include "disklab/sequence/scramble.h"
#include "disklab/types.h"

namespace disklab::sequence {

namespace art {

inline constexpr int kChildren =
    16;  // 4 x 4; cell j covers [jx/4, (jx+1)/4) x [jy/4, ..), j = jx + 4 jy

struct Tile {
  uint16_t child[kChildren];  // type of the child in cell j
  uint8_t order[kChildren];   // visiting order of the cells; order[0] holds the tile's point
  // The tile's point in tile coordinates as 32-bit fractions: the 16 base-4 digits read along
  // the chain of sharing children (cell order[0], then that child's order[0], ...), so it equals
  // (cell + child's point) / 4 exactly and every level is consistent with the next.
  FixedPoint2 point;
};

// Number of tile types in the compiled table.
uint32_t tile_count();
// Tile type `type` (< tile_count()).
const Tile& tile(uint32_t type);
// The point the CSV records for `type` (x, y as printed by the generator), for the tests.
Point2 recorded_point(uint32_t type);

}  // namespace art

class ArtSequence {
 public:
  explicit ArtSequence(uint64_t seed);

  // The point in the unshifted lattice (the tile structure's own coordinates).
  FixedPoint2 lattice_at(uint32_t index) const;
  FixedPoint2 fixed_at(uint32_t index) const {
    const FixedPoint2 p = lattice_at(index);
    return {rotate(p.x, shift_.x), rotate(p.y, shift_.y)};
  }
  Point2 at(uint32_t index) const { return to_point(fixed_at(index)); }

  uint32_t root() const { return root_; }
  FixedPoint2 shift() const { return shift_; }

 private:
  uint32_t root_;
  FixedPoint2 shift_;
};

}  // namespace disklab::sequence
