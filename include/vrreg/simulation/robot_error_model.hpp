// SPDX-License-Identifier: Apache-2.0
#pragma once
// How a simulated robot deviates from its nominal model (design.md 5): kinematic (DH) errors, a
// periodic joint transmission error, per-visit repeatability and optional joint compliance under
// gravity. RobotErrorModel holds spreads and per-joint constants; a seed draws one concrete robot
// (RobotErrors) from it, so every seed is another robot of the same make. Lost motion depends on
// the path: it is applied where the robot moves (simulated_robot.hpp).
#include <vector>

#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/dh.hpp"

namespace vrreg::simulation {

/// Spreads and per-joint constants of a robot's errors. SI: m, rad, kg, N m / rad.
struct RobotErrorModel {
  /// Joint zero offset error (DH theta offset), Gaussian per joint, drawn once per robot.
  double joint_offset_sigma_rad = 0.0;
  /// Link length error (DH a), Gaussian per joint, drawn once per robot.
  double link_length_sigma_m = 0.0;
  /// Link offset error (DH d), Gaussian per joint, drawn once per robot.
  double link_offset_sigma_m = 0.0;
  /// Link twist error (DH alpha), Gaussian per joint, drawn once per robot.
  double twist_sigma_rad = 0.0;
  /// Transmission error of joint i: A_i sin(2 pi q_i / P_i + phi_i) added to the commanded
  /// angle q_i; phi_i uniform in [0, 2 pi) per robot. Amplitudes A_i [rad], one per joint, or
  /// empty for none.
  std::vector<double> transmission_amplitude_rad{};
  /// Periods P_i [rad] > 0 of the transmission error, one per joint (empty when no amplitudes).
  std::vector<double> transmission_period_rad{};
  /// Lost motion b_i [rad] of joint i (gear backlash and transmission compliance), one per joint,
  /// or empty for none. The joint stops lost_motion_take_up * b_i / 2 short of its commanded
  /// angle, against the direction of its last move along the commanded path (a joint that did not
  /// move keeps the side its last move left it on; before its first move it sits centred).
  std::vector<double> lost_motion_rad{};
  /// Fraction of the lost motion taken up on arrival, in [0, 1] (1: the joint lags by the full
  /// half play b_i / 2; less when friction stops it inside the play).
  double lost_motion_take_up = 1.0;
  /// Repeatability: TCP displacement drawn once per visit, Gaussian per axis of the base frame
  /// [m]. Not averaged away by repeat readings of one visit.
  double repeatability_sigma_m = 0.0;
  /// Joint deflection under gravity, dq_i = tau_i / k_i (off unless a test bed turns it on: the
  /// KUKA's does, the UR5's does not; a smooth error like this one is removed by RRBC).
  bool compliance = false;
  /// Mass of link i [kg], lumped halfway between the origins of DH frames i-1 and i.
  std::vector<double> link_mass_kg{};
  /// Stiffness of joint i [N m / rad] > 0.
  std::vector<double> joint_stiffness_nm_per_rad{};
  /// Mass at the TCP [kg] (the tracked sphere and its mount).
  double payload_kg = 0.0;
  /// Thermal growth: every link length (DH a) and offset (DH d) of the actual robot is longer by
  /// this fraction (alpha dT; aluminium 2.3e-5 per kelvin). Set per time by cell_events.hpp.
  double link_growth = 0.0;

  /// Throws InputError unless every value is finite and non-negative (link_growth: above -0.01)
  /// and every per-joint list has `n_joints` entries (transmission lists may both be empty, the
  /// lost motion list too; its take-up lies in [0, 1]).
  void validate(int n_joints) const;
  /// True when the drawn robot would be the nominal one and every visit lands exactly.
  [[nodiscard]] bool is_perfect() const;
};

/// One concrete robot drawn from a RobotErrorModel: what the seed decided.
struct RobotErrors {
  std::vector<kinematics::DhRow> dh_delta{};     ///< actual minus nominal DH row, per joint
  std::vector<double> transmission_phase_rad{};  ///< phi_i per joint (empty without transmission)
};

/// Draws the DH errors and transmission phases of one robot with `n_joints` joints.
RobotErrors draw_robot_errors(const RobotErrorModel& model, int n_joints, Random& rng);

}  // namespace vrreg::simulation
