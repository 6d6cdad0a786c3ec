#pragma once
// Small value types shared by every folder of the library.
#include <Eigen/Core>

namespace disklab {

// A point of the unit square or of the plane (a disk sample); plain aggregate.
struct Point2 {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Point2&, const Point2&) = default;
};

using Vec3 = Eigen::Vector3d;

}  // namespace disklab
