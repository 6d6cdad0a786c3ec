// libFuzzer: every spherical-ellipse map (any_map.h, by map_names(), so a map added later is
// fuzzed too) on any disk, point and u: make, sample, sample_copies, pdf, invert, contains. The
// contracts are ellipse/contracts.h's (finite fields, unit direction, on the disk to a unit
// direction's resolution, pdf(direction) == the sample's pdf, inverse round trip), plus: an
// invalid map never samples; u outside [0, 1]^2 is no sample; pdf, contains and invert of any
// direction are finite, and invert only answers where contains() is true, with u in [0, 1]^2.
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "disklab/ellipse/any_map.h"
#include "disklab/ellipse/contracts.h"
#include "fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using disklab::Point2;
  using disklab::Vec3;
  namespace ellipse = disklab::ellipse;
  disklab::fuzz::Bytes in(data, size);
  const auto& names = ellipse::map_names();
  const auto kind = static_cast<ellipse::MapKind>(in.u8() % names.size());
  const uint8_t mode = in.u8();
  ellipse::Disk disk;
  Vec3 o;
  if (mode & 1) {  // raw doubles: NaN, Inf, subnormals, anything
    for (int i = 0; i < 3; ++i)
      disk.center[i] = in.any_double();
    for (int i = 0; i < 3; ++i)
      disk.normal[i] = in.any_double();
    disk.radius = in.any_double();
    for (int i = 0; i < 3; ++i)
      o[i] = in.any_double();
  } else {  // a moderate scene: coordinates in [-4, 4], radius in (0, 2]
    for (int i = 0; i < 3; ++i)
      disk.center[i] = 8.0 * in.unit() - 4.0;
    for (int i = 0; i < 3; ++i)
      disk.normal[i] = 2.0 * in.unit() - 1.0;
    disk.radius = 2.0 * in.unit() + 1e-3;
    for (int i = 0; i < 3; ++i)
      o[i] = 8.0 * in.unit() - 4.0;
  }
  disk.two_sided = mode & 2;
  const auto m = ellipse::AnyMap::make(kind, disk, o);
  // On a violation, the whole chain: scene, map, u, sample (%.17g, reads back exactly).
  auto show = [&](const Point2& u, const ellipse::EllipseSample& s, ellipse::Violation v) {
    std::fprintf(stderr,
                 "map %s c=(%.17g,%.17g,%.17g) n=(%.17g,%.17g,%.17g) r=%.17g two_sided=%d "
                 "o=(%.17g,%.17g,%.17g) u=(%.17g,%.17g) dir=(%.17g,%.17g,%.17g) pdf=%.17g: %s\n",
                 std::string(m.name()).c_str(), disk.center.x(), disk.center.y(), disk.center.z(),
                 disk.normal.x(), disk.normal.y(), disk.normal.z(), disk.radius,
                 int(disk.two_sided), o.x(), o.y(), o.z(), u.x, u.y, s.direction.x(),
                 s.direction.y(), s.direction.z(), s.pdf, ellipse::violation_name(v));
    return v;
  };
  for (int k = 0; k < 4; ++k) {
    const Point2 u =
        (mode & 4) ? Point2{in.any_double(), in.any_double()} : Point2{in.unit(), in.unit()};
    const ellipse::EllipseSample s = m.sample(u);
    const bool in_domain = u.x >= 0.0 && u.x <= 1.0 && u.y >= 0.0 && u.y <= 1.0;
    if (!m.valid() || !in_domain) FUZZ_CHECK(!s.valid);
    const ellipse::Violation v = ellipse::check_sample(m, s);
    const ellipse::Violation vi = ellipse::check_inverse(m, s);
    if (v != ellipse::Violation::none) show(u, s, v);
    if (vi != ellipse::Violation::none) show(u, s, vi);
    FUZZ_CHECK(v == ellipse::Violation::none);
    FUZZ_CHECK(vi == ellipse::Violation::none);
    std::array<ellipse::EllipseSample, 4> copies;
    const int n = m.sample_copies(u, copies);
    FUZZ_CHECK(n == m.copies());
    for (int c = 0; c < n; ++c) {
      if (!in_domain) FUZZ_CHECK(!copies[c].valid);
      FUZZ_CHECK(ellipse::check_sample(m, copies[c]) == ellipse::Violation::none);
    }
  }
  const Vec3 d(in.any_double(), in.any_double(), in.any_double());
  const double p = m.pdf(d);
  FUZZ_CHECK(std::isfinite(p) && p >= 0.0);
  const bool inside = m.contains(d);
  if (!inside) FUZZ_CHECK(p == 0.0);
  if (const auto u = m.invert(d)) {
    FUZZ_CHECK(inside);
    FUZZ_CHECK(u->x >= 0.0 && u->x <= 1.0 && u->y >= 0.0 && u->y <= 1.0);
  }
  return 0;
}
