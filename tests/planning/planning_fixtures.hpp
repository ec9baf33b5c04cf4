// SPDX-License-Identifier: Apache-2.0
#pragma once
// The robot the planning tests plan for.
#include <Eigen/Geometry>

#include "vrreg/kinematics/robots.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::testing {

/// A UR5 carrying a tracked sphere 60 mm out along the flange's z axis.
inline kinematics::SerialChain ur5_with_sphere() {
  return kinematics::ur5().with_tool(Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.06)));
}

}  // namespace vrreg::testing
