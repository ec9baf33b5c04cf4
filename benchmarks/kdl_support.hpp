// SPDX-License-Identifier: Apache-2.0
#pragma once
// Orocos KDL peers of the kinematics benchmarks: a vrreg chain's DH table and a pose as KDL types.
#include <Eigen/Geometry>
#include <kdl/chain.hpp>
#include <kdl/frames.hpp>

#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::bench {

/// The DH part of `chain` (no base or tool transform) as a KDL chain, joint for joint.
inline KDL::Chain kdl_chain(const kinematics::SerialChain& chain) {
  KDL::Chain kdl;
  for (const auto& r : chain.rows()) {
    kdl.addSegment(KDL::Segment(KDL::Joint(r.prismatic() ? KDL::Joint::TransZ : KDL::Joint::RotZ),
                                KDL::Frame::DH(r.a_m, r.alpha_rad, r.d_m, r.theta_offset_rad)));
  }
  return kdl;
}

/// `t` as a KDL frame (m).
inline KDL::Frame kdl_frame(const Eigen::Isometry3d& t) {
  const Eigen::Matrix3d& r = t.linear();
  return KDL::Frame(KDL::Rotation(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0),
                                  r(2, 1), r(2, 2)),
                    KDL::Vector(t.translation().x(), t.translation().y(), t.translation().z()));
}

}  // namespace vrreg::bench
