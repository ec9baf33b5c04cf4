// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/robot_error_model.hpp"

#include <cmath>
#include <numbers>

#include "vrreg/core/check.hpp"

namespace vrreg::simulation {
namespace {

void check_value(double value, const char* name) {
  VRREG_THROW_UNLESS(
      std::isfinite(value) && value >= 0.0,
      "robot error model: " << name << " must be finite and >= 0 (got " << value << ")");
}

void check_list(const std::vector<double>& values, int n_joints, const char* name, bool positive) {
  VRREG_THROW_UNLESS(values.size() == static_cast<std::size_t>(n_joints),
                     "robot error model: " << name << " needs one value per joint (" << n_joints
                                           << "), got " << values.size());
  for (double v : values) {
    VRREG_THROW_UNLESS(std::isfinite(v) && (positive ? v > 0.0 : v >= 0.0),
                       "robot error model: " << name << " must be finite and "
                                             << (positive ? "> 0" : ">= 0") << " (got " << v
                                             << ")");
  }
}

}  // namespace

void RobotErrorModel::validate(int n_joints) const {
  VRREG_THROW_UNLESS(n_joints > 0, "robot error model: no joints");
  check_value(joint_offset_sigma_rad, "joint offset sigma");
  check_value(link_length_sigma_m, "link length sigma");
  check_value(link_offset_sigma_m, "link offset sigma");
  check_value(twist_sigma_rad, "twist sigma");
  check_value(repeatability_sigma_m, "repeatability sigma");
  check_value(payload_kg, "payload");
  VRREG_THROW_UNLESS(
      std::isfinite(link_growth) && link_growth > -0.01,
      "robot error model: link growth must be finite and > -0.01, got " << link_growth);
  if (!transmission_amplitude_rad.empty() || !transmission_period_rad.empty()) {
    check_list(transmission_amplitude_rad, n_joints, "transmission amplitude", false);
    check_list(transmission_period_rad, n_joints, "transmission period", true);
  }
  if (!lost_motion_rad.empty()) check_list(lost_motion_rad, n_joints, "lost motion", false);
  VRREG_THROW_UNLESS(
      std::isfinite(lost_motion_take_up) && lost_motion_take_up >= 0.0 &&
          lost_motion_take_up <= 1.0,
      "robot error model: lost motion take-up must be in [0, 1], got " << lost_motion_take_up);
  if (compliance) {
    check_list(link_mass_kg, n_joints, "link mass", false);
    check_list(joint_stiffness_nm_per_rad, n_joints, "joint stiffness", true);
  }
}

bool RobotErrorModel::is_perfect() const {
  bool no_transmission = true;
  for (double a : transmission_amplitude_rad) no_transmission = no_transmission && a == 0.0;
  bool no_lost_motion = true;
  for (double b : lost_motion_rad) no_lost_motion = no_lost_motion && b == 0.0;
  no_lost_motion = no_lost_motion || lost_motion_take_up == 0.0;
  return link_growth == 0.0 && joint_offset_sigma_rad == 0.0 && link_length_sigma_m == 0.0 &&
         link_offset_sigma_m == 0.0 && twist_sigma_rad == 0.0 && repeatability_sigma_m == 0.0 &&
         no_transmission && no_lost_motion && !compliance;
}

RobotErrors draw_robot_errors(const RobotErrorModel& model, int n_joints, Random& rng) {
  model.validate(n_joints);
  RobotErrors errors;
  const auto n = static_cast<std::size_t>(n_joints);
  errors.dh_delta.resize(n);
  // A fixed draw order (per joint: theta, a, d, alpha) keeps a seed's robot stable.
  for (kinematics::DhRow& delta : errors.dh_delta) {
    delta.theta_offset_rad = rng.normal(model.joint_offset_sigma_rad);
    delta.a_m = rng.normal(model.link_length_sigma_m);
    delta.d_m = rng.normal(model.link_offset_sigma_m);
    delta.alpha_rad = rng.normal(model.twist_sigma_rad);
  }
  if (!model.transmission_amplitude_rad.empty()) {
    errors.transmission_phase_rad.resize(n);
    for (double& phase : errors.transmission_phase_rad) {
      phase = rng.uniform(0.0, 2.0 * std::numbers::pi);
    }
  }
  return errors;
}

}  // namespace vrreg::simulation
