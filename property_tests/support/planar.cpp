#include "support/planar.h"

#include <algorithm>
#include <cmath>

namespace disklab::test {
namespace {

// int_0^x sqrt(1 - t^2) dt = (x sqrt(1 - x^2) + asin x) / 2.
double half_chord_integral(double x) {
  x = std::clamp(x, -1.0, 1.0);
  return 0.5 * (x * std::sqrt(1.0 - x * x) + std::asin(x));
}

}  // namespace

double disk_rect_area(double x0, double x1, double y0, double y1) {
  x0 = std::max(x0, -1.0);
  x1 = std::min(x1, 1.0);
  if (!(x0 < x1) || !(y0 < y1)) return 0.0;
  // The vertical extent at x is [max(y0, -h), min(y1, h)], h = sqrt(1 - x^2). It changes form
  // only where h crosses |y0| or |y1|, i.e. at x = +-sqrt(1 - c^2): split there, then each piece
  // is a constant, +-h plus a constant, 2h, or empty, integrated exactly.
  std::vector<double> cuts{x0, x1};
  for (double c : {y0, y1}) {
    if (std::fabs(c) <= 1.0) {  // |c| = 1 cuts at x = 0, where the circle touches y = c
      const double s = std::sqrt(1.0 - c * c);
      for (double x : {-s, s})
        if (x > x0 && x < x1) cuts.push_back(x);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  double area = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double a = cuts[i], b = cuts[i + 1];
    if (!(a < b)) continue;
    const double mid = 0.5 * (a + b);
    const double h = std::sqrt(std::max(0.0, 1.0 - mid * mid));
    const bool top_is_circle = h < y1;      // upper end is +h, else y1
    const bool bottom_is_circle = -h > y0;  // lower end is -h, else y0
    const double top_mid = top_is_circle ? h : y1;
    const double bottom_mid = bottom_is_circle ? -h : y0;
    if (!(top_mid > bottom_mid)) continue;  // empty column on this piece
    const double hint = half_chord_integral(b) - half_chord_integral(a);  // int h dx
    const double top = top_is_circle ? hint : y1 * (b - a);
    const double bottom = bottom_is_circle ? -hint : y0 * (b - a);
    area += top - bottom;
  }
  return area;
}

}  // namespace disklab::test
