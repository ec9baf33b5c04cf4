// SPDX-License-Identifier: Apache-2.0
// On a coupled chain the joint variables are first mapped to the rows' values; the Jacobian's
// column of a variable is then the sum of its rows' columns times their multipliers (chain rule).
#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg::kinematics {
namespace {

// T_dh0_flange from every row's value `q_row`.
Eigen::Isometry3d compose_rows(const SerialChain& chain, const JointRef& q_row) {
  Eigen::Isometry3d t = dh_transform(chain.row(0), q_row(0));
  for (int i = 1; i < chain.n_rows(); ++i) t = t * dh_transform(chain.row(i), q_row(i));
  return t;
}

std::vector<Eigen::Isometry3d> frames_of_rows(const SerialChain& chain, const JointRef& q_row) {
  std::vector<Eigen::Isometry3d> frames;
  frames.reserve(static_cast<std::size_t>(chain.n_rows()) + 1);
  frames.push_back(chain.T_base_dh0());
  for (int i = 0; i < chain.n_rows(); ++i) {
    frames.push_back(frames.back() * dh_transform(chain.row(i), q_row(i)));
  }
  return frames;
}

}  // namespace

Eigen::Isometry3d flange_in_dh0(const SerialChain& chain, const JointRef& q_rad) {
  chain.check_joints(q_rad, "forward kinematics");
  if (chain.coupled()) return compose_rows(chain, chain.row_values(q_rad));
  return compose_rows(chain, q_rad);
}

Eigen::Isometry3d forward_kinematics(const SerialChain& chain, const JointRef& q_rad) {
  const Eigen::Isometry3d T_dh0_flange = flange_in_dh0(chain, q_rad);
  if (chain.tcp_is_flange_in_dh0()) return T_dh0_flange;
  return chain.T_base_dh0() * T_dh0_flange * chain.T_flange_tcp();
}

std::vector<Eigen::Isometry3d> link_frames(const SerialChain& chain, const JointRef& q_rad) {
  chain.check_joints(q_rad, "link frames");
  if (chain.coupled()) return frames_of_rows(chain, chain.row_values(q_rad));
  return frames_of_rows(chain, q_rad);
}

Jacobian jacobian(const SerialChain& chain, const JointRef& q_rad) {
  const std::vector<Eigen::Isometry3d> frames = link_frames(chain, q_rad);
  const Eigen::Vector3d p_tcp = (frames.back() * chain.T_flange_tcp()).translation();
  // One column per row: row i turns about (or slides along) z of frame i, through its origin.
  Jacobian rows(6, chain.n_rows());
  for (int i = 0; i < chain.n_rows(); ++i) {
    const Eigen::Isometry3d& f = frames[static_cast<std::size_t>(i)];
    const Eigen::Vector3d z = f.linear().col(2);
    if (chain.row(i).prismatic()) {
      rows.block<3, 1>(0, i) = z;
      rows.block<3, 1>(3, i).setZero();
    } else {
      rows.block<3, 1>(0, i) = z.cross(p_tcp - f.translation());
      rows.block<3, 1>(3, i) = z;
    }
  }
  if (!chain.coupled()) return rows;
  Jacobian j = Jacobian::Zero(6, chain.n_joints());
  for (int i = 0; i < chain.n_rows(); ++i) {
    const JointCoupling& c = chain.couplings().rows[static_cast<std::size_t>(i)];
    j.col(c.variable) += c.multiplier * rows.col(i);
  }
  return j;
}

}  // namespace vrreg::kinematics
