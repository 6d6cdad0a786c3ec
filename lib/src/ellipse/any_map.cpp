// Run-time dispatch over the spherical-ellipse samplers (any_map.h).
#include "disklab/ellipse/any_map.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace disklab::ellipse {
namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

// kind() reads the variant's index: the alternatives must be listed in MapKind's order.
template <MapKind K, class T>
constexpr bool kAlternative =
    std::is_same_v<std::variant_alternative_t<static_cast<std::size_t>(K), AnyMap::Variant>, T>;
static_assert(kAlternative<MapKind::area, AreaSampler> &&
              kAlternative<MapKind::gamito, GamitoSampler> &&
              kAlternative<MapKind::parallel, ParallelMap> &&
              kAlternative<MapKind::radial, RadialMap> &&
              kAlternative<MapKind::ld_radial, LdRadialMap> &&
              kAlternative<MapKind::radial4, Radial4Map> &&
              kAlternative<MapKind::tabulated, TabulatedMap> &&
              kAlternative<MapKind::radial_fast, RadialFastMap> &&
              kAlternative<MapKind::projected, ProjectedMap>);

}  // namespace

const std::vector<std::string>& map_names() {
  static const std::vector<std::string> names = {"area",      "gamito",      "parallel",
                                                 "radial",    "ld-radial",   "radial4",
                                                 "tabulated", "radial-fast", "projected"};
  return names;
}

std::optional<MapKind> parse_map(std::string_view name) {
  const auto& names = map_names();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<MapKind>(i);
  return std::nullopt;
}

std::string_view map_name(MapKind kind) {
  return map_names()[static_cast<std::size_t>(kind)];
}

bool map_has_inverse(MapKind kind) {
  return kind != MapKind::gamito;
}

bool map_is_uniform(MapKind kind) {
  // area: density |o - x|^2 / (A cos); gamito, tabulated: proposal densities; projected: the
  // receiver's cosine.
  return kind != MapKind::area && kind != MapKind::gamito && kind != MapKind::tabulated &&
         kind != MapKind::projected;
}

int map_copies(MapKind kind) {
  return kind == MapKind::radial4 ? 4 : 1;
}

namespace {
MapKind parse_map_or_throw(std::string_view name) {
  const auto kind = parse_map(name);
  if (!kind) {
    std::string valid;
    for (const auto& n : map_names())
      valid += (valid.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown spherical-ellipse map '" + std::string(name) +
                                "' (valid: " + valid + ")");
  }
  return *kind;
}
}  // namespace

AnyMap AnyMap::make(std::string_view name, const Disk& disk, const Vec3& o) {
  return make(parse_map_or_throw(name), disk, o);
}

AnyMap AnyMap::make(std::string_view name, const Disk& disk, const Vec3& o,
                    const Vec3& receiver_normal) {
  return make(parse_map_or_throw(name), disk, o, receiver_normal);
}

AnyMap AnyMap::make(MapKind kind, const Disk& disk, const Vec3& o,
                    const Vec3& receiver_normal) noexcept {
  if (kind == MapKind::projected) return AnyMap(ProjectedMap::make(disk, o, receiver_normal));
  return make(kind, disk, o);
}

AnyMap AnyMap::make(MapKind kind, const Disk& disk, const Vec3& o) noexcept {
  switch (kind) {
    case MapKind::area:
      return AnyMap(AreaSampler::make(disk, o));
    case MapKind::gamito:
      return AnyMap(GamitoSampler::make(disk, o));
    case MapKind::parallel:
      return AnyMap(ParallelMap::make(disk, o));
    case MapKind::radial:
      return AnyMap(RadialMap::make(disk, o));
    case MapKind::ld_radial:
      return AnyMap(LdRadialMap::make(disk, o));
    case MapKind::radial4:
      return AnyMap(Radial4Map::make(disk, o));
    case MapKind::tabulated:
      return AnyMap(TabulatedMap::make(disk, o));
    case MapKind::radial_fast:
      return AnyMap(RadialFastMap::make(disk, o));
    case MapKind::projected:
      return AnyMap(ProjectedMap::make(disk, o));
  }
  return AnyMap(AreaSampler{});  // not reached: every kind is listed
}

double AnyMap::omega() const {
  if (!valid()) return 0.0;
  if (const auto* p = std::get_if<ProjectedMap>(&map_)) return p->solid_angle();
  return geometry().omega;
}

const MapGeometry& AnyMap::geometry() const {
  return std::visit(Overloaded{
                        [](const LdRadialMap& m) -> const MapGeometry& { return m.radial.g; },
                        [](const Radial4Map& m) -> const MapGeometry& { return m.radial.g; },
                        [](const RadialFastMap& m) -> const MapGeometry& { return m.radial.g; },
                        [](const auto& m) -> const MapGeometry& { return m.g; },
                    },
                    map_);
}

EllipseSample AnyMap::sample(Point2 u, int* iterations) const {
  if (iterations) *iterations = 0;
  return std::visit(Overloaded{
                        [&](const AreaSampler& m) { return m.sample(u); },
                        [&](const GamitoSampler& m) { return m.propose(u); },
                        [&](const TabulatedMap& m) { return m.sample(u); },
                        [&](const auto& m) { return m.sample(u, iterations); },
                    },
                    map_);
}

int AnyMap::sample_copies(Point2 u, std::array<EllipseSample, 4>& out, int* iterations) const {
  if (const auto* m = std::get_if<Radial4Map>(&map_)) {
    if (iterations) *iterations = 0;
    out = m->sample4(u, iterations);
    return 4;
  }
  out[0] = sample(u, iterations);
  return 1;
}

double AnyMap::pdf(const Vec3& direction) const {
  return std::visit([&](const auto& m) { return m.pdf(direction); }, map_);
}

std::optional<Point2> AnyMap::invert(const Vec3& direction) const {
  // projected's image is the part of the disk above the receiver's horizon.
  if (const auto* p = std::get_if<ProjectedMap>(&map_)) {
    // The same finite answer as every map below (projected's seam can give NaN near the rim).
    const auto u = p->invert(direction);
    if (u && std::isfinite(u->x) && std::isfinite(u->y)) return u;
    return std::nullopt;
  }
  if (!has_inverse() || !contains(direction)) return std::nullopt;
  const Vec3 d = unit_vector(direction);
  const MapGeometry& g = geometry();
  const Vec3 l = g.to_local(d);
  const Point2 u = std::visit(Overloaded{
                                  [&](const AreaSampler& m) { return m.invert(d); },
                                  [&](const GamitoSampler&) { return Point2{}; },
                                  [&](const auto& m) { return m.invert_local(l); },
                              },
                              map_);
  if (!std::isfinite(u.x) || !std::isfinite(u.y)) return std::nullopt;
  return u;
}

std::optional<Point2> AnyMap::invert_copy(const Vec3& direction, int* copy) const {
  if (copy) *copy = 0;
  const auto* m = std::get_if<Radial4Map>(&map_);
  if (m == nullptr) return invert(direction);
  if (!contains(direction)) return std::nullopt;
  int k = 0;
  const Point2 u = m->invert_copy_local(geometry().to_local(unit_vector(direction)), k);
  if (!std::isfinite(u.x) || !std::isfinite(u.y)) return std::nullopt;
  if (copy) *copy = k;
  return u;
}

}  // namespace disklab::ellipse
