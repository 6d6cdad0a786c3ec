// ART (Ahmed, Niese, Huang and Deussen 2017): the compiled tile table and the sampler's descent.
#include "disklab/sequence/art.h"

#include <array>
#include <cstddef>
#include <iterator>

namespace disklab::sequence {
namespace {

// One row of reference/art_tiles.csv, as lib/CMakeLists.txt writes it into art_tiles.inc.
struct Row {
  int type;
  double x, y;
  int child[art::kChildren];
  int order[art::kChildren];
};

constexpr Row kRows[] = {
#include "art_tiles.inc"
};
constexpr std::size_t kTypes = std::size(kRows);
static_assert(kTypes >= 1 && kTypes <= 65536, "the table indexes types with 16 bits");

// A tile's point as 16 base-4 digits along its chain of sharing children (art.h).
constexpr FixedPoint2 chain_point(std::size_t t) {
  uint32_t x = 0, y = 0;
  for (int d = 0; d < 16; ++d) {
    const auto cell = static_cast<uint32_t>(kRows[t].order[0]);
    x |= (cell & 3u) << (30 - 2 * d);
    y |= (cell >> 2u) << (30 - 2 * d);
    t = static_cast<std::size_t>(kRows[t].child[cell]);
  }
  return {x, y};
}

// Checks the table's shape at compile time: rows in type order, child types in range, each
// order a permutation of the 16 cells.
constexpr bool table_is_well_formed() {
  for (std::size_t t = 0; t < kTypes; ++t) {
    if (kRows[t].type != static_cast<int>(t)) return false;
    unsigned seen = 0;
    for (int j = 0; j < art::kChildren; ++j) {
      if (kRows[t].child[j] < 0 || static_cast<std::size_t>(kRows[t].child[j]) >= kTypes)
        return false;
      if (kRows[t].order[j] < 0 || kRows[t].order[j] >= art::kChildren) return false;
      seen |= 1u << static_cast<unsigned>(kRows[t].order[j]);
    }
    if (seen != 0xffffu) return false;
  }
  return true;
}
static_assert(table_is_well_formed(), "reference/art_tiles.csv is malformed");

constexpr std::array<art::Tile, kTypes> make_tiles() {
  std::array<art::Tile, kTypes> tiles{};
  for (std::size_t t = 0; t < kTypes; ++t) {
    for (int j = 0; j < art::kChildren; ++j) {
      tiles[t].child[j] = static_cast<uint16_t>(kRows[t].child[j]);
      tiles[t].order[j] = static_cast<uint8_t>(kRows[t].order[j]);
    }
    tiles[t].point = chain_point(t);
  }
  return tiles;
}
constexpr std::array<art::Tile, kTypes> kTiles = make_tiles();

}  // namespace

namespace art {
uint32_t tile_count() {
  return static_cast<uint32_t>(kTypes);
}
const Tile& tile(uint32_t type) {
  return kTiles[type];
}
Point2 recorded_point(uint32_t type) {
  return {kRows[type].x, kRows[type].y};
}
}  // namespace art

ArtSequence::ArtSequence(uint64_t seed)
    : root_(static_cast<uint32_t>(derive_seed(seed, 0xa47) % kTypes)), shift_{} {
  const uint64_t h = derive_seed(seed, 0xa48);
  shift_ = {static_cast<uint32_t>(h), static_cast<uint32_t>(h >> 32u)};
}

// Ahmed et al. 2017, the progressive traversal: one level per base-16 digit of the index, lowest
// digit first, so consecutive indices visit different tiles of the coarsest level first.
FixedPoint2 ArtSequence::lattice_at(uint32_t index) const {
  uint32_t t = root_, x = 0, y = 0;
  int shift = 30;  // bit position of the current level's base-4 digit
  while (index != 0) {
    const art::Tile& tile = kTiles[t];
    const uint32_t cell = tile.order[index & 15u];
    x |= (cell & 3u) << shift;
    y |= (cell >> 2u) << shift;
    t = tile.child[cell];
    index >>= 4u;
    shift -= 2;
  }
  // The final tile is 2^(shift + 2) wide in 32-bit fractions: its point, scaled into it, fills
  // exactly the bits below the digits (at most 8 levels: shift >= 14).
  const int depth_bits = 30 - shift;
  const FixedPoint2 p = kTiles[t].point;
  return {x | (p.x >> depth_bits), y | (p.y >> depth_bits)};
}

}  // namespace disklab::sequence
