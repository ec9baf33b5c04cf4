// SPDX-License-Identifier: Apache-2.0
#pragma once
// A urdfdom pose as an Eigen transform, for the URDF tests' references composed on urdfdom's tree.
#include <urdf_model/pose.h>

#include <Eigen/Geometry>

namespace vrreg::testing {

inline Eigen::Isometry3d to_eigen(const urdf::Pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  double x = 0, y = 0, z = 0, w = 1;
  p.rotation.getQuaternion(x, y, z, w);
  t.linear() = Eigen::Quaterniond(w, x, y, z).toRotationMatrix();
  t.translation() << p.position.x, p.position.y, p.position.z;
  return t;
}

}  // namespace vrreg::testing
