// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/gravity_compliance.hpp"

#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg::simulation {

kinematics::JointVector gravity_torques_nm(const kinematics::SerialChain& chain,
                                           const kinematics::JointRef& q_rad,
                                           const std::vector<double>& link_mass_kg,
                                           double payload_kg) {
  const int n = chain.n_joints();
  VRREG_THROW_UNLESS(
      link_mass_kg.size() == static_cast<std::size_t>(n),
      "gravity torques: " << link_mass_kg.size() << " link masses for " << n << " joints");
  const std::vector<Eigen::Isometry3d> frames = kinematics::link_frames(chain, q_rad);
  const Eigen::Vector3d tcp = (frames.back() * chain.T_flange_tcp()).translation();
  const Eigen::Vector3d g(0.0, 0.0, -kGravity_m_per_s2);
  // Point masses: link i (1-based) between frame origins i-1 and i, payload at the TCP.
  std::vector<Eigen::Vector3d> position;
  std::vector<double> mass;
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    position.push_back(0.5 * (frames[k].translation() + frames[k + 1].translation()));
    mass.push_back(link_mass_kg[k]);
  }
  position.push_back(tcp);
  mass.push_back(payload_kg);
  kinematics::JointVector tau = kinematics::JointVector::Zero(n);
  for (int j = 0; j < n; ++j) {
    // Joint j+1 turns link j+1 and everything after it about z of frame j.
    const Eigen::Isometry3d& f = frames[static_cast<std::size_t>(j)];
    const Eigen::Vector3d axis = f.linear().col(2);
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    for (std::size_t m = static_cast<std::size_t>(j); m < position.size(); ++m) {
      moment += (position[m] - f.translation()).cross(mass[m] * g);
    }
    tau(j) = axis.dot(moment);
  }
  return tau;
}

kinematics::JointVector gravity_deflection_rad(const kinematics::SerialChain& chain,
                                               const kinematics::JointRef& q_rad,
                                               const std::vector<double>& link_mass_kg,
                                               double payload_kg,
                                               const std::vector<double>& stiffness_nm_per_rad) {
  const int n = chain.n_joints();
  VRREG_THROW_UNLESS(stiffness_nm_per_rad.size() == static_cast<std::size_t>(n),
                     "gravity deflection: " << stiffness_nm_per_rad.size() << " stiffnesses for "
                                            << n << " joints");
  kinematics::JointVector dq = gravity_torques_nm(chain, q_rad, link_mass_kg, payload_kg);
  for (int i = 0; i < n; ++i) {
    const double k = stiffness_nm_per_rad[static_cast<std::size_t>(i)];
    VRREG_THROW_UNLESS(
        k > 0.0, "gravity deflection: joint " << i + 1 << " stiffness " << k << " is not positive");
    dq(i) /= k;
  }
  return dq;
}

}  // namespace vrreg::simulation
