// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg::kinematics {

Eigen::Isometry3d flange_in_dh0(const SerialChain& chain, const JointRef& q_rad) {
  chain.check_joints(q_rad, "forward kinematics");
  Eigen::Isometry3d t = dh_transform(chain.row(0), q_rad(0));
  for (int i = 1; i < chain.n_joints(); ++i) t = t * dh_transform(chain.row(i), q_rad(i));
  return t;
}

Eigen::Isometry3d forward_kinematics(const SerialChain& chain, const JointRef& q_rad) {
  const Eigen::Isometry3d T_dh0_flange = flange_in_dh0(chain, q_rad);
  if (chain.tcp_is_flange_in_dh0()) return T_dh0_flange;
  return chain.T_base_dh0() * T_dh0_flange * chain.T_flange_tcp();
}

std::vector<Eigen::Isometry3d> link_frames(const SerialChain& chain, const JointRef& q_rad) {
  chain.check_joints(q_rad, "link frames");
  std::vector<Eigen::Isometry3d> frames;
  frames.reserve(static_cast<std::size_t>(chain.n_joints()) + 1);
  frames.push_back(chain.T_base_dh0());
  for (int i = 0; i < chain.n_joints(); ++i) {
    frames.push_back(frames.back() * dh_transform(chain.row(i), q_rad(i)));
  }
  return frames;
}

Jacobian jacobian(const SerialChain& chain, const JointRef& q_rad) {
  const std::vector<Eigen::Isometry3d> frames = link_frames(chain, q_rad);
  const Eigen::Vector3d p_tcp = (frames.back() * chain.T_flange_tcp()).translation();
  Jacobian j(6, chain.n_joints());
  for (int i = 0; i < chain.n_joints(); ++i) {
    // Joint i+1 turns about (or slides along) z of frame i, through the origin of frame i.
    const Eigen::Isometry3d& f = frames[static_cast<std::size_t>(i)];
    const Eigen::Vector3d z = f.linear().col(2);
    if (chain.row(i).prismatic()) {
      j.block<3, 1>(0, i) = z;
      j.block<3, 1>(3, i).setZero();
    } else {
      j.block<3, 1>(0, i) = z.cross(p_tcp - f.translation());
      j.block<3, 1>(3, i) = z;
    }
  }
  return j;
}

}  // namespace vrreg::kinematics
