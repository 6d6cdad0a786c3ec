// Generation of the tabulated sequences: best candidates and pmj02 / pmj02bn.
#include "disklab/sequence/tabulated.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "disklab/sequence/random.h"
#include "disklab/sequence/sobol.h"

namespace disklab::sequence {
namespace {

// Nearest-neighbour distances on the unit torus with a uniform grid that refines as points
// arrive (about two points per cell), so a query touches O(1) cells on average.
class TorusGrid {
 public:
  explicit TorusGrid(std::size_t capacity) {
    xs_.reserve(capacity);
    ys_.reserve(capacity);
    next_.reserve(capacity);
    rebuild(1);
  }

  void insert(double x, double y) {
    xs_.push_back(x);
    ys_.push_back(y);
    next_.push_back(-1);
    if (xs_.size() > 2 * static_cast<std::size_t>(side_) * side_)
      rebuild(side_ * 2);
    else
      link(static_cast<int>(xs_.size()) - 1);
  }

  // Squared toroidal distance from (x, y) to the nearest stored point (infinity if none).
  double nearest_distance2(double x, double y) const {
    double best = std::numeric_limits<double>::infinity();
    if (xs_.empty()) return best;
    const int cx = cell_of(x), cy = cell_of(y);
    const double h = 1.0 / side_;
    for (int r = 0; r <= side_ / 2 + 1; ++r) {
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          if (std::max(std::abs(dx), std::abs(dy)) != r) continue;  // ring r only
          const int gx = wrap(cx + dx), gy = wrap(cy + dy);
          for (int p = head_[gy * side_ + gx]; p >= 0; p = next_[p]) {
            double ddx = std::abs(xs_[p] - x), ddy = std::abs(ys_[p] - y);
            ddx = std::min(ddx, 1.0 - ddx);
            ddy = std::min(ddy, 1.0 - ddy);
            best = std::min(best, ddx * ddx + ddy * ddy);
          }
        }
      // Every point outside rings 0..r is at least r cell widths away (the query is inside
      // its own cell), so once the best distance is that small the search is over.
      const double reach = r * h;
      if (best <= reach * reach) break;
    }
    return best;
  }

 private:
  int cell_of(double v) const { return std::min(static_cast<int>(v * side_), side_ - 1); }
  int wrap(int c) const { return ((c % side_) + side_) % side_; }
  void link(int p) {
    const int c = cell_of(ys_[p]) * side_ + cell_of(xs_[p]);
    next_[p] = head_[c];
    head_[c] = p;
  }
  void rebuild(int side) {
    side_ = side;
    head_.assign(static_cast<std::size_t>(side_) * side_, -1);
    for (int p = 0; p < static_cast<int>(xs_.size()); ++p)
      link(p);
  }

  int side_ = 1;
  std::vector<double> xs_, ys_;
  std::vector<int> next_, head_;
};

int log2_ceil(uint32_t capacity) {
  if (capacity == 0 || capacity > (1u << 24))
    throw std::invalid_argument("sequence capacity must be in [1, 2^24], got " +
                                std::to_string(capacity));
  return static_cast<int>(std::bit_width(capacity - 1));
}

// The xor that finds point i's y partner in Pmj02 (tabulated.h): the index d_n in [2^n, 2^(n+1))
// whose unscrambled Sobol' y has n leading zero digits, so that i and i ^ d_n share y's top n
// digits for every i. Column r of the Pascal matrix has digits 1..r+1 with digit r+1 set, so
// clearing digits n..1 from the bottom up never disturbs a cleared one.
uint32_t y_partner_xor(int n) {
  uint32_t t = sobol_dim1_column(n), d = 1u << n;
  for (int r = n - 1; r >= 0; --r)
    if (t & (0x80000000u >> r)) {
      t ^= sobol_dim1_column(r);
      d |= 1u << r;
    }
  return d;
}

// The stochastic (0,2)-sequence of Helmer, Christensen and Kensler 2021 (see Pmj02 in
// tabulated.h), from one random stream in index order, so a longer table extends a shorter one.
void generate_02(std::vector<FixedPoint2>& s, Pcg32& rng) {
  if (s.empty()) return;
  s[0] = {rng.next_u32(), rng.next_u32()};
  for (int n = 0; (std::size_t{1} << n) < s.size(); ++n) {
    const uint32_t first = 1u << n, d = y_partner_xor(n);
    const uint32_t flip = 0x80000000u >> n;  // digit n+1
    const uint32_t keep = ~(flip - 1u);      // digits 1..n+1: copied, the last one flipped
    for (uint32_t i = first; i < 2 * first; ++i) {
      const uint32_t rx = rng.next_u32(), ry = rng.next_u32();
      s[i] = {((s[i ^ first].x ^ flip) & keep) | (rx & ~keep),
              ((s[i ^ d].y ^ flip) & keep) | (ry & ~keep)};
    }
  }
}

// pmj02bn's order (see Pmj02 in tabulated.h): the points of `s` level by level, each half of a
// level [2^n, 2^(n+1)) in turn (the first one drawn at random), and within a half, greedily, the
// point farthest from all earlier ones among `candidates` drawn from those not yet taken.
void order_blue_noise(const std::vector<FixedPoint2>& s, std::vector<FixedPoint2>& out,
                      int candidates, Pcg32& rng) {
  TorusGrid grid(out.size());
  auto take = [&](std::size_t o, FixedPoint2 p) {
    out[o] = p;
    grid.insert(to_unit(p.x), to_unit(p.y));
  };
  for (std::size_t i = 0; i < std::min<std::size_t>(2, s.size()); ++i)
    take(i, s[i]);
  std::vector<uint32_t> pool;
  std::size_t o = 2;
  for (int n = 1; (std::size_t{1} << n) < s.size(); ++n) {
    const uint32_t first = 1u << n, half = first / 2;
    const uint32_t lead = rng.next_u32() >> 31;
    for (uint32_t h : {lead, 1u - lead}) {
      pool.resize(half);
      for (uint32_t k = 0; k < half; ++k)
        pool[k] = first + h * half + k;
      for (uint32_t left = half; left > 0; --left) {
        uint32_t best = 0;
        double best_d2 = -1.0;
        for (int c = 0; c < candidates && left > 1; ++c) {
          const auto k = static_cast<uint32_t>((uint64_t{rng.next_u32()} * left) >> 32u);
          const FixedPoint2 p = s[pool[k]];
          const double d2 = grid.nearest_distance2(to_unit(p.x), to_unit(p.y));
          if (d2 > best_d2) {
            best_d2 = d2;
            best = k;
          }
        }
        take(o++, s[pool[best]]);
        pool[best] = pool[left - 1];
      }
    }
  }
}

}  // namespace

TabulatedSequence::TabulatedSequence(uint64_t seed, uint32_t capacity, bool block_xor)
    : log2_capacity_(log2_ceil(capacity)),
      block_seed_(derive_seed(seed, 0xb10c)),
      block_xor_(block_xor) {
  points_.resize(std::size_t{1} << log2_capacity_);
}

BestCandidate::BestCandidate(uint64_t seed, uint32_t capacity, int candidates)
    : TabulatedSequence(seed, capacity, /*block_xor=*/false) {
  if (candidates < 1) throw std::invalid_argument("best-candidate: candidates must be >= 1");
  Pcg32 rng(derive_seed(seed, 0xbc01));
  TorusGrid grid(points_.size());
  for (FixedPoint2& point : points_) {
    double best_d2 = -1.0;
    for (int c = 0; c < candidates; ++c) {
      const FixedPoint2 p{rng.next_u32(), rng.next_u32()};
      const double d2 = grid.nearest_distance2(to_unit(p.x), to_unit(p.y));
      if (d2 > best_d2) {
        best_d2 = d2;
        point = p;
      }
    }
    grid.insert(to_unit(point.x), to_unit(point.y));
  }
}

Pmj02::Pmj02(uint64_t seed, uint32_t capacity, int candidates)
    : TabulatedSequence(seed, capacity, /*block_xor=*/true) {
  if (candidates < 1) throw std::invalid_argument("pmj02: candidates must be >= 1");
  if (candidates == 1) {
    Pcg32 rng(derive_seed(seed, 0x93a0));
    generate_02(points_, rng);
    return;
  }
  // Two streams, each consumed in index order, so the table's prefix does not depend on its size;
  // a stream of its own for the points, so pmj02bn's sets are not pmj02's reordered.
  Pcg32 points_rng(derive_seed(seed, 0x93b1)), order_rng(derive_seed(seed, 0x93b2));
  std::vector<FixedPoint2> s(points_.size());
  generate_02(s, points_rng);
  order_blue_noise(s, points_, candidates, order_rng);
}

}  // namespace disklab::sequence
