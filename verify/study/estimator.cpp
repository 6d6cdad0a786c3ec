#include "study/estimator.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "disklab/math/constants.h"

namespace disklab::study {

std::vector<AreaSample> disk_samples(disk::Strategy strategy, const sequence::Sequence& seq,
                                     uint32_t count) {
  std::vector<AreaSample> out(count);
  disk::DiskSampler<sequence::Sequence> sampler(strategy, seq);
  for (uint32_t i = 0; i < count; ++i) {
    const disk::DiskSample d = sampler.next();
    out[i] = {d.point, d.weight};
  }
  return out;
}

uint32_t square_points_needed(disk::Strategy strategy, uint32_t count) {
  switch (strategy) {
    case disk::Strategy::rejection:
      // Accepted count ~ (pi/4) x square points; 1.5 x count is ~16 standard deviations above
      // the mean of 4/pi x count for count >= 16.
      return count + count / 2 + 64;
    case disk::Strategy::polar4:
    case disk::Strategy::concentric4:
      return (count + 3) / 4;
    default:
      return count;
  }
}

void progressive_irradiance(const Scene& scene, const ShadingPoint& sp,
                            std::span<const AreaSample> samples, std::span<const uint32_t> ns,
                            std::span<double> out) {
  if (out.size() != ns.size()) throw std::invalid_argument("progressive_irradiance: sizes differ");
  if (!ns.empty() && ns.back() > samples.size())
    throw std::invalid_argument("progressive_irradiance: fewer samples than the largest N");
  const double area = math::kPi * scene.light.radius * scene.light.radius;
  double sum = 0.0;
  std::size_t k = 0;
  for (uint32_t i = 0; i < samples.size() && k < ns.size(); ++i) {
    const AreaSample& s = samples[i];
    if (s.weight != 0.0)
      sum += s.weight * irradiance_integrand(scene, sp, scene.light.point(s.point));
    while (k < ns.size() && ns[k] == i + 1) {
      out[k] = area * sum / (i + 1);
      ++k;
    }
  }
}

ellipse::AnyMap light_map(ellipse::MapKind kind, const Scene& scene, const ShadingPoint& sp) {
  const DiskLight& l = scene.light;
  return ellipse::AnyMap::make(kind, ellipse::Disk{l.center, l.normal, l.radius, l.two_sided},
                               sp.position, sp.normal);
}

void progressive_irradiance(const Scene& scene, const ShadingPoint& sp, const ellipse::AnyMap& map,
                            std::span<const Point2> u, std::span<const uint32_t> ns,
                            std::span<double> out, std::span<uint64_t> newton) {
  if (out.size() != ns.size()) throw std::invalid_argument("progressive_irradiance: sizes differ");
  const auto copies = static_cast<uint32_t>(map.copies());
  if (!ns.empty() && ns.back() > static_cast<uint64_t>(u.size()) * copies)
    throw std::invalid_argument("progressive_irradiance: fewer points than the largest N");
  const double radiance = scene.light.radiance;
  auto value = [&](const ellipse::EllipseSample& s) {
    if (!s.valid) return 0.0;
    const double cos_o = s.direction.dot(sp.normal);
    if (!(cos_o > 0.0) || occluded(scene, sp.position, s.point)) return 0.0;
    return radiance * cos_o / s.pdf;
  };
  std::array<ellipse::EllipseSample, 4> copy;
  double sum = 0.0;
  std::size_t k = 0;
  for (uint32_t i = 0; i < u.size() && k < ns.size(); ++i) {
    int iterations = 0;
    const int m = map.sample_copies(u[i], copy, newton.empty() ? nullptr : &iterations);
    for (int c = 0; c < m; ++c)
      sum += value(copy[c]);
    if (!newton.empty()) ++newton[std::min<std::size_t>(iterations, newton.size() - 1)];
    const uint64_t done = static_cast<uint64_t>(i + 1) * copies;
    while (k < ns.size() && ns[k] == done) {
      out[k] = sum / static_cast<double>(done);
      ++k;
    }
  }
}

}  // namespace disklab::study
