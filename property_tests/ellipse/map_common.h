#pragma once
// Shared fixtures of the spherical-ellipse map suites (map_*_test.cpp): the configurations, from
// on-axis to grazing to 1e8 radii away, and a type-erased view of every map so one property can
// run over all of them.
#include <algorithm>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "disklab/ellipse/area.h"
#include "disklab/ellipse/gamito.h"
#include "disklab/ellipse/ld_radial.h"
#include "disklab/ellipse/parallel.h"
#include "disklab/ellipse/radial.h"
#include "disklab/ellipse/radial4.h"
#include "disklab/ellipse/radial_fast.h"
#include "disklab/ellipse/tabulated.h"

namespace disklab::test {

struct DiskConfig {
  std::string name;
  Vec3 center, normal;
  double radius;
  Vec3 point;
  bool two_sided = false;
  ellipse::Disk disk() const { return {center, normal, radius, two_sided}; }
  std::string describe() const {
    std::ostringstream s;
    s.precision(17);
    s << name << " {c=(" << center.transpose() << ") n=(" << normal.transpose() << ") r=" << radius
      << " o=(" << point.transpose() << ")" << (two_sided ? " two-sided" : "") << "}";
    return s.str();
  }
};

inline Vec3 tilted_normal() {
  return Vec3(0.3, -0.2, -1.0).normalized();
}

// From the disk's face to grazing and to 1e8 radii away. The disk faces -z (towards o = 0) unless
// tilted. "grazing": the point is 0.02 radii above the disk's plane, 3 radii off its axis, so the
// ellipse is thin (b/a ~ 1e-2) and near the horizon; "under-rim": the point lies under the disk
// near its rim, so the ellipse covers most of the hemisphere.
inline std::vector<DiskConfig> map_configs() {
  return {
      {"on-axis-near", Vec3(0, 0, 0.05), Vec3(0, 0, -1), 1.0, Vec3::Zero()},
      {"on-axis-unit", Vec3(0, 0, 1), Vec3(0, 0, -1), 1.0, Vec3::Zero()},
      {"under-rim", Vec3(0.9, 0.1, 0.3), Vec3(0, 0, -1), 1.0, Vec3::Zero()},
      {"tilted-mid", Vec3(1.0, 0.5, 2.0), tilted_normal(), 1.0, Vec3::Zero()},
      {"grazing", Vec3(3.0, 0.0, 0.02), Vec3(0, 0, -1), 1.0, Vec3::Zero()},
      {"far-1e4", Vec3(3e3, 2e3, 1e4), tilted_normal(), 1.0, Vec3::Zero()},
      {"far-1e8", Vec3(3e7, 2e7, 1e8), tilted_normal(), 1.0, Vec3::Zero()},
  };
}

// Boundary of the stratum [x0,x1] x [y0,y1], counter-clockwise in the square, as a closed curve
// t in [0,1) -> square point (four edges of equal parameter length). Along each edge the
// parameter is clustered towards the corners by the quintic smoothstep (tau ~ 10 s^3 at the
// ends): the parallel map's rim behaves like eps1^(1/3) (h_p ~ sqrt(beta - phi_p) and
// Omega_p ~ (beta - phi_p)^(3/2)), a singular parametrization that would stall the chord
// quadrature; composed with s^3 it becomes smooth. For smooth maps the clustering is harmless.
inline Point2 stratum_boundary(double x0, double x1, double y0, double y1, double t) {
  const double s4 = 4.0 * t;
  const int edge = std::min(3, static_cast<int>(s4));
  const double s = s4 - edge;
  const double tau = s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
  if (edge == 0) return {x0 + tau * (x1 - x0), y0};
  if (edge == 1) return {x1, y0 + tau * (y1 - y0)};
  if (edge == 2) return {x1 - tau * (x1 - x0), y1};
  return {x0, y1 - tau * (y1 - y0)};
}

// A map [0,1]^2 -> spherical ellipse with its inverse, for properties over all maps.
struct AnyMap {
  std::string name;
  double measure = 0.0;  // solid angle of the map's image (Omega, or Omega/4 for radial4)
  double omega = 0.0;
  std::function<ellipse::EllipseSample(Point2, int*)> sample;
  std::function<Point2(const Vec3&)> invert_local;  // local-frame direction -> u
};

inline std::vector<std::string> bijective_map_names() {
  return {"radial", "parallel", "ld-radial", "radial4", "radial-fast"};
}

inline AnyMap make_map(const std::string& name, const DiskConfig& c) {
  AnyMap m;
  m.name = name;
  if (name == "radial") {
    auto p = std::make_shared<ellipse::RadialMap>(ellipse::RadialMap::make(c.disk(), c.point));
    m.omega = m.measure = p->g.omega;
    m.sample = [p](Point2 u, int* it) { return p->sample(u, it); };
    m.invert_local = [p](const Vec3& l) { return p->invert_local(l); };
  } else if (name == "parallel") {
    auto p = std::make_shared<ellipse::ParallelMap>(ellipse::ParallelMap::make(c.disk(), c.point));
    m.omega = m.measure = p->g.omega;
    m.sample = [p](Point2 u, int* it) { return p->sample(u, it); };
    m.invert_local = [p](const Vec3& l) { return p->invert_local(l); };
  } else if (name == "ld-radial") {
    auto p = std::make_shared<ellipse::LdRadialMap>(ellipse::LdRadialMap::make(c.disk(), c.point));
    m.omega = m.measure = p->radial.g.omega;
    m.sample = [p](Point2 u, int* it) { return p->sample(u, it); };
    m.invert_local = [p](const Vec3& l) { return p->invert_local(l); };
  } else if (name == "radial4") {
    auto p = std::make_shared<ellipse::Radial4Map>(ellipse::Radial4Map::make(c.disk(), c.point));
    m.omega = p->radial.g.omega;
    m.measure = 0.25 * m.omega;
    m.sample = [p](Point2 u, int* it) { return p->sample_quadrant(u, it); };
    m.invert_local = [p](const Vec3& l) {
      int k;
      return p->invert_copy_local(l, k);
    };
  } else if (name == "radial-fast") {
    auto p =
        std::make_shared<ellipse::RadialFastMap>(ellipse::RadialFastMap::make(c.disk(), c.point));
    m.omega = m.measure = p->radial.g.omega;
    m.sample = [p](Point2 u, int* it) { return p->sample(u, it); };
    m.invert_local = [p](const Vec3& l) { return p->invert_local(l); };
  }
  return m;
}

}  // namespace disklab::test
