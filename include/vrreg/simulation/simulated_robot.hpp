// SPDX-License-Identifier: Apache-2.0
#pragma once
// A robot as it really moves: the controller commands joints computed with the nominal model;
// the arm takes those joints plus its transmission error and gravity deflection, and the TCP
// lands where the actual (perturbed) DH model puts it, give or take the repeatability. Lost motion
// depends on the path: each joint stops short of its command against the direction of its last
// move (JointApproach follows a path and gives those directions).
#include <Eigen/Core>

#include "vrreg/core/measurement.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/simulation/robot_error_model.hpp"

namespace vrreg::simulation {

/// The nominal chain, the actual chain (nominal DH + drawn errors) and the joint-level errors.
class SimulatedRobot {
 public:
  /// `nominal`: the controller's model with the tracked point as TCP; `errors` drawn from `model`
  /// for this chain (throws InputError when the sizes do not match).
  SimulatedRobot(kinematics::SerialChain nominal, RobotErrorModel model, RobotErrors errors);

  [[nodiscard]] const kinematics::SerialChain& nominal() const { return nominal_; }
  [[nodiscard]] const kinematics::SerialChain& actual() const { return actual_; }
  [[nodiscard]] const RobotErrorModel& model() const { return model_; }
  [[nodiscard]] const RobotErrors& errors() const { return errors_; }

  /// Joint angles the arm really takes for commanded joints `q_cmd_rad` [rad]: plus the
  /// transmission error and, when enabled, the gravity deflection; minus, per joint j, the lost
  /// motion take_up * b_j / 2 * approach_sign(j), where `approach_sign` holds the sign (-1, 0, +1)
  /// of each joint's last move (JointApproach); empty = 0 for every joint.
  [[nodiscard]] kinematics::JointVector actual_joints(
      const kinematics::JointRef& q_cmd_rad,
      const kinematics::JointRef& approach_sign = Eigen::VectorXd()) const;
  /// Where the TCP really is for commanded joints, without repeatability [m, base frame].
  [[nodiscard]] Eigen::Vector3d actual_tcp_m(
      const kinematics::JointRef& q_cmd_rad,
      const kinematics::JointRef& approach_sign = Eigen::VectorXd()) const;
  /// The TCP's true orientation for commanded joints, base frame (repeatability moves the TCP
  /// by a translation only).
  [[nodiscard]] Eigen::Matrix3d actual_rotation(
      const kinematics::JointRef& q_cmd_rad,
      const kinematics::JointRef& approach_sign = Eigen::VectorXd()) const;
  /// One visit: actual_tcp_m plus a repeatability draw (Gaussian per base axis) [m].
  [[nodiscard]] Eigen::Vector3d visit_tcp_m(
      const kinematics::JointRef& q_cmd_rad, Random& rng,
      const kinematics::JointRef& approach_sign = Eigen::VectorXd()) const;

 private:
  kinematics::SerialChain nominal_;
  kinematics::SerialChain actual_;
  RobotErrorModel model_{};
  RobotErrors errors_{};
};

/// Follows a commanded path and gives, per joint, the sign of its last move (+1, -1; 0 before
/// its first move): the side of the gear play each joint rests on (update_approach_sign).
class JointApproach {
 public:
  /// Starts where the arm stands (`q_start_rad` [rad]), every joint centred in its play.
  explicit JointApproach(const kinematics::JointRef& q_start_rad);
  /// Moves to `q_rad` [rad]; returns the approach signs at arrival.
  const kinematics::JointVector& move_to(const kinematics::JointRef& q_rad);
  [[nodiscard]] const kinematics::JointVector& sign() const { return sign_; }

 private:
  kinematics::JointVector q_rad_;
  kinematics::JointVector sign_;
};

}  // namespace vrreg::simulation
