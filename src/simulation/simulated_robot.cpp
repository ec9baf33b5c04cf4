// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/simulated_robot.hpp"

#include <cmath>
#include <numbers>
#include <utility>

#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/simulation/gravity_compliance.hpp"

namespace vrreg::simulation {
namespace {

kinematics::SerialChain perturbed(const kinematics::SerialChain& nominal, const RobotErrors& errors,
                                  double growth) {
  VRREG_THROW_UNLESS(!nominal.coupled(), "simulated robot: robot '"
                                             << nominal.name()
                                             << "' has joints that follow others (mimic "
                                                "joints), which the simulation does not model");
  VRREG_THROW_UNLESS(errors.dh_delta.size() == static_cast<std::size_t>(nominal.n_joints()),
                     "simulated robot: " << errors.dh_delta.size() << " DH errors for "
                                         << nominal.n_joints() << " joints");
  std::vector<kinematics::DhRow> rows = nominal.rows();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const kinematics::DhRow& d = errors.dh_delta[i];
    rows[i].a_m += d.a_m;
    rows[i].alpha_rad += d.alpha_rad;
    rows[i].d_m += d.d_m;
    rows[i].theta_offset_rad += d.theta_offset_rad;
    rows[i].a_m *= 1.0 + growth;  // thermal growth of the link
    rows[i].d_m *= 1.0 + growth;
  }
  return kinematics::SerialChain(nominal.name() + "-actual", std::move(rows), nominal.limits(),
                                 nominal.T_base_dh0(), nominal.T_flange_tcp());
}

}  // namespace

SimulatedRobot::SimulatedRobot(kinematics::SerialChain nominal, RobotErrorModel model,
                               RobotErrors errors)
    : nominal_(std::move(nominal)),
      actual_(perturbed(nominal_, errors, model.link_growth)),
      model_(std::move(model)),
      errors_(std::move(errors)) {
  model_.validate(nominal_.n_joints());
  VRREG_THROW_UNLESS(
      errors_.transmission_phase_rad.size() == model_.transmission_amplitude_rad.size(),
      "simulated robot: " << errors_.transmission_phase_rad.size() << " transmission phases for "
                          << model_.transmission_amplitude_rad.size() << " amplitudes");
}

kinematics::JointVector SimulatedRobot::actual_joints(
    const kinematics::JointRef& q_cmd_rad, const kinematics::JointRef& approach_sign) const {
  nominal_.check_joints(q_cmd_rad, "simulated robot");
  VRREG_THROW_UNLESS(approach_sign.size() == 0 || approach_sign.size() == q_cmd_rad.size(),
                     "simulated robot: " << approach_sign.size() << " approach signs for "
                                         << q_cmd_rad.size() << " joints");
  kinematics::JointVector q = q_cmd_rad;
  for (std::size_t i = 0; i < model_.transmission_amplitude_rad.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    const double omega = 2.0 * std::numbers::pi / model_.transmission_period_rad[i];
    q(k) += model_.transmission_amplitude_rad[i] *
            std::sin(omega * q_cmd_rad(k) + errors_.transmission_phase_rad[i]);
  }
  if (approach_sign.size() > 0) {
    for (std::size_t i = 0; i < model_.lost_motion_rad.size(); ++i) {
      const auto k = static_cast<Eigen::Index>(i);
      q(k) -= approach_sign(k) * model_.lost_motion_take_up * 0.5 * model_.lost_motion_rad[i];
    }
  }
  if (model_.compliance) {
    q += gravity_deflection_rad(nominal_, q_cmd_rad, model_.link_mass_kg, model_.payload_kg,
                                model_.joint_stiffness_nm_per_rad);
  }
  return q;
}

Eigen::Vector3d SimulatedRobot::actual_tcp_m(const kinematics::JointRef& q_cmd_rad,
                                             const kinematics::JointRef& approach_sign) const {
  return kinematics::forward_kinematics(actual_, actual_joints(q_cmd_rad, approach_sign))
      .translation();
}

Eigen::Matrix3d SimulatedRobot::actual_rotation(const kinematics::JointRef& q_cmd_rad,
                                                const kinematics::JointRef& approach_sign) const {
  return kinematics::forward_kinematics(actual_, actual_joints(q_cmd_rad, approach_sign)).linear();
}

Eigen::Vector3d SimulatedRobot::visit_tcp_m(const kinematics::JointRef& q_cmd_rad, Random& rng,
                                            const kinematics::JointRef& approach_sign) const {
  return actual_tcp_m(q_cmd_rad, approach_sign) + rng.normal3(model_.repeatability_sigma_m);
}

JointApproach::JointApproach(const kinematics::JointRef& q_start_rad)
    : q_rad_(q_start_rad), sign_(kinematics::JointVector::Zero(q_start_rad.size())) {}

const kinematics::JointVector& JointApproach::move_to(const kinematics::JointRef& q_rad) {
  update_approach_sign(q_rad_, q_rad, sign_);
  q_rad_ = q_rad;
  return sign_;
}

}  // namespace vrreg::simulation
