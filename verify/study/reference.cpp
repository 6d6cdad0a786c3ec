#include "study/reference.h"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "disklab/math/constants.h"

namespace disklab::study {

double disk_irradiance_parallel(double radiance, double radius, double height, double offset) {
  const double h2 = height * height;
  const double y = std::sqrt(h2 + (offset - radius) * (offset - radius)) *
                   std::sqrt(h2 + (offset + radius) * (offset + radius));
  const double x = h2 + offset * offset - radius * radius;
  // x >= 0: 1 - x / y cancels, y + x does not. x < 0 (under the disk, close to it): the
  // other way round.
  if (x >= 0.0) return 2.0 * math::kPi * radiance * radius * radius * h2 / (y * (y + x));
  return 0.5 * math::kPi * radiance * (1.0 - x / y);
}

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Rim samples searched for sign changes of the shadow cone along the disk's boundary: the
// shadow of one sphere is a conic, which meets a circle at most 4 times, and these scenes put
// those crossings far more than 2 pi / 4096 apart (a missed pair would show in the error
// estimate as a kink the adaptive rule has to resolve).
constexpr int kRimSearch = 4096;
// Adaptive Gauss-Legendre: 20 nodes per panel, every breakpoint interval split into 4 panels
// before the first comparison, at most 40 levels of bisection and a budget of ray evaluations
// (the error estimate then reports what is left). A panel is also accepted once its two halves
// agree to within their rounding estimates: the halved tolerance would otherwise fall below
// what double can resolve and the bisection would never stop.
constexpr int kInitialPanels = 4;
constexpr int kMaxDepth = 40;
constexpr long kRayBudget = 4'000'000;
constexpr double kNoiseFloor = 16.0 * kEps;
using Rule = boost::math::quadrature::gauss<double, 20>;

struct Occluder {
  double wx = 0.0, wy = 0.0;  // in-plane components of w = centre - o
  double b = 0.0;             // w . v at rho = 0, i.e. -h (w . n)
  double k = 0.0;             // |w|^2 - r^2 > 0: o outside the sphere
  double r = 0.0;
};

// The shading point seen from the light's plane: everything a ray integral needs.
struct Setup {
  const Scene* scene = nullptr;
  Vec3 o, n;                  // shading point; light normal turned towards o
  Vec3 foot;                  // o - h n, the origin of the polar coordinates
  double h = 0.0;             // distance from o to the plane (> 0)
  double px = 0.0, py = 0.0;  // the foot relative to the disk centre, in (axis_x, axis_y)
  double radius = 0.0, radiance = 0.0;
  double a = 0.0;             // -n . n_o: d cos_o = h a + rho b(theta)
  double bx = 0.0, by = 0.0;  // b(theta) = bx cos(theta) + by sin(theta)
  std::vector<Occluder> occluders;
};

// The radial integral int_{ra}^{rb} f(rho) rho drho along one ray, f = L cos_o cos_l / d^2, in
// closed form (with d cos_o = h a + rho b, d cos_l = h, d^2 = h^2 + rho^2), written with
// dr = rb - ra passed in so that a short or distant interval does not cancel:
//   a-term: (L a / 2) h^2 dr (ra + rb) / (Pa Pb),                    P = h^2 + rho^2,
//   b-term: (L b / 2) (atan2(h dr, h^2 + ra rb) - h dr (h^2 - ra rb) / (Pa Pb)).
struct RayValue {
  double value = 0.0;
  double rounding = 0.0;  // an estimate of the rounding error of value
};
RayValue radial_integral(const Setup& s, double b, double ra, double rb, double dr) {
  const double h2 = s.h * s.h, pa = h2 + ra * ra, pb = h2 + rb * rb;
  const double ta = s.a * h2 * dr * (ra + rb) / (pa * pb);
  const double t1 = std::atan2(s.h * dr, h2 + ra * rb);
  const double t2 = s.h * dr * (h2 - ra * rb) / (pa * pb);
  const double value = 0.5 * s.radiance * (ta + b * (t1 - t2));
  return {value, 8.0 * kEps * 0.5 * std::fabs(s.radiance) *
                     (std::fabs(ta) + std::fabs(b) * (std::fabs(t1) + std::fabs(t2)))};
}

// |f(rho) rho| at an end of a run: what an error in that end's position costs per unit length.
double radial_density(const Setup& s, double b, double rho) {
  const double d2 = s.h * s.h + rho * rho;
  return std::fabs(s.radiance * s.h * (s.h * s.a + b * rho) * rho / (d2 * d2));
}

// Stable roots of c2 x^2 + 2 c1 x + c0 = 0 given the discriminant c1^2 - c2 c0 >= 0.
void push_roots(double c2, double c1, double c0, double disc, std::vector<double>& out) {
  const double t = -(c1 + std::copysign(std::sqrt(disc), c1));
  if (c2 != 0.0) out.push_back(t / c2);
  if (t != 0.0) out.push_back(c0 / t);
}

// Visible part of the ray foot + rho u(theta) inside the disk, integrated in closed form.
RayValue ray_integral(const Setup& s, double theta, std::vector<double>& cuts) {
  const double ux = std::cos(theta), uy = std::sin(theta);
  // Disk: |P + rho U| = R. Discriminant R^2 - (P x U)^2 formed as a product (no cancellation).
  const double pu = s.px * ux + s.py * uy;
  const double cross = std::fabs(s.px * uy - s.py * ux);
  const double disc = (s.radius - cross) * (s.radius + cross);
  if (disc < 0.0) return {};
  const double pr = std::hypot(s.px, s.py);
  const double c0 = (pr - s.radius) * (pr + s.radius);
  const double sq = std::sqrt(disc);
  double lo, hi;
  if (-pu > 0.0) {
    hi = -pu + sq;
    lo = c0 / hi;
  } else {
    lo = -pu - sq;
    hi = lo != 0.0 ? c0 / lo : sq;
  }
  // The chord between the two roots is 2 sq exactly, however far the disk is.
  const bool chord = lo >= 0.0;
  lo = std::max(lo, 0.0);
  if (!(hi > lo)) return {};

  cuts.clear();
  cuts.push_back(lo);
  for (const Occluder& oc : s.occluders) {
    // Shadow cone: q(rho) = (A rho + B)^2 - K (h^2 + rho^2) >= 0 with A rho + B > 0. Its
    // discriminant is K h^2 (r^2 - (w_par x U)^2), again formed as a product.
    const double a = oc.wx * ux + oc.wy * uy;
    const double wc = std::fabs(oc.wx * uy - oc.wy * ux);
    const double qdisc = oc.k * s.h * s.h * (oc.r - wc) * (oc.r + wc);
    if (qdisc >= 0.0)
      push_roots(a * a - oc.k, a * oc.b, oc.b * oc.b - oc.k * s.h * s.h, qdisc, cuts);
    if (a != 0.0) cuts.push_back(-oc.b / a);
  }
  cuts.push_back(hi);
  std::sort(cuts.begin() + 1, cuts.end() - 1);

  const double b = s.bx * ux + s.by * uy;
  const Vec3 u = ux * s.scene->light.axis_x + uy * s.scene->light.axis_y;
  RayValue sum;
  double run_start = -1.0;  // start of the current visible run, or -1
  double prev = lo;
  auto close_run = [&](double end) {
    if (run_start < 0.0) return;
    if (s.h * s.a + b * run_start < -1e-12 * s.h || s.h * s.a + b * end < -1e-12 * s.h)
      throw std::domain_error("the disk crosses the receiver's horizon");
    const bool whole = chord && run_start == lo && end == hi;
    const RayValue v = radial_integral(s, b, run_start, end, whole ? 2.0 * sq : end - run_start);
    sum.value += v.value;
    // Each end is a computed root, off by a few ulps of its distance (a chord's two ends move
    // together: its length 2 sq is what matters, and its rounding is in v).
    sum.rounding += v.rounding;
    if (!whole)
      sum.rounding +=
          8.0 * kEps *
          (radial_density(s, b, run_start) * run_start + radial_density(s, b, end) * end);
    run_start = -1.0;
  };
  for (std::size_t i = 1; i < cuts.size(); ++i) {
    const double next = std::clamp(cuts[i], lo, hi);
    if (next <= prev) continue;
    const double mid = 0.5 * (prev + next);
    const bool visible = !occluded(*s.scene, s.o, s.foot + mid * u);
    if (visible && run_start < 0.0) run_start = prev;
    if (!visible) close_run(prev);
    prev = next;
  }
  close_run(hi);
  return sum;
}

double wrap_into(double theta, double lo) {
  return lo + std::fmod(std::fmod(theta - lo, math::kTwoPi) + math::kTwoPi, math::kTwoPi);
}

// Angles (in [lo, lo + 2 pi)) where the rays' visible intervals change shape.
std::vector<double> breakpoints(const Setup& s, double lo) {
  std::vector<double> out;
  for (const Occluder& oc : s.occluders) {
    const double w = std::hypot(oc.wx, oc.wy);
    if (w > oc.r) {  // rays tangent to the shadow cone: |w_par x U| = r
      const double tw = std::atan2(oc.wy, oc.wx), beta = std::asin(oc.r / w);
      for (double t : {tw + beta, tw - beta, tw + math::kPi - beta, tw + math::kPi + beta})
        out.push_back(wrap_into(t, lo));
    }
  }
  // Where the shadow's boundary crosses the rim: sign changes of the cone function along it.
  {
    auto cone = [&](const Occluder& oc, double t) {
      const double x = s.radius * std::cos(t) - s.px, y = s.radius * std::sin(t) - s.py;
      const double wv = oc.b + oc.wx * x + oc.wy * y;
      const double vv = s.h * s.h + x * x + y * y;
      return wv > 0.0 ? wv * wv - oc.k * vv : -oc.k * vv;
    };
    for (const Occluder& oc : s.occluders) {
      double t0 = 0.0, g0 = cone(oc, t0);
      for (int i = 1; i <= kRimSearch; ++i) {
        const double t1 = math::kTwoPi * i / kRimSearch, g1 = cone(oc, t1);
        if ((g0 >= 0.0) != (g1 >= 0.0)) {
          double a = t0, b = t1;
          const bool a_in = g0 >= 0.0;
          for (int it = 0; it < 80 && b - a > 4.0 * kEps * b; ++it) {
            const double m = 0.5 * (a + b);
            ((cone(oc, m) >= 0.0) == a_in ? a : b) = m;
          }
          const double t = 0.5 * (a + b);
          out.push_back(wrap_into(
              std::atan2(s.radius * std::sin(t) - s.py, s.radius * std::cos(t) - s.px), lo));
        }
        t0 = t1;
        g0 = g1;
      }
    }
  }
  return out;
}

struct Panel {
  double value = 0.0, rounding = 0.0;
};

struct Integrator {
  const Setup* s;
  std::vector<double> cuts;
  double error = 0.0;
  long rays = 0;

  // One breakpoint interval [ta, tb], theta = ta + (tb - ta)(3 t^2 - 2 t^3): dtheta/dt vanishes
  // at both ends like t and 1 - t, which turns the square-root behaviour of the intervals at
  // a tangent into an analytic integrand. Gauss-Legendre on [lo, hi] in t, with the rounding
  // estimates integrated by the same rule.
  Panel panel(double ta, double tb, double lo, double hi) {
    const auto& x = Rule::abscissa();
    const auto& w = Rule::weights();
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    Panel p;
    auto node = [&](double t, double weight) {
      ++rays;
      const double theta = ta + (tb - ta) * t * t * (3.0 - 2.0 * t);
      const double jac = (tb - ta) * 6.0 * t * (1.0 - t);
      const RayValue v = ray_integral(*s, theta, cuts);
      p.value += weight * v.value * jac;
      p.rounding += weight * v.rounding * std::fabs(jac);
    };
    for (std::size_t i = 0; i < x.size(); ++i) {
      node(mid + half * x[i], w[i]);
      if (x[i] != 0.0) node(mid - half * x[i], w[i]);
    }
    p.value *= half;
    p.rounding *= half;
    return p;
  }
  Panel adapt(double ta, double tb, double lo, double hi, const Panel& whole, double tol,
              int depth) {
    const double mid = 0.5 * (lo + hi);
    const Panel left = panel(ta, tb, lo, mid), right = panel(ta, tb, mid, hi);
    const double diff = std::fabs(left.value + right.value - whole.value);
    const double noise = left.rounding + right.rounding + kNoiseFloor * std::fabs(whole.value);
    if (diff <= tol || diff <= noise || depth >= kMaxDepth || rays > kRayBudget) {
      error += diff;
      return {left.value + right.value, left.rounding + right.rounding};
    }
    const Panel a = adapt(ta, tb, lo, mid, left, 0.5 * tol, depth + 1);
    const Panel b = adapt(ta, tb, mid, hi, right, 0.5 * tol, depth + 1);
    return {a.value + b.value, a.rounding + b.rounding};
  }
};

}  // namespace

ReferenceValue irradiance_quadrature(const Scene& scene, const ShadingPoint& sp, double rel_tol) {
  const DiskLight& light = scene.light;
  Setup s;
  s.scene = &scene;
  s.o = sp.position;
  s.n = light.normal;
  double side = (sp.position - light.center).dot(s.n);
  if (side < 0.0 && light.two_sided) {
    s.n = -s.n;
    side = -side;
  }
  if (!(side > 0.0) || !(light.radius > 0.0) || light.radiance == 0.0) return {0.0, 0.0};
  s.h = side;
  s.foot = sp.position - side * s.n;
  s.px = (s.foot - light.center).dot(light.axis_x);
  s.py = (s.foot - light.center).dot(light.axis_y);
  s.radius = light.radius;
  s.radiance = light.radiance;
  s.a = -s.n.dot(sp.normal);
  s.bx = light.axis_x.dot(sp.normal);
  s.by = light.axis_y.dot(sp.normal);
  for (const Sphere& sphere : scene.occluders) {
    const Vec3 w = sphere.center - sp.position;
    const double k = w.squaredNorm() - sphere.radius * sphere.radius;
    if (!(k > 0.0)) throw std::domain_error("the shading point is inside an occluder");
    const double plane = (sphere.center - light.center).dot(s.n);
    if (plane < -sphere.radius) continue;  // behind the light: never between o and the disk
    if (plane <= sphere.radius) throw std::domain_error("an occluder crosses the light's plane");
    s.occluders.push_back(
        {w.dot(light.axis_x), w.dot(light.axis_y), -s.h * w.dot(s.n), k, sphere.radius});
  }

  // Angular range: the disk's tangents from the foot, or the full turn when the foot is inside.
  const double pr = std::hypot(s.px, s.py);
  double lo = 0.0, hi = math::kTwoPi;
  std::vector<double> cuts;
  if (pr > light.radius) {
    const double centre = std::atan2(-s.py, -s.px), half = std::asin(light.radius / pr);
    lo = centre - half;
    hi = centre + half;
  }
  cuts.push_back(lo);
  std::vector<double> angles = breakpoints(s, lo);
  if (pr <= light.radius && pr > 0.0) {
    // Foot inside: the far end of each ray is smooth but steep where the ray runs along the
    // nearest rim (perpendicular to the foot's offset) when the foot is close to it.
    const double t = std::atan2(s.py, s.px);
    angles.push_back(wrap_into(t + 0.5 * math::kPi, lo));
    angles.push_back(wrap_into(t - 0.5 * math::kPi, lo));
  }
  for (double t : angles)
    if (t > lo && t < hi) cuts.push_back(t);
  cuts.push_back(hi);
  std::sort(cuts.begin(), cuts.end());

  Integrator in{&s, {}, 0.0, 0};
  // A first pass gives the scale for the absolute tolerance.
  struct Piece {
    double ta, tb, lo, hi;
    Panel first;
  };
  std::vector<Piece> pieces;
  double coarse = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (!(cuts[i + 1] > cuts[i])) continue;
    for (int p = 0; p < kInitialPanels; ++p) {
      const double a = double(p) / kInitialPanels, b = double(p + 1) / kInitialPanels;
      const Panel v = in.panel(cuts[i], cuts[i + 1], a, b);
      pieces.push_back({cuts[i], cuts[i + 1], a, b, v});
      coarse += v.value;
    }
  }
  const double tol =
      rel_tol * std::fabs(coarse) / static_cast<double>(std::max<std::size_t>(pieces.size(), 1));
  double value = 0.0, rounding = 0.0;
  for (const Piece& p : pieces) {
    const Panel v = in.adapt(p.ta, p.tb, p.lo, p.hi, p.first, tol, 0);
    value += v.value;
    rounding += v.rounding;
  }
  // Summing the panels adds at most a few ulps of the (nonnegative) total.
  rounding += 4.0 * kEps * static_cast<double>(pieces.size()) * std::fabs(value);
  return {value, in.error + rounding};
}

ReferenceValue irradiance_rim(const DiskLight& light, const ShadingPoint& sp, double rel_tol) {
  const Vec3 w = light.center - sp.position;
  const Vec3& n_o = sp.normal;
  const double R = light.radius;
  // Lowest rim point over the horizon: min_t (w + R e(t)) . n_o = w . n_o - R |P n_o|.
  const double ux = light.axis_x.dot(n_o), uy = light.axis_y.dot(n_o);
  if (!(w.dot(n_o) - R * std::hypot(ux, uy) > 0.0))
    throw std::domain_error("irradiance_rim: part of the disk is on or below the horizon");
  if (!(R > 0.0) || light.radiance == 0.0) return {0.0, 0.0};
  // n_o . (x cross x') / |x|^2 at rim angle t, x' = dx/dt.
  auto term = [&](double t) {
    const double c = std::cos(t), sn = std::sin(t);
    const Vec3 x = w + R * (c * light.axis_x + sn * light.axis_y);
    const Vec3 xp = R * (c * light.axis_y - sn * light.axis_x);
    return n_o.dot(x.cross(xp)) / x.squaredNorm();
  };
  // Neumaier-compensated sums of the terms and of their magnitudes.
  double sum = 0.0, comp = 0.0, abs_sum = 0.0;
  auto add = [&](double v) {
    const double t = sum + v;
    comp += std::fabs(sum) >= std::fabs(v) ? (sum - t) + v : (v - t) + sum;
    sum = t;
    abs_sum += std::fabs(v);
  };
  constexpr int kFirst = 16, kMaxNodes = 1 << 20;
  for (int j = 0; j < kFirst; ++j)
    add(term(math::kTwoPi * j / kFirst));
  double prev = math::kTwoPi / kFirst * (sum + comp), diff = 0.0, rounding = 0.0;
  int m = kFirst;
  for (;;) {
    for (int j = 0; j < m; ++j)
      add(term(math::kTwoPi * (j + 0.5) / m));
    m *= 2;
    const double cur = math::kTwoPi / m * (sum + comp);
    diff = std::fabs(cur - prev);
    prev = cur;
    // Each term is good to a few ulps of its magnitude; the compensated sum adds about one.
    rounding = 8.0 * kEps * math::kTwoPi / m * abs_sum;
    // Two levels that agree to within rounding cannot be told apart any further.
    if (m >= 64 && (diff <= rel_tol * std::fabs(cur) || diff <= 2.0 * rounding)) break;
    if (m >= kMaxNodes) break;
  }
  const double scale = 0.5 * std::fabs(light.radiance);
  return {scale * std::fabs(prev), scale * (diff + rounding)};
}

}  // namespace disklab::study
