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

kinematics::JointVector SimulatedRobot::actual_joints(const kinematics::JointRef& q_cmd_rad) const {
  nominal_.check_joints(q_cmd_rad, "simulated robot");
  kinematics::JointVector q = q_cmd_rad;
  for (std::size_t i = 0; i < model_.transmission_amplitude_rad.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    const double omega = 2.0 * std::numbers::pi / model_.transmission_period_rad[i];
    q(k) += model_.transmission_amplitude_rad[i] *
            std::sin(omega * q_cmd_rad(k) + errors_.transmission_phase_rad[i]);
  }
  if (model_.compliance) {
    q += gravity_deflection_rad(nominal_, q_cmd_rad, model_.link_mass_kg, model_.payload_kg,
                                model_.joint_stiffness_nm_per_rad);
  }
  return q;
}

Eigen::Vector3d SimulatedRobot::actual_tcp_m(const kinematics::JointRef& q_cmd_rad) const {
  return kinematics::forward_kinematics(actual_, actual_joints(q_cmd_rad)).translation();
}

Eigen::Matrix3d SimulatedRobot::actual_rotation(const kinematics::JointRef& q_cmd_rad) const {
  return kinematics::forward_kinematics(actual_, actual_joints(q_cmd_rad)).linear();
}

Eigen::Vector3d SimulatedRobot::visit_tcp_m(const kinematics::JointRef& q_cmd_rad,
                                            Random& rng) const {
  return actual_tcp_m(q_cmd_rad) + rng.normal3(model_.repeatability_sigma_m);
}

}  // namespace vrreg::simulation
