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

double torus_distance2(double ax, double ay, double bx, double by) {
  double dx = std::abs(ax - bx), dy = std::abs(ay - by);
  dx = std::min(dx, 1.0 - dx);
  dy = std::min(dy, 1.0 - dy);
  return dx * dx + dy * dy;
}

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
          for (int p = head_[gy * side_ + gx]; p >= 0; p = next_[p])
            best = std::min(best, torus_distance2(xs_[p], ys_[p], x, y));
        }
      // Every point outside rings 0..r is at least r cell widths away (the query is inside
      // its own cell), so once the best distance is that small the search is over.
      const double reach = r * h;
      if (best <= reach * reach) break;
    }
    return best;
  }

  // Sets `out` (x, y pairs) to the stored points within d + margin of (x, y), d the distance
  // to the nearest one, and possibly some farther ones; none if the grid is empty.
  void near_points(double x, double y, double margin, std::vector<double>& out) const {
    out.clear();
    if (xs_.empty()) return;
    if (side_ >= 3) {
      // The 3 x 3 cells around (x, y) first: every point outside them is at least `edge` away.
      const int cx = cell_of(x), cy = cell_of(y);
      const double h = 1.0 / side_;
      const double fx = x - cx * h, fy = y - cy * h;
      const double edge = h + std::min(std::min(fx, h - fx), std::min(fy, h - fy));
      double best = std::numeric_limits<double>::infinity();
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          for (int p = head_[wrap(cy + dy) * side_ + wrap(cx + dx)]; p >= 0; p = next_[p]) {
            best = std::min(best, torus_distance2(xs_[p], ys_[p], x, y));
            out.push_back(xs_[p]);
            out.push_back(ys_[p]);
          }
      const double radius = std::sqrt(best) + margin;
      if (radius <= edge) {
        keep_within(x, y, radius, out);
        return;
      }
      out.clear();
    }
    const double radius = std::sqrt(nearest_distance2(x, y)) + margin;
    const int reach = static_cast<int>(radius * side_) + 1;
    const bool all = 2 * reach + 1 >= side_;  // every cell, each once
    const int lo_x = all ? 0 : cell_of(x) - reach, lo_y = all ? 0 : cell_of(y) - reach;
    const int span = all ? side_ : 2 * reach + 1;
    for (int dy = 0; dy < span; ++dy)
      for (int dx = 0; dx < span; ++dx)
        for (int p = head_[wrap(lo_y + dy) * side_ + wrap(lo_x + dx)]; p >= 0; p = next_[p]) {
          out.push_back(xs_[p]);
          out.push_back(ys_[p]);
        }
    keep_within(x, y, radius, out);
  }

 private:
  int cell_of(double v) const { return std::min(static_cast<int>(v * side_), side_ - 1); }
  static void keep_within(double x, double y, double radius, std::vector<double>& pts) {
    std::size_t kept = 0;
    for (std::size_t k = 0; k < pts.size(); k += 2)
      if (torus_distance2(pts[k], pts[k + 1], x, y) <= radius * radius) {
        pts[kept++] = pts[k];
        pts[kept++] = pts[k + 1];
      }
    pts.resize(kept);
  }
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

// Top `digits` binary digits of a 32-bit fraction (digits in 0..32).
uint32_t top(uint32_t v, int digits) {
  return digits == 0 ? 0u : static_cast<uint32_t>(static_cast<uint64_t>(v) >> (32 - digits));
}

// Random low bits below the top `digits`: uniform jitter inside the finest stratum.
uint32_t with_jitter(uint32_t stratum, int digits, Pcg32& rng) {
  const uint32_t r = rng.next_u32();
  if (digits == 0) return r;
  if (digits >= 32) return stratum;
  return (stratum << (32 - digits)) | (r >> digits);
}

// pmj02bn's builder: the stratum search of Christensen et al. 2018 (Sec. 5) with best candidates
// (Sec. 6); see Pmj02 in tabulated.h. Only the prefix condition is imposed: point i at level M
// avoids the elementary intervals used by points 0..i-1. Also requiring every aligned block to be
// a net makes this greedy random placement run into dead ends (tried: at every even level, and
// level 12 never completes); pmj02 gets that property from the xor construction above instead.
// The valid positions in the rule's sub-squares are surveyed once per point (SubSquare), so each
// of its candidates costs a few random draws instead of a search.
class Pmj02Builder {
 public:
  Pmj02Builder(uint64_t seed, std::vector<FixedPoint2>& points, int candidates)
      : rng_(derive_seed(seed, 0x93a0)),
        pts_(points),
        candidates_(candidates),
        grid_(points.size()) {}

  uint32_t build() {
    const auto n = static_cast<uint32_t>(pts_.size());
    if (n == 0) return 0;
    pts_[0] = {rng_.next_u32(), rng_.next_u32()};
    grid_.insert(to_unit(pts_[0].x), to_unit(pts_[0].y));
    for (uint32_t i = 1; i < n; ++i) {
      if (std::has_single_bit(i)) start_level(static_cast<int>(std::bit_width(i)));
      place(i);
    }
    return fallbacks_;
  }

 private:
  // The valid positions of a point inside one sub-square S of side 2^-plen (x and y start with
  // px and py), where 2 plen >= M. An elementary interval of shape 2^k x 2^(M-k) then has its
  // x digits inside S's when k <= plen and its y digits inside S's when M - k <= plen, so shapes
  // M - plen <= k <= plen are one interval each, and the others constrain x alone (k > plen) or
  // y alone (k < M - plen): the valid (column, row) pairs are the product cols x rows.
  struct SubSquare {
    bool empty = true;
    std::vector<uint32_t> cols, rows;  // M-digit strata, ascending
    bool gathered = false;
    std::vector<double> near;  // x, y pairs: every earlier point that can be a candidate's nearest
  };

  // Level M: the points 2^(M-1) .. 2^M - 1 complete a (0,M,2)-net. Bit (k << M) + c of occ_ marks
  // the elementary interval c of shape 2^k x 2^(M-k) as used, c indexed (x's top k digits, y's top
  // M-k digits); bits keep all M+1 shapes within a few cache-sized blocks.
  void start_level(int M) {
    M_ = M;
    occ_.assign(((static_cast<std::size_t>(M) + 1) << M) / 64 + 1, 0);
    const uint32_t first = 1u << (M - 1);
    for (uint32_t j = 0; j < first; ++j)
      mark(pts_[j]);
  }

  std::size_t bit(int k, uint32_t xk, uint32_t yk) const {
    return (static_cast<std::size_t>(k) << M_) | (static_cast<std::size_t>(xk) << (M_ - k)) | yk;
  }
  // Whether the shape-k interval with the given top k digits of x and M-k digits of y is used.
  bool used(int k, uint32_t xk, uint32_t yk) const {
    const std::size_t b = bit(k, xk, yk);
    return (occ_[b / 64] >> (b % 64)) & 1u;
  }

  void mark(FixedPoint2 p) {
    for (int k = 0; k <= M_; ++k) {
      const std::size_t b = bit(k, top(p.x, k), top(p.y, M_ - k));
      occ_[b / 64] |= uint64_t{1} << (b % 64);
    }
  }

  // Columns of S, depth first: x prefix `xk` of k digits, the shape-k interval checked with y's
  // top M-k digits (inside py, since k > plen >= M - plen).
  void collect_cols(uint32_t xk, int k, uint32_t py, int plen, std::vector<uint32_t>& out) const {
    if (k > plen && used(k, xk, py >> (plen - (M_ - k)))) return;
    if (k == M_) {
      out.push_back(xk);
      return;
    }
    collect_cols(xk << 1, k + 1, py, plen, out);
    collect_cols((xk << 1) | 1u, k + 1, py, plen, out);
  }
  // Rows of S likewise: y prefix `yd` of d digits, the shape M-d interval checked with x's top
  // M-d digits (inside px).
  void collect_rows(uint32_t yd, int d, uint32_t px, int plen, std::vector<uint32_t>& out) const {
    if (d > plen && used(M_ - d, px >> (plen - (M_ - d)), yd)) return;
    if (d == M_) {
      out.push_back(yd);
      return;
    }
    collect_rows(yd << 1, d + 1, px, plen, out);
    collect_rows((yd << 1) | 1u, d + 1, px, plen, out);
  }

  void survey(uint32_t px, uint32_t py, int plen, SubSquare& s) const {
    s.cols.clear();
    s.rows.clear();
    s.empty = true;
    for (int k = M_ - plen; k <= plen; ++k)
      if (used(k, px >> (plen - k), py >> (plen - (M_ - k)))) return;
    collect_cols(px, plen, py, plen, s.cols);
    if (s.cols.empty()) return;
    collect_rows(py, plen, px, plen, s.rows);
    s.empty = s.rows.empty();
    s.gathered = false;
  }

  // The earlier points near S's valid cells, gathered once for all its candidates: a candidate q
  // in the box spanned by cols x rows (centre c, half-diagonal b) has its nearest point within
  // d(q, c) + d(c) <= b + d(c) of q, so within 2 b + d(c) of c, where d(c) is c's nearest-point
  // distance (toroidal distances obey the triangle inequality).
  void gather(SubSquare& s) {
    const double w = std::ldexp(1.0, -M_);
    const double x0 = s.cols.front() * w, x1 = (s.cols.back() + 1.0) * w;
    const double y0 = s.rows.front() * w, y1 = (s.rows.back() + 1.0) * w;
    const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
    const double b = 0.5 * std::hypot(x1 - x0, y1 - y0);
    // The margin's last term covers the rounding of the distances, each within a few ulps of 1.
    grid_.near_points(cx, cy, 2.0 * b + 1e-12, s.near);
    s.gathered = true;
  }

  static double nearest_distance2(const std::vector<double>& near, double x, double y) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < near.size(); k += 2)
      best = std::min(best, torus_distance2(near[k], near[k + 1], x, y));
    return best;
  }

  // A candidate in S, distributed as the 2018 search's with S's prefixes (main's builder): that
  // search takes a uniform free column and drops it while no row fits, so its column is uniform
  // over `cols`; its randomized depth-first search over y's digits enters either child of a node
  // with equal probability when both hold valid rows, and the descent over `rows` splits the same
  // way. Only the random stream's use differs.
  FixedPoint2 draw(const SubSquare& s) {
    const uint32_t column = s.cols[uniform_index(s.cols.size())];
    std::size_t lo = 0, hi = s.rows.size();
    for (uint32_t bit = 1u << (M_ - 1); hi - lo > 1; bit >>= 1) {
      // rows[lo, hi) share the digits above `bit`; split them by that digit.
      std::size_t mid = lo;
      while (mid < hi && (s.rows[mid] & bit) == 0)
        ++mid;
      if (mid == lo || mid == hi) continue;
      if (rng_.next_u32() >> 31)
        lo = mid;
      else
        hi = mid;
    }
    return {with_jitter(column, M_, rng_), with_jitter(s.rows[lo], M_, rng_)};
  }

  std::size_t uniform_index(std::size_t n) {
    return static_cast<std::size_t>((uint64_t{rng_.next_u32()} * n) >> 32u);
  }

  // Randomized depth-first search for y's top M digits given x's column: after d digits of y,
  // the shape 2^(M-d) x 2^d interval must be empty.
  bool search_y(uint32_t column, uint32_t yprefix, int d, uint32_t& row) {
    if (d > 0 && used(M_ - d, column >> d, yprefix)) return false;
    if (d == M_) {
      row = yprefix;
      return true;
    }
    const uint32_t first = rng_.next_u32() >> 31;
    for (uint32_t t = 0; t < 2; ++t)
      if (search_y(column, (yprefix << 1) | (first ^ t), d + 1, row)) return true;
    return false;
  }

  // The 2018 search without the sub-square rule (Christensen et al. 2018, Sec. 5): a uniform free
  // x column (shape 2^M x 1), taken out of the draw while no y fits, and a randomized depth-first
  // search over y.
  bool fallback_search(FixedPoint2& out) {
    free_.clear();
    for (uint32_t column = 0; column < (1u << M_); ++column)
      if (!used(M_, column, 0)) free_.push_back(column);
    while (!free_.empty()) {
      const std::size_t k = uniform_index(free_.size());
      uint32_t row = 0;
      if (search_y(free_[k], 0, 0, row)) {
        out = {with_jitter(free_[k], M_, rng_), with_jitter(row, M_, rng_)};
        return true;
      }
      free_[k] = free_.back();
      free_.pop_back();
    }
    return false;
  }

  // The sub-squares pmj's rule allows for point i (Christensen et al. 2018, Sec. 3), in the
  // 2^(n+1) grid with n = floor((M-1)/2); parent j's cell in the 2^n grid is kept. Returns how
  // many (1 at odd M, 2 at even M, in either order per candidate).
  int rule_subsquares(uint32_t i, uint32_t (&sub)[2][2]) const {
    const int n = (M_ - 1) / 2;
    const uint32_t quarter = 1u << (2 * n);  // 4^n
    if (M_ % 2 == 1) {
      // 4^n .. 2 4^n - 1: diagonally opposite the parent's sub-square.
      const FixedPoint2 p = pts_[i - quarter];
      sub[0][0] = top(p.x, n + 1) ^ 1u;
      sub[0][1] = top(p.y, n + 1) ^ 1u;
      return 1;
    }
    const uint32_t j = (i - 2 * quarter) % quarter;  // parent in the first 4^n points
    const FixedPoint2 p = pts_[j];
    const uint32_t sx = top(p.x, n + 1), sy = top(p.y, n + 1);
    // The two sub-squares left empty by j and its diagonal partner: flip x only or y only.
    sub[0][0] = sx ^ 1u;
    sub[0][1] = sy;
    sub[1][0] = sx;
    sub[1][1] = sy ^ 1u;
    return 2;
  }

  // Point i: `candidates_` valid positions, each in the first of the rule's sub-squares (in a
  // random order) that has one, else anywhere valid; the one farthest from points 0..i-1 wins.
  void place(uint32_t i) {
    const int plen = (M_ - 1) / 2 + 1;
    uint32_t sub[2][2];
    const int count = rule_subsquares(i, sub);
    for (int s = 0; s < count; ++s)
      survey(sub[s][0], sub[s][1], plen, squares_[s]);
    FixedPoint2 best{};
    double best_d2 = -1.0;
    for (int c = 0; c < candidates_; ++c) {
      int s = count == 2 ? static_cast<int>(rng_.next_u32() >> 31) : 0;
      if (squares_[s].empty && count == 2) s ^= 1;
      FixedPoint2 p;
      double d2;
      if (SubSquare& square = squares_[s]; !square.empty) {
        p = draw(square);
        if (!square.gathered) gather(square);
        d2 = nearest_distance2(square.near, to_unit(p.x), to_unit(p.y));
      } else {
        ++fallbacks_;
        if (!fallback_search(p))
          throw std::runtime_error("pmj02: no valid position for point " + std::to_string(i));
        d2 = grid_.nearest_distance2(to_unit(p.x), to_unit(p.y));
      }
      if (d2 > best_d2) {
        best_d2 = d2;
        best = p;
      }
    }
    pts_[i] = best;
    mark(best);
    grid_.insert(to_unit(best.x), to_unit(best.y));
  }

  Pcg32 rng_;
  std::vector<FixedPoint2>& pts_;
  int candidates_;
  TorusGrid grid_;
  int M_ = 0;
  std::vector<uint64_t> occ_;
  std::vector<uint32_t> free_;
  SubSquare squares_[2];
  uint32_t fallbacks_ = 0;
};

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
  rule_fallbacks_ = Pmj02Builder(seed, points_, candidates).build();
}

}  // namespace disklab::sequence
