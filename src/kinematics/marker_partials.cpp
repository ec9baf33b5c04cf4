// SPDX-License-Identifier: Apache-2.0
#include "vrreg/kinematics/marker_partials.hpp"

#include <vector>

#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg::kinematics {

MarkerPartials marker_partials(const SerialChain& chain, const JointRef& q_rad,
                               const Eigen::Vector3d& p_flange_marker_m) {
  const std::vector<Eigen::Isometry3d> frames = link_frames(chain, q_rad);
  const int n = chain.n_rows();
  MarkerPartials out;
  out.R_base_flange = frames.back().linear();
  out.position_m = frames.back() * p_flange_marker_m;
  out.d_joint = Eigen::Matrix3Xd::Zero(3, chain.n_joints());
  out.d_theta.resize(3, n);
  out.d_a.resize(3, n);
  out.d_d.resize(3, n);
  out.d_alpha.resize(3, n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Isometry3d& before = frames[static_cast<std::size_t>(i)];     // frame i-1
    const Eigen::Isometry3d& after = frames[static_cast<std::size_t>(i) + 1];  // frame i
    const Eigen::Vector3d z = before.linear().col(2);
    const Eigen::Vector3d x = after.linear().col(0);  // Rx(alpha) leaves x_i where Tx(a) put it
    out.d_theta.col(i) = z.cross(out.position_m - before.translation());
    out.d_d.col(i) = z;
    // A variable moves each row that follows it by the row's multiplier (1 on its own row).
    const JointCoupling c = chain.coupled() ? chain.couplings().rows[static_cast<std::size_t>(i)]
                                            : JointCoupling{i, 1.0, 0.0};
    out.d_joint.col(c.variable) +=
        c.multiplier * (chain.row(i).prismatic() ? out.d_d.col(i) : out.d_theta.col(i));
    out.d_a.col(i) = x;
    out.d_alpha.col(i) = x.cross(out.position_m - after.translation());
  }
  return out;
}

}  // namespace vrreg::kinematics
