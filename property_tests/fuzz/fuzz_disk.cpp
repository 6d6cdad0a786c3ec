// libFuzzer: every disk strategy (disk/strategy.h) on square points from the fuzzer's bytes.
// Contracts: points finite and in the unit disk (pad-zero: in [-1, 1]^2, weight 0 outside the
// disk, 4/pi inside), weights finite and >= 0, copies of polar4/concentric4 are the four quarter
// turns of one point; the polar and concentric maps' inverses are in [0, 1]^2 and map back to the
// point to 1e-12 (their conditioning is bounded away from the centre, where the check is skipped).
#include <cmath>
#include <vector>

#include "disklab/disk/strategy.h"
#include "fuzz/fuzz_common.h"

namespace {
struct FuzzSequence {
  std::vector<disklab::Point2> points;
  disklab::Point2 at(uint32_t i) const { return points[i % points.size()]; }
};
constexpr double kRoundTrip = 1e-12;
constexpr double kCentre = 1e-6;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using disklab::Point2;
  namespace disk = disklab::disk;
  disklab::fuzz::Bytes in(data, size);
  FuzzSequence seq;
  for (int i = 0; i < 8; ++i)
    seq.points.push_back({in.unit(), in.unit()});
  for (const disk::Strategy st : disk::kAllStrategies) {
    disk::DiskSampler<FuzzSequence> sampler(st, seq);
    for (int i = 0; i < 8; ++i) {
      const disk::DiskSample s = sampler.next();
      FUZZ_CHECK(std::isfinite(s.point.x) && std::isfinite(s.point.y));
      FUZZ_CHECK(std::isfinite(s.weight) && s.weight >= 0.0);
      const double r2 = s.point.x * s.point.x + s.point.y * s.point.y;
      if (st == disk::Strategy::pad_zero) {
        FUZZ_CHECK(std::abs(s.point.x) <= 1.0 && std::abs(s.point.y) <= 1.0);
      } else if (s.weight > 0.0) {
        FUZZ_CHECK(r2 <= 1.0 + 4e-16);
      }
    }
  }
  for (const Point2& u : seq.points) {
    const Point2 pp = disk::sample_polar(u), pc = disk::sample_concentric(u);
    for (const bool polar : {true, false}) {
      const Point2 p = polar ? pp : pc;
      if (std::hypot(p.x, p.y) < kCentre) continue;
      const Point2 back = polar ? disk::invert_polar(p) : disk::invert_concentric(p);
      FUZZ_CHECK(back.x >= 0.0 && back.x <= 1.0 && back.y >= 0.0 && back.y <= 1.0);
      const Point2 again = polar ? disk::sample_polar(back) : disk::sample_concentric(back);
      FUZZ_CHECK(std::abs(again.x - p.x) <= kRoundTrip && std::abs(again.y - p.y) <= kRoundTrip);
    }
  }
  return 0;
}
