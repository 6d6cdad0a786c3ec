// Irradiance at a point under a disk light by multiple importance sampling: directions from
// the light (disklab's radial map) and from the receiver's cosine lobe, balance heuristic.
// Built with -fno-exceptions by the install test, which runs it.
#include <disklab/ellipse/any_map.h>

#include <cmath>
#include <cstdio>
#include <random>

int main() {
  using disklab::Vec3;
  namespace ellipse = disklab::ellipse;
  const double pi = 3.14159265358979323846;
  const ellipse::Disk light{Vec3(0, 0, 2), Vec3(0, 0, -1), 1.0, /*two_sided=*/false};
  const Vec3 point(0.5, 0, 0), normal(0, 0, 1);  // a receiver facing the light, L = 1

  const auto map = ellipse::AnyMap::make(ellipse::MapKind::radial, light, point);
  if (!map.valid()) return 1;  // the point sees nothing of the light

  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const int n = 1 << 16;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    double f = 0.0;
    // Strategy 1, the light: pdf in solid angle, and the cosine lobe's pdf of the same direction.
    const ellipse::EllipseSample s = map.sample({uniform(rng), uniform(rng)});
    if (s.valid) {
      const double cos_o = std::max(0.0, s.direction.dot(normal));
      f += cos_o / (s.pdf + cos_o / pi);
    }
    // Strategy 2, the cosine lobe about the normal: the light's pdf of that direction (0 where
    // it misses the light).
    const double r = std::sqrt(uniform(rng)), phi = 2 * pi * uniform(rng);
    const Vec3 w(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - r * r)));
    const double p_light = map.pdf(w);
    if (p_light > 0.0) f += w.dot(normal) / (p_light + w.dot(normal) / pi);
    sum += f;
    sum2 += f * f;
  }
  const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / (n - 1));

  // The exact irradiance from a facing disk (h = 2 below it, d = 0.5 off its axis, R = 1).
  const double h2 = 4.0, d2 = 0.25, r2 = 1.0;
  const double exact =
      pi / 2 * (1 - (h2 + d2 - r2) / std::sqrt((h2 + d2 + r2) * (h2 + d2 + r2) - 4 * d2 * r2));
  std::printf("E = %.6f +- %.6f (exact %.6f)\n", mean, se, exact);
  return std::abs(mean - exact) <= 5 * se ? 0 : 1;
}
