// Set-up and sampling allocate nothing (any_map.h's contract for renderers): the global operator
// new of this test binary counts the allocations made while a map is built, sampled, evaluated
// and inverted, for every map on every configuration, and that count must be zero. The
// tabulated map's process-wide table is built once beforehand (RadialTable::shared()).
#include <gtest/gtest.h>

#include <cstdlib>
#include <new>

#include "disklab/ellipse/any_map.h"
#include "disklab/ellipse/area_lean.h"
#include "ellipse/map_common.h"

namespace {
thread_local bool counting = false;
thread_local long allocations = 0;
}  // namespace

// The replacements pair malloc with free; GCC (-O1 and up) inlines a delete next to a `new T`
// and warns as if the built-in operator new had allocated (-Wmismatched-new-delete), which is
// not what runs here.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t size) {
  if (counting) ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  return ::operator new(size);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

namespace disklab::test {
namespace {

TEST(MapAllocation, SetUpSamplingAndPdfAllocateNothing) {
  (void)ellipse::RadialTable::shared();
  // The counter works: a vector allocates.
  counting = true;
  allocations = 0;
  { const std::vector<int> v(3); }
  counting = false;
  ASSERT_EQ(allocations, 1);

  for (const DiskConfig& c : map_configs()) {
    for (const std::string& name : ellipse::map_names()) {
      const ellipse::MapKind kind = *ellipse::parse_map(name);
      counting = true;
      allocations = 0;
      const ellipse::AnyMap m = ellipse::AnyMap::make(kind, c.disk(), c.point);
      std::array<ellipse::EllipseSample, 4> out;
      double sink = 0.0;
      for (int i = 0; i < 16; ++i) {
        const Point2 u{(i + 0.5) / 16, (i * 7 % 16 + 0.5) / 16};
        const ellipse::EllipseSample s = m.sample(u);
        m.sample_copies(u, out);
        sink += m.pdf(s.direction) + (m.invert(s.direction) ? 1.0 : 0.0);
      }
      counting = false;
      EXPECT_EQ(allocations, 0) << name << " on " << c.describe() << " (sink " << sink << ")";
    }
    // The lean area sampler (bench_maps' baseline): the light once, then per shading point.
    counting = true;
    allocations = 0;
    const ellipse::LeanDiskLight light = ellipse::LeanDiskLight::make(c.disk());
    const ellipse::LeanAreaSampler lean = ellipse::LeanAreaSampler::make(light, c.point);
    double sink = 0.0;
    for (int i = 0; i < 16; ++i) {
      const ellipse::LightSample s = lean.sample({(i + 0.5) / 16, (i * 7 % 16 + 0.5) / 16});
      sink += lean.pdf(s.direction);
    }
    counting = false;
    EXPECT_EQ(allocations, 0) << "lean area on " << c.describe() << " (sink " << sink << ")";
  }
}

}  // namespace
}  // namespace disklab::test
