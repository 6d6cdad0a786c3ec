#include "study/estimator.h"

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

}  // namespace disklab::study
