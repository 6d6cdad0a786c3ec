#pragma once
// Shared fixtures of the spherical-ellipse map suites (map_*_test.cpp): the configurations, from
// on-axis to grazing to 1e8 radii away, and a type-erased view of every map so one property can
// run over all of them.
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
  std::string describe() const {
    std::ostringstream s;
    s.precision(17);
    s << name << " {c=(" << center.transpose() << ") n=(" << normal.transpose() << ") r=" << radius
      << " o=(" << point.transpose() << ")}";
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
    auto p = std::make_shared<ellipse::RadialMap>(
        ellipse::RadialMap::make(c.center, c.normal, c.radius, c.point));
    m.omega = m.measure = p->g.omega;
    m.sample = [p](Point2 u, int* it) { return p->sample(u, it); };
    m.invert_local = [p](const Vec3& l) { return p->invert_local(l); };
  } else if (name == "parallel") {
    auto p = std::make_shared<ellipse::ParallelMap>(
        ellipse::ParallelMap::make(c.center, c.normal, c.radius, c.point));
    m.omega = m.measure = p->g.omega;
    m.sample = [p](Point2 u, int* it) { return p->sample(u, it); };
    m.invert_local = [p](const Vec3& l) { return p->invert_local(l); };
  } else if (name == "ld-radial") {
    auto p = std::make_shared<ellipse::LdRadialMap>(
        ellipse::LdRadialMap::make(c.center, c.normal, c.radius, c.point));
    m.omega = m.measure = p->radial.g.omega;
    m.sample = [p](Point2 u, int* it) { return p->sample(u, it); };
    m.invert_local = [p](const Vec3& l) { return p->invert_local(l); };
  } else if (name == "radial4") {
    auto p = std::make_shared<ellipse::Radial4Map>(
        ellipse::Radial4Map::make(c.center, c.normal, c.radius, c.point));
    m.omega = p->radial.g.omega;
    m.measure = 0.25 * m.omega;
    m.sample = [p](Point2 u, int* it) { return p->sample_quadrant(u, it); };
    m.invert_local = [p](const Vec3& l) { return p->invert_local(l); };
  } else if (name == "radial-fast") {
    auto p = std::make_shared<ellipse::RadialFastMap>(
        ellipse::RadialFastMap::make(c.center, c.normal, c.radius, c.point));
    m.omega = m.measure = p->radial.g.omega;
    m.sample = [p](Point2 u, int* it) { return p->sample(u, it); };
    m.invert_local = [p](const Vec3& l) { return p->invert_local(l); };
  }
  return m;
}

}  // namespace disklab::test
