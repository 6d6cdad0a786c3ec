#include "study/scene.h"

namespace disklab::study {

std::vector<ShadingPoint> Region::points() const {
  std::vector<ShadingPoint> out;
  auto lin = [](double a, double b, int n, int i) {
    return n == 1 ? a : a + (b - a) * static_cast<double>(i) / (n - 1);
  };
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      out.push_back({Vec3(lin(x0, x1, nx, i), lin(y0, y1, ny, j), 0.0), Vec3::UnitZ()});
  return out;
}

}  // namespace disklab::study
