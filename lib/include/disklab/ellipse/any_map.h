#pragma once
// Every spherical-ellipse sampler behind one value type, chosen by its CLI name at run time (for
// the `disklab` CLI and for renderers that read the map from a scene file).
//
// Names: area, gamito, parallel, radial, ld-radial, radial4, tabulated, radial-fast, projected.
//
// Conventions (one per map family, stated once here):
//  - sample(u) is a pure function of u for every map, so it can be inverted and stratified:
//    gamito and tabulated run in PROPOSAL mode (one candidate per u; valid == accepted; pdf is
//    the proposal's solid-angle density, so (1/N) sum_{accepted} f / pdf is unbiased with N
//    counting every candidate, docs/design.md section 3 "Rejection must stay unbiased").
//  - radial4 yields copies() == 4 directions per u through sample_copies() (the ellipse's
//    reflections, counter-clockwise from quadrant 0, each with pdf 1/Omega; invert_copy() is
//    their inverse). sample(u) is a full-ellipse sample, the radial map's, so that an estimator
//    built on sample() alone stays unbiased.
//  - projected samples max(0, w . n_o) / P (projected.h): it needs the receiver's normal n_o
//    (the make overload that takes one); without it, n_o is the direction of the ellipse's
//    centre. The other maps ignore n_o.
//  - pdf is always in the solid-angle measure; `valid == false` means "no sample" (degenerate
//    geometry or a rejected candidate), never NaN.
//  - invert(direction) takes any non-zero direction (it need not be unit) and returns nothing
//    when the map has no inverse (gamito), the geometry is empty, or the direction misses the
//    disk (see contains()).
// Hot paths (sample, sample_copies, pdf, invert, contains) and make(MapKind, ...) allocate
// nothing and throw nothing; make(name, ...) throws std::invalid_argument for an unknown name
// (degenerate geometry gives !valid()). The tabulated map reads a table shared by the process,
// built once on first use (RadialTable::shared(); call it up front to keep that out of a render
// loop).
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "disklab/ellipse/area.h"
#include "disklab/ellipse/gamito.h"
#include "disklab/ellipse/ld_radial.h"
#include "disklab/ellipse/parallel.h"
#include "disklab/ellipse/projected.h"
#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/radial4.h"
#include "disklab/ellipse/radial_fast.h"
#include "disklab/ellipse/sampler.h"
#include "disklab/ellipse/tabulated.h"
#include "disklab/types.h"

namespace disklab::ellipse {

enum class MapKind {
  area,
  gamito,
  parallel,
  radial,
  ld_radial,
  radial4,
  tabulated,
  radial_fast,
  projected
};

// All names, in the order of MapKind.
const std::vector<std::string>& map_names();
// The kind of a name; nullopt when unknown.
std::optional<MapKind> parse_map(std::string_view name);
std::string_view map_name(MapKind kind);
// Whether invert() exists for the kind (every map but gamito: its candidates come from a
// rectangle sampler whose inverse this library does not provide).
bool map_has_inverse(MapKind kind);
// Whether the map is uniform in solid angle (pdf == 1/Omega for every valid sample).
// False for area, gamito, tabulated and projected.
bool map_is_uniform(MapKind kind);
// Directions per square point (4 for radial4, else 1).
int map_copies(MapKind kind);

class AnyMap {
 public:
  using Variant = std::variant<AreaSampler, GamitoSampler, ParallelMap, RadialMap, LdRadialMap,
                               Radial4Map, TabulatedMap, RadialFastMap, ProjectedMap>;

  // The map of `kind` for `disk` seen from the shading point `o`. Never throws, never
  // allocates; degenerate geometry gives a map with !valid().
  static AnyMap make(MapKind kind, const Disk& disk, const Vec3& o) noexcept;
  // The same with the receiver's normal at o (any non-zero length), which projected samples
  // the cosine of; a renderer can pass it for every kind.
  static AnyMap make(MapKind kind, const Disk& disk, const Vec3& o,
                     const Vec3& receiver_normal) noexcept;
  // By name, for the CLI and scene files. Throws std::invalid_argument("unknown
  // spherical-ellipse map 'x' (valid: ...)"); code built without exceptions uses parse_map and
  // the overload above.
  static AnyMap make(std::string_view name, const Disk& disk, const Vec3& o);
  static AnyMap make(std::string_view name, const Disk& disk, const Vec3& o,
                     const Vec3& receiver_normal);

  // The variant's alternatives are in MapKind's order.
  MapKind kind() const { return static_cast<MapKind>(map_.index()); }
  std::string_view name() const { return map_name(kind()); }
  bool has_inverse() const { return map_has_inverse(kind()); }
  int copies() const { return map_copies(kind()); }
  // False when the point sees nothing (behind the one-sided disk, in its plane, zero radius,
  // non-finite input): every sample is then "no sample".
  bool valid() const { return !geometry().empty; }
  // Solid angle of the disk seen from the point (0 when !valid()).
  double omega() const;
  // The map's geometry. projected's needs no solid angle: its omega and quadrant are 0 (omega()
  // computes the solid angle on demand).
  const MapGeometry& geometry() const;

  // One sample of the whole ellipse (for radial4: the radial map; a single candidate for gamito
  // and tabulated). `iterations` receives the Newton iterations of the maps that solve for a
  // root (else it is set to 0).
  EllipseSample sample(Point2 u, int* iterations = nullptr) const;
  // All copies of u into out[0..copies()-1]; returns copies(). radial4: the four reflections of
  // one first-quadrant sample (one root solve); the others: sample(u).
  int sample_copies(Point2 u, std::array<EllipseSample, 4>& out, int* iterations = nullptr) const;

  // Solid-angle density of `direction` (any non-zero length) as sample() would report it: 1/Omega
  // inside for the uniform maps, area's converted density, the proposal density for gamito and
  // tabulated (their single candidates), 0 where the direction misses the disk. The uniform
  // maps and area integrate to 1 over the sphere, gamito and tabulated to their acceptance rate.
  // What multiple importance sampling needs (pbrt-v4's Disk::PDF(ctx, wi)).
  double pdf(const Vec3& direction) const;

  // Whether the ray from the point along `direction` (any length) meets the disk: inside the
  // spherical ellipse (MapGeometry::contains).
  bool contains(const Vec3& direction) const { return geometry().contains(direction); }
  // Direction -> u with sample(u) in that direction (see the header comment for when it returns
  // nothing).
  std::optional<Point2> invert(const Vec3& direction) const;
  // For sample_copies: the u of which the direction is a copy, and which copy (radial4: its
  // quadrant k counter-clockwise from +x_e; the others: invert(), copy 0).
  std::optional<Point2> invert_copy(const Vec3& direction, int* copy = nullptr) const;

  // The concrete sampler, for what the common interface does not cover (e.g. gamito's
  // loop-until-accepted sample(u, rng)).
  const Variant& variant() const { return map_; }

 private:
  explicit AnyMap(Variant map) : map_(std::move(map)) {}
  Variant map_;
};

}  // namespace disklab::ellipse
