// The workbook's vocabulary types: fixed-size Eigen vectors and matrices behind short names.
//
// Every header in rigid/ includes this one and nothing else from Eigen, so that `cross()`
// and the other geometry functions are always available (<Eigen/Dense> brings Geometry).
#pragma once

#include <Eigen/Dense>

namespace rigid {

using Vec3 = Eigen::Vector3d;  // a 3-vector: lab or body coordinates, as each function says
using Mat3 = Eigen::Matrix3d;  // a 3x3 matrix: rotation R, inertia J, skew hat(w), ...

}  // namespace rigid
