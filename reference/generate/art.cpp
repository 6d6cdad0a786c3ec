// Offline construction of the tile table of the ART sequence ("art" in the registry), after
// Ahmed, Niese, Huang and Deussen 2017, "An adaptive point sampler on a regular lattice"
// (ACM TOG 36(4), SIGGRAPH 2017): square tiles on a regular lattice, one sample point per tile
// at an offset stored per tile type; each type subdivides into 4 x 4 children whose types come
// from the same set, and visits them in a stored order whose first child is the one that shares
// the parent's point (the paper's Fig. 1: "first, sample points are filled in that are shared by
// one of the respective child tiles"). Everything below is our own construction of such a table
// by the paper's kind of optimization (per-type offsets and rules tuned on instances of the
// lattice so that every level is blue noise); where it departs from the published one is listed
// in reference/README.md and the README's ART section:
//  - tile types are abstract symbols (not the paper's 44 x 44 word-based IDs), and every
//    (type, cell) slot of the subdivision rules is free: the rules are optimized, not derived
//    from a substitution;
//  - the point of a type is not a free offset: it is inherited from the child that shares it,
//    p_t = (cell + p_child) / 4, so offsets are chosen through the rules (4^-k precision along
//    the chain of sharing children) and every level is exactly consistent with the next;
//  - the blue-noise objective is a two-scale compact repulsive kernel energy (see kernel())
//    over each level (and, for the visiting orders, over each prefix size m 16^k), minimized by
//    greedy coordinate descent with exact acceptance, not the paper's optimizer.
//
// Every step is deterministic: PCG32 from the seed, integer tie-breaks, no libm transcendental
// (the kernel is a polynomial), so the same build reproduces the table bit for bit.
//
// Usage:
//   reference_art --out reference/art_tiles.csv [--seed S] [--types T] [--levels K]
//                 [--roots R] [--sweeps W] [--radius H]
//   reference_art --check reference/art_tiles.csv   (regenerates with the file's parameters and
//                                                   compares every line but the date; exit 1 on
//                                                   a difference)
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "disklab/sequence/random.h"

namespace {

constexpr int kCells =
    16;  // 4 x 4 children; cell j covers [jx/4, (jx+1)/4) x [jy/4, ..), j = jx + 4 jy
constexpr int kChainDigits = 28;  // 4^-28 = 2^-56: the point of a type to below double precision

struct Params {
  uint64_t seed = 1;
  int types = 256;      // tile types (the paper publishes 1,936; see the README for why fewer)
  int levels = 3;       // finest lattice level optimized: 16^levels points per root
  int roots = 8;        // root types whose lattices are optimized together in one sweep
  int sweeps = 10;      // rounds of point and rule updates over all types
  double radius = 2.0;  // kernel support h in units of the point spacing 1/sqrt(n) of the set
  int candidates = 32;  // point positions tried per type and sweep
  double short_radius = 0.85;  // h_short in spacings
  double short_weight = 10.0;  // g_short
};

struct Table {
  int types = 0;
  std::vector<std::array<int, kCells>> child;  // child[t][j]: type of child cell j
  std::vector<std::array<int, kCells>>
      order;  // visiting order of the cells; order[t][0] shares t's point
  std::vector<std::array<double, 2>> point;  // derived from the sharing chain (derive_points)
};

int rep(const Table& tb, int t) {
  return tb.order[static_cast<size_t>(t)][0];
}

// p_t = (cell(rep_t) + p_{child_t})/4 along the chain of sharing children, summed from the
// deepest digit up so each step is one exact scaling and one rounding.
void derive_points(Table& tb) {
  tb.point.assign(static_cast<size_t>(tb.types), {0.0, 0.0});
  for (int t = 0; t < tb.types; ++t) {
    std::array<int, kChainDigits> digits{};
    int u = t;
    for (int d = 0; d < kChainDigits; ++d) {
      digits[static_cast<size_t>(d)] = rep(tb, u);
      u = tb.child[static_cast<size_t>(u)][static_cast<size_t>(rep(tb, u))];
    }
    double x = 0.0, y = 0.0;
    for (int d = kChainDigits - 1; d >= 0; --d) {
      x = ((digits[static_cast<size_t>(d)] & 3) + x) / 4.0;
      y = ((digits[static_cast<size_t>(d)] >> 2) + y) / 4.0;
    }
    tb.point[static_cast<size_t>(t)] = {x, y};
  }
}

// One level of a root's lattice: g x g tiles (g = 4^k), their types and points (global, torus).
struct Level {
  int g = 1;
  std::vector<int> type;
  std::vector<double> x, y;
};
using Lattice = std::vector<Level>;  // levels 0..K

Lattice expand(const Table& tb, int root, int levels) {
  Lattice lat(static_cast<size_t>(levels) + 1);
  lat[0].g = 1;
  lat[0].type = {root};
  for (int k = 1; k <= levels; ++k) {
    const Level& up = lat[static_cast<size_t>(k) - 1];
    Level& L = lat[static_cast<size_t>(k)];
    L.g = up.g * 4;
    const auto n = static_cast<size_t>(L.g) * static_cast<size_t>(L.g);
    L.type.resize(n);
    for (int b = 0; b < L.g; ++b)
      for (int a = 0; a < L.g; ++a) {
        const int parent = up.type[static_cast<size_t>((b / 4) * up.g + a / 4)];
        L.type[static_cast<size_t>(b * L.g + a)] =
            tb.child[static_cast<size_t>(parent)][static_cast<size_t>((a % 4) + 4 * (b % 4))];
      }
  }
  for (Level& L : lat) {
    const auto n = L.type.size();
    L.x.resize(n);
    L.y.resize(n);
    for (int b = 0; b < L.g; ++b)
      for (int a = 0; a < L.g; ++a) {
        const auto i = static_cast<size_t>(b * L.g + a);
        const auto& p = tb.point[static_cast<size_t>(L.type[i])];
        L.x[i] = (a + p[0]) / L.g;
        L.y[i] = (b + p[1]) / L.g;
      }
  }
  return lat;
}

double torus(double d) {
  if (d > 0.5) return d - 1.0;
  if (d < -0.5) return d + 1.0;
  return d;
}

// The repulsive kernel: (1 - d^2/h^2)^3 on d < h (smooth, compact, a polynomial, so
// deterministic), plus g_short times the same shape on d < h_short. The long part (h = 2
// spacings) evens the density at the scale of a few points; alone it tolerates close pairs. The
// short part (h_short below one spacing) removes close pairs; alone it is minimized by the
// square grid (all distances one spacing, energy 0), whose aligned rows raise the discrepancy.
// Both scale with the set's spacing 1/sqrt(n).
double g_short_ratio2 = 0.0;  // (h / h_short)^2, set from Params in generate()
double g_short_weight = 0.0;
double kernel(double d2, double inv_h2) {
  const double r2 = d2 * inv_h2;
  if (r2 >= 1.0) return 0.0;
  const double s = 1.0 - r2;
  double e = s * s * s;
  const double q2 = r2 * g_short_ratio2;
  if (q2 < 1.0) {
    const double t = 1.0 - q2;
    e += g_short_weight * t * t * t;
  }
  return e;
}

// Energy of a point at (qx, qy) in cell (a, b) of a level whose occupied cells are `occupied`
// (null: all), against every other occupied cell's point within h. reach: cells to scan.
struct Field {
  const Level* level;
  const std::vector<char>* occupied;  // null: every cell holds its point
  double inv_h2;
  int reach;
};

// Calls visit(i) once for every cell i of L other than (a, b) within `reach` cells (torus).
template <class Visit>
void for_neighbors(const Level& L, int reach, int a, int b, Visit visit) {
  const int own = b * L.g + a;
  if (2 * reach + 1 >= L.g) {  // the window would wrap onto itself: every cell once
    for (int i = 0; i < L.g * L.g; ++i)
      if (i != own) visit(i);
    return;
  }
  for (int db = -reach; db <= reach; ++db)
    for (int da = -reach; da <= reach; ++da) {
      if (da == 0 && db == 0) continue;
      const int aa = (a + da + L.g) % L.g, bb = (b + db + L.g) % L.g;
      visit(bb * L.g + aa);
    }
}

double point_energy(const Field& f, double qx, double qy, int a, int b) {
  const Level& L = *f.level;
  double e = 0.0;
  for_neighbors(L, f.reach, a, b, [&](int i) {
    if (f.occupied && !(*f.occupied)[static_cast<size_t>(i)]) return;
    const double dx = torus(qx - L.x[static_cast<size_t>(i)]);
    const double dy = torus(qy - L.y[static_cast<size_t>(i)]);
    e += kernel(dx * dx + dy * dy, f.inv_h2);
  });
  return e;
}

// Kernel support of a set of n points on the unit torus: radius x spacing 1/sqrt(n).
struct Scale {
  double inv_h2;
  int reach;  // cells of the level's grid (side 1/g) to scan
};
Scale scale_for(const Params& prm, double n, int g) {
  const double h = prm.radius / std::sqrt(n);
  return {1.0 / (h * h), static_cast<int>(std::ceil(h * g))};
}

// Total energy of the lattices: every level k = 1..K, each point's energy, per point (so each
// level weighs the same).
double total_energy(const Params& prm, const std::vector<Lattice>& lats) {
  double total = 0.0;
  for (const Lattice& lat : lats)
    for (int k = 1; k <= prm.levels; ++k) {
      const Level& L = lat[static_cast<size_t>(k)];
      const double n = static_cast<double>(L.g) * L.g;
      const Scale s = scale_for(prm, n, L.g);
      const Field f{&L, nullptr, s.inv_h2, s.reach};
      double e = 0.0;
      for (int b = 0; b < L.g; ++b)
        for (int a = 0; a < L.g; ++a) {
          const auto i = static_cast<size_t>(b * L.g + a);
          e += point_energy(f, L.x[i], L.y[i], a, b);
        }
      total += e / n;
    }
  return total;
}

struct Optimizer {
  Params prm;
  Table tb;
  std::vector<int> roots;
  std::vector<Lattice> lats;
  double energy = 0.0;
  int accepted = 0, rejected = 0;

  void rebuild() {
    derive_points(tb);
    lats.clear();
    for (int r : roots)
      lats.push_back(expand(tb, r, prm.levels));
    energy = total_energy(prm, lats);
  }

  // Keeps the change made to tb if the total energy fell; otherwise restores the saved state.
  struct Saved {
    Table tb;
    std::vector<Lattice> lats;
    double energy;
  };
  Saved save() const { return {tb, lats, energy}; }
  bool accept_or_revert(Saved& saved) {
    rebuild();
    if (energy < saved.energy) {
      ++accepted;
      return true;
    }
    ++rejected;
    tb = std::move(saved.tb);
    lats = std::move(saved.lats);
    energy = saved.energy;
    return false;
  }

  // Instances (root, level, a, b) of type t at levels lo..hi.
  struct Instance {
    int root, k, a, b;
  };
  std::vector<Instance> instances(int t, int lo, int hi) const {
    std::vector<Instance> out;
    for (size_t r = 0; r < lats.size(); ++r)
      for (int k = lo; k <= hi; ++k) {
        const Level& L = lats[r][static_cast<size_t>(k)];
        for (int b = 0; b < L.g; ++b)
          for (int a = 0; a < L.g; ++a)
            if (L.type[static_cast<size_t>(b * L.g + a)] == t)
              out.push_back({static_cast<int>(r), k, a, b});
      }
    return out;
  }

  // Energy of type t's point placed at p (tile coordinates) over all its instances, at its own
  // level and at every coarser level that shares the point (the tile is its parent's sharing
  // child, and so on up).
  double point_cost(const std::vector<Instance>& inst, double px, double py) const {
    double e = 0.0;
    for (const Instance& in : inst) {
      const Lattice& lat = lats[static_cast<size_t>(in.root)];
      int k = in.k, a = in.a, b = in.b;
      const double qx = (a + px) / lat[static_cast<size_t>(k)].g;
      const double qy = (b + py) / lat[static_cast<size_t>(k)].g;
      while (k >= 1) {
        const Level& L = lat[static_cast<size_t>(k)];
        const double n = static_cast<double>(L.g) * L.g;
        const Scale s = scale_for(prm, n, L.g);
        e += point_energy({&L, nullptr, s.inv_h2, s.reach}, qx, qy, a, b) / n;
        const Level& up = lat[static_cast<size_t>(k) - 1];
        const int parent = up.type[static_cast<size_t>((b / 4) * up.g + a / 4)];
        if (rep(tb, parent) != (a % 4) + 4 * (b % 4)) break;
        a /= 4;
        b /= 4;
        --k;
      }
    }
    return e;
  }

  // Moves type t's point: candidates (r + p_s)/4 nearest to the current point and to where the
  // repulsion pushes it; the best by point_cost is kept if the total energy falls.
  void update_point(int t) {
    const auto inst = instances(t, 1, prm.levels);
    if (inst.empty()) return;
    const auto& p = tb.point[static_cast<size_t>(t)];
    // Repulsion direction, in tile units, averaged over the instances at their own level.
    double fx = 0.0, fy = 0.0;
    for (const Instance& in : inst) {
      const Level& L = lats[static_cast<size_t>(in.root)][static_cast<size_t>(in.k)];
      const double n = static_cast<double>(L.g) * L.g;
      const Scale s = scale_for(prm, n, L.g);
      const double qx = (in.a + p[0]) / L.g, qy = (in.b + p[1]) / L.g;
      double wx = 0.0, wy = 0.0, ws = 0.0;
      for_neighbors(L, s.reach, in.a, in.b, [&](int i) {
        const auto j = static_cast<size_t>(i);
        const double dx = torus(qx - L.x[j]), dy = torus(qy - L.y[j]);
        const double w = kernel(dx * dx + dy * dy, s.inv_h2);
        wx += w * dx;
        wy += w * dy;
        ws += w;
      });
      if (ws > 0.0) {
        fx += wx / ws * L.g;
        fy += wy / ws * L.g;
      }
    }
    const double tx = std::clamp(p[0] + 0.5 * fx / static_cast<double>(inst.size()), 0.0, 1.0);
    const double ty = std::clamp(p[1] + 0.5 * fy / static_cast<double>(inst.size()), 0.0, 1.0);
    // Every reachable position: (cell r + p_s)/4.
    struct Cand {
      double d2;
      int r, s;
    };
    std::vector<Cand> near_p, near_t;
    for (int r = 0; r < kCells; ++r)
      for (int s = 0; s < tb.types; ++s) {
        const double cx = ((r & 3) + tb.point[static_cast<size_t>(s)][0]) / 4.0;
        const double cy = ((r >> 2) + tb.point[static_cast<size_t>(s)][1]) / 4.0;
        near_p.push_back({(cx - p[0]) * (cx - p[0]) + (cy - p[1]) * (cy - p[1]), r, s});
        near_t.push_back({(cx - tx) * (cx - tx) + (cy - ty) * (cy - ty), r, s});
      }
    auto by_d2 = [](const Cand& a, const Cand& b) {
      return a.d2 < b.d2 || (a.d2 == b.d2 && (a.r < b.r || (a.r == b.r && a.s < b.s)));
    };
    const auto half = static_cast<size_t>(prm.candidates / 2);
    std::partial_sort(near_p.begin(), near_p.begin() + half, near_p.end(), by_d2);
    std::partial_sort(near_t.begin(), near_t.begin() + half, near_t.end(), by_d2);
    const int cur_r = rep(tb, t),
              cur_s = tb.child[static_cast<size_t>(t)][static_cast<size_t>(cur_r)];
    double best = point_cost(inst, p[0], p[1]);
    int best_r = cur_r, best_s = cur_s;
    for (size_t c = 0; c < 2 * half; ++c) {
      const Cand& cd = c < half ? near_p[c] : near_t[c - half];
      const double cx = ((cd.r & 3) + tb.point[static_cast<size_t>(cd.s)][0]) / 4.0;
      const double cy = ((cd.r >> 2) + tb.point[static_cast<size_t>(cd.s)][1]) / 4.0;
      const double e = point_cost(inst, cx, cy);
      if (e < best) {
        best = e;
        best_r = cd.r;
        best_s = cd.s;
      }
    }
    if (best_r == cur_r && best_s == cur_s) return;
    Saved saved = save();
    auto& ord = tb.order[static_cast<size_t>(t)];
    std::swap(ord[0], *std::find(ord.begin(), ord.end(), best_r));
    tb.child[static_cast<size_t>(t)][static_cast<size_t>(best_r)] = best_s;
    accept_or_revert(saved);
  }

  // Chooses the types of t's 15 non-sharing children, cell by cell: the type whose point fits
  // best among the neighbours at the child level, over all instances of t.
  void update_children(int t) {
    auto inst = instances(t, 0, prm.levels - 1);
    if (inst.empty()) return;
    Saved saved = save();
    bool changed = false;
    for (int j = 0; j < kCells; ++j) {
      if (j == rep(tb, t)) continue;
      double best = 0.0;
      int best_s = -1;
      for (int s = 0; s < tb.types; ++s) {
        const auto& ps = tb.point[static_cast<size_t>(s)];
        double e = 0.0;
        for (const Instance& in : inst) {
          const Level& L = lats[static_cast<size_t>(in.root)][static_cast<size_t>(in.k) + 1];
          const int a = 4 * in.a + (j & 3), b = 4 * in.b + (j >> 2);
          const double n = static_cast<double>(L.g) * L.g;
          const Scale sc = scale_for(prm, n, L.g);
          e += point_energy({&L, nullptr, sc.inv_h2, sc.reach}, (a + ps[0]) / L.g,
                            (b + ps[1]) / L.g, a, b);
        }
        if (best_s < 0 || e < best) {
          best = e;
          best_s = s;
        }
      }
      if (best_s != tb.child[static_cast<size_t>(t)][static_cast<size_t>(j)]) {
        tb.child[static_cast<size_t>(t)][static_cast<size_t>(j)] = best_s;
        changed = true;
        // Siblings chosen next see this child where it now is.
        const auto& ps = tb.point[static_cast<size_t>(best_s)];
        for (const Instance& in : inst) {
          Level& L = lats[static_cast<size_t>(in.root)][static_cast<size_t>(in.k) + 1];
          const int a = 4 * in.a + (j & 3), b = 4 * in.b + (j >> 2);
          const auto i = static_cast<size_t>(b * L.g + a);
          L.type[i] = best_s;
          L.x[i] = (a + ps[0]) / L.g;
          L.y[i] = (b + ps[1]) / L.g;
        }
      }
    }
    if (changed) accept_or_revert(saved);
  }

  // Visiting orders (the paper's progressive traversal): the first m children of every tile of
  // level k form the prefix of m 16^k points, so child m is chosen, for all types at once, as
  // the free cell whose point is least crowded by the prefix of m 16^k points, over instances.
  void update_orders() {
    std::vector<std::array<char, kCells>> used(static_cast<size_t>(tb.types));
    for (int t = 0; t < tb.types; ++t) {
      used[static_cast<size_t>(t)].fill(0);
      used[static_cast<size_t>(t)][static_cast<size_t>(rep(tb, t))] = 1;
    }
    for (int m = 1; m < kCells; ++m) {
      // cost[t][j]: crowding of child j of type t given the first m children everywhere.
      std::vector<std::array<double, kCells>> cost(static_cast<size_t>(tb.types));
      for (auto& c : cost)
        c.fill(0.0);
      for (const Lattice& lat : lats)
        for (int k = 0; k < prm.levels; ++k) {
          const Level& up = lat[static_cast<size_t>(k)];
          const Level& L = lat[static_cast<size_t>(k) + 1];
          std::vector<char> occupied(L.type.size(), 0);
          for (int b = 0; b < up.g; ++b)
            for (int a = 0; a < up.g; ++a) {
              const int t = up.type[static_cast<size_t>(b * up.g + a)];
              for (int q = 0; q < m; ++q) {
                const int j = tb.order[static_cast<size_t>(t)][static_cast<size_t>(q)];
                occupied[static_cast<size_t>((4 * b + (j >> 2)) * L.g + 4 * a + (j & 3))] = 1;
              }
            }
          const double n = static_cast<double>(m + 1) * up.g * up.g;
          const Scale sc = scale_for(prm, n, L.g);
          const Field f{&L, &occupied, sc.inv_h2, sc.reach};
          for (int b = 0; b < up.g; ++b)
            for (int a = 0; a < up.g; ++a) {
              const int t = up.type[static_cast<size_t>(b * up.g + a)];
              for (int j = 0; j < kCells; ++j) {
                if (used[static_cast<size_t>(t)][static_cast<size_t>(j)]) continue;
                const int ca = 4 * a + (j & 3), cb = 4 * b + (j >> 2);
                const auto i = static_cast<size_t>(cb * L.g + ca);
                cost[static_cast<size_t>(t)][static_cast<size_t>(j)] +=
                    point_energy(f, L.x[i], L.y[i], ca, cb) / n;
              }
            }
        }
      for (int t = 0; t < tb.types; ++t) {
        int best = -1;
        for (int j = 0; j < kCells; ++j) {
          if (used[static_cast<size_t>(t)][static_cast<size_t>(j)]) continue;
          if (best < 0 || cost[static_cast<size_t>(t)][static_cast<size_t>(j)] <
                              cost[static_cast<size_t>(t)][static_cast<size_t>(best)])
            best = j;
        }
        auto& ord = tb.order[static_cast<size_t>(t)];
        std::swap(ord[static_cast<size_t>(m)], *std::find(ord.begin() + m, ord.end(), best));
        used[static_cast<size_t>(t)][static_cast<size_t>(best)] = 1;
      }
    }
  }

  void pick_roots(disklab::sequence::Pcg32& rng) {
    roots.clear();
    while (static_cast<int>(roots.size()) < prm.roots) {
      const int r = static_cast<int>(rng.next_u32() % static_cast<uint32_t>(tb.types));
      if (std::find(roots.begin(), roots.end(), r) == roots.end()) roots.push_back(r);
    }
  }
};

Table generate(const Params& prm, bool verbose) {
  g_short_ratio2 = (prm.radius / prm.short_radius) * (prm.radius / prm.short_radius);
  g_short_weight = prm.short_weight;
  disklab::sequence::Pcg32 rng(prm.seed);
  Optimizer opt;
  opt.prm = prm;
  Table& tb = opt.tb;
  tb.types = prm.types;
  tb.child.resize(static_cast<size_t>(prm.types));
  tb.order.resize(static_cast<size_t>(prm.types));
  // Start: random rules and orders (so random sharing chains: a jittered grid at every level).
  for (int t = 0; t < prm.types; ++t) {
    for (int j = 0; j < kCells; ++j) {
      tb.child[static_cast<size_t>(t)][static_cast<size_t>(j)] =
          static_cast<int>(rng.next_u32() % static_cast<uint32_t>(prm.types));
      tb.order[static_cast<size_t>(t)][static_cast<size_t>(j)] = j;
    }
    auto& ord = tb.order[static_cast<size_t>(t)];
    for (int j = kCells - 1; j > 0; --j)
      std::swap(ord[static_cast<size_t>(j)], ord[rng.next_u32() % static_cast<uint32_t>(j + 1)]);
  }
  for (int sweep = 0; sweep < prm.sweeps; ++sweep) {
    opt.pick_roots(rng);
    opt.rebuild();
    const double start = opt.energy;
    for (int t = 0; t < prm.types; ++t)
      opt.update_point(t);
    for (int t = 0; t < prm.types; ++t)
      opt.update_children(t);
    if (verbose)
      std::fprintf(stderr,
                   "reference_art: sweep %d: energy %.6g -> %.6g (%d changes kept, %d undone)\n",
                   sweep + 1, start, opt.energy, opt.accepted, opt.rejected);
  }
  // Orders on every type as a root (all of them serve as the seed's random root).
  opt.roots.clear();
  for (int r = 0; r < prm.types; r += std::max(1, prm.types / (2 * prm.roots)))
    opt.roots.push_back(r);
  opt.rebuild();
  opt.update_orders();
  derive_points(tb);
  return tb;
}

std::string fmt17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string params_line(const Params& p) {
  std::ostringstream s;
  s << "# parameters: seed=" << p.seed << " types=" << p.types << " levels=" << p.levels
    << " roots=" << p.roots << " sweeps=" << p.sweeps << " radius=" << fmt17(p.radius)
    << " candidates=" << p.candidates << " short_radius=" << fmt17(p.short_radius)
    << " short_weight=" << fmt17(p.short_weight);
  return s.str();
}

// The file without its date line (what --check compares).
std::string render(const Params& p, const Table& tb, const std::string& date) {
  std::string s;
  s += "# ART tile table: a tile-type set, its 4x4 subdivision rules, points and visiting orders\n";
  s += "# after Ahmed, Niese, Huang, Deussen 2017, \"An adaptive point sampler on a regular "
       "lattice\"\n";
  s += "# (ACM TOG 36(4)); our construction, not the published table (see reference/README.md).\n";
  s += "# generator: reference/generate/art.cpp (build/<preset>/bin/reference_art)\n";
  s += params_line(p);
  s += "\n";
  if (!date.empty()) {
    s += "# date: ";
    s += date;
    s += "\n";
  }
  s +=
      "# columns: type; x, y: the type's point in tile coordinates (derived: x = (c + x_child)/4\n";
  s += "# along the children o0, as the library recomputes it); c0..c15: child type of cell\n";
  s += "# j = jx + 4 jy; o0..o15: visiting order of the cells (o0 holds the tile's point)\n";
  s += "type,x,y";
  for (int j = 0; j < kCells; ++j) {
    s += ",c";
    s += std::to_string(j);
  }
  for (int j = 0; j < kCells; ++j) {
    s += ",o";
    s += std::to_string(j);
  }
  s += "\n";
  for (int t = 0; t < tb.types; ++t) {
    s += std::to_string(t);
    s += ",";
    s += fmt17(tb.point[static_cast<size_t>(t)][0]);
    s += ",";
    s += fmt17(tb.point[static_cast<size_t>(t)][1]);
    for (int j = 0; j < kCells; ++j) {
      s += ",";
      s += std::to_string(tb.child[static_cast<size_t>(t)][static_cast<size_t>(j)]);
    }
    for (int j = 0; j < kCells; ++j) {
      s += ",";
      s += std::to_string(tb.order[static_cast<size_t>(t)][static_cast<size_t>(j)]);
    }
    s += "\n";
  }
  return s;
}

std::string without_date(const std::string& text) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line))
    if (line.rfind("# date:", 0) != 0) {
      out += line;
      out += "\n";
    }
  return out;
}

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr,
               "reference_art: %s\nusage: reference_art --out FILE [--seed S] [--types T] "
               "[--levels K] [--roots R] [--sweeps W] [--radius H] [--candidates C]\n"
               "       reference_art --check FILE\n",
               why);
  std::exit(2);
}

// Reads the parameters back from a table's header.
Params parse_params(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# parameters:", 0) != 0) continue;
    Params p;
    std::istringstream words(line.substr(13));
    std::string w;
    while (words >> w) {
      const auto eq = w.find('=');
      if (eq == std::string::npos) usage("bad parameters line");
      const std::string key = w.substr(0, eq), value = w.substr(eq + 1);
      if (key == "seed")
        p.seed = std::stoull(value);
      else if (key == "types")
        p.types = std::stoi(value);
      else if (key == "levels")
        p.levels = std::stoi(value);
      else if (key == "roots")
        p.roots = std::stoi(value);
      else if (key == "sweeps")
        p.sweeps = std::stoi(value);
      else if (key == "radius")
        p.radius = std::stod(value);
      else if (key == "candidates")
        p.candidates = std::stoi(value);
      else if (key == "short_radius")
        p.short_radius = std::stod(value);
      else if (key == "short_weight")
        p.short_weight = std::stod(value);
      else
        usage("unknown parameter in the file's header");
    }
    return p;
  }
  usage("no '# parameters:' line in the file");
}

void validate(const Params& p) {
  if (p.types < 2 || p.types > 65535) usage("--types must be in [2, 65535]");
  if (p.levels < 1 || p.levels > 5) usage("--levels must be in [1, 5]");
  if (p.roots < 1 || p.roots > p.types) usage("--roots must be in [1, types]");
  if (p.sweeps < 0) usage("--sweeps must be >= 0");
  if (!(p.radius > 0.0 && p.radius <= 8.0)) usage("--radius must be in (0, 8]");
  if (p.candidates < 2 || p.candidates > kCells * p.types) usage("--candidates out of range");
  if (!(p.short_radius > 0.0 && p.short_radius <= p.radius)) usage("--short-radius in (0, radius]");
  if (!(p.short_weight >= 0.0)) usage("--short-weight must be >= 0");
}

}  // namespace

int main(int argc, char** argv) {
  Params p;
  std::string out, check;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) usage(("missing value after " + a).c_str());
    const std::string v = argv[++i];
    if (a == "--out")
      out = v;
    else if (a == "--check")
      check = v;
    else if (a == "--seed")
      p.seed = std::stoull(v);
    else if (a == "--types")
      p.types = std::stoi(v);
    else if (a == "--levels")
      p.levels = std::stoi(v);
    else if (a == "--roots")
      p.roots = std::stoi(v);
    else if (a == "--sweeps")
      p.sweeps = std::stoi(v);
    else if (a == "--radius")
      p.radius = std::stod(v);
    else if (a == "--candidates")
      p.candidates = std::stoi(v);
    else if (a == "--short-radius")
      p.short_radius = std::stod(v);
    else if (a == "--short-weight")
      p.short_weight = std::stod(v);
    else
      usage(("unknown option " + a).c_str());
  }
  if (out.empty() == check.empty()) usage("give exactly one of --out and --check");
  if (!check.empty()) {
    std::ifstream f(check);
    if (!f) usage(("cannot read " + check).c_str());
    std::stringstream ss;
    ss << f.rdbuf();
    const std::string committed = ss.str();
    const Params fp = parse_params(committed);
    validate(fp);
    const std::string fresh = render(fp, generate(fp, false), "");
    if (without_date(committed) != fresh) {
      std::fprintf(stderr, "reference_art: %s differs from its regeneration (%s)\n", check.c_str(),
                   params_line(fp).c_str());
      return 1;
    }
    std::printf("reference_art: %s regenerated identically (%s)\n", check.c_str(),
                params_line(fp).c_str());
    return 0;
  }
  validate(p);
  const Table tb = generate(p, true);
  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  const std::string text = render(p, tb, date);
  const std::string tmp = out + ".tmp";
  {
    std::ofstream f(tmp);
    f << text;
    if (!f) usage(("cannot write " + tmp).c_str());
  }
  std::filesystem::rename(tmp, out);
  std::fprintf(stderr, "reference_art: wrote %s\n", out.c_str());
  return 0;
}
