// SPDX-License-Identifier: Apache-2.0
#pragma once
// The paper's two test beds (section 4): a UR5 and a KUKA LWR 4+, each carrying a tracked sphere
// (the TCP) in a work volume seen by an OptiTrack-like tracker, with default error parameters
// calibrated so that the simulated data look like the paper's (docs/testbed-calibration.md).
#include <Eigen/Core>
#include <string>
#include <string_view>

#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/simulation/robot_error_model.hpp"
#include "vrreg/simulation/tracker_model.hpp"

namespace vrreg::simulation {

/// Everything that may differ between two simulated runs of one test bed: the robot's errors
/// and the tracker (what an error-model file holds).
struct TestbedErrorModel {
  RobotErrorModel robot{};
  TrackerModel tracker{};
  /// Throws InputError when a part is invalid for a robot with `n_joints` joints.
  void validate(int n_joints) const {
    robot.validate(n_joints);
    tracker.validate();
  }
};

/// Which robot a test bed has and so how its controller picks joints.
enum class TestbedKind {
  kUr5,   ///< UR controller: the one IK solution nearest the previous location's joints
  kLwr4,  ///< custom analytic IK: every feasible configuration at a fixed arm angle
};

/// A test bed: robot, fixed geometry of the cell and default errors.
struct Testbed {
  TestbedKind kind = TestbedKind::kUr5;
  std::string name{};               ///< "ur5" or "lwr4"
  kinematics::SerialChain nominal;  ///< the controller's model; TCP = the tracked sphere
  Eigen::Matrix3d tcp_rotation{};   ///< commanded TCP orientation, base frame (fixed)
  Eigen::Vector3d volume_centre_m{};  ///< centre of the work volume, base frame [m]
  double arm_angle_rad = 0.0;       ///< LWR: the arm angle psi every location is sent with
  /// UR: the joints the arm stands at before the first location. LWR: the home posture the
  /// analytic IK ranks its configurations by (see aik_order.hpp) [rad].
  kinematics::JointVector home_q_rad{};
  double sigma_rep_spec_m = 0.0;     ///< manufacturer's repeatability, for sigma_noise (Eq. 9)
  TestbedErrorModel default_errors{};  ///< calibrated defaults
};

/// The UR5 test bed: 250 x 300 x 200 mm volume 2.1 m from the tracker, K = 12.
Testbed ur5_testbed();
/// The KUKA LWR 4+ test bed: 240 x 200 x 200 mm volume 1.8 m from the tracker, four arm
/// configurations per location, one reading each.
Testbed lwr4_testbed();
/// The test bed called `name` ("ur5" or "lwr4", case-insensitive); throws InputError otherwise.
Testbed testbed_by_name(std::string_view name);

}  // namespace vrreg::simulation
