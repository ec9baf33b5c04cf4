// SPDX-License-Identifier: Apache-2.0
#pragma once
// Arm configurations for a plan (paper section 6 with section 4.4): each part point is reached by
// an IK solution of a fixed tool orientation, and each of its fiducials by the IK solution nearest
// the part point's joints, so fiducials and target share the arm configuration.
#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "vrreg/kinematics/configuration_label.hpp"
#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::planning {

/// Tool pointing down: TCP z axis along -z of the robot base, R_base_tcp = Rx(pi) (rpy 180, 0, 0).
Eigen::Matrix3d tool_pointing_down();

/// How joints are chosen for every planned location.
struct ArmConfigurationOptions {
  Eigen::Matrix3d R_base_tcp = tool_pointing_down();        ///< fixed TCP orientation, base frame
  kinematics::JointNorm norm = kinematics::JointNorm::kL2;  ///< nearest-configuration norm
  double psi_rad = 0.0;  ///< LWR arm angle for every location [rad] (UR: unused)
  /// Part points take the IK solution nearest these joints [rad] (2 pi shifts included); when
  /// absent, the first solution within the limits in configuration-label order.
  std::optional<kinematics::JointVector> home_q_rad{};
  /// Throws InputError on a non-proper rotation, a non-finite psi, or home joints that do not fit
  /// `chain`; and when `chain` has no analytic IK (neither UR nor LWR structure).
  void validate(const kinematics::SerialChain& chain) const;
};

/// Joints chosen for one location, or why there are none.
struct JointChoice {
  kinematics::IkStatus status = kinematics::IkStatus::kUnreachable;
  std::string message{};            ///< why not (empty when ok)
  kinematics::JointVector q_rad{};  ///< commanded joints [rad], within the limits
  kinematics::ConfigurationLabel config{};
  double distance_rad = 0.0;  ///< joint distance to the reference (options.norm)
  [[nodiscard]] bool ok() const { return status == kinematics::IkStatus::kOk; }
};

/// TCP pose at `point_base_m` [m] with the options' orientation.
Eigen::Isometry3d tcp_pose(const Eigen::Vector3d& point_base_m,
                           const ArmConfigurationOptions& options);

/// Joints for a part point [m, base frame]: nearest options.home_q_rad, else the first solution.
JointChoice part_joints(const kinematics::SerialChain& chain, const Eigen::Vector3d& point_base_m,
                        const ArmConfigurationOptions& options);

/// Joints for a fiducial [m, base frame]: of every IK solution (each moved to its 2 pi shift within
/// the limits nearest `reference_q_rad`), the one nearest `reference_q_rad` in options.norm.
JointChoice nearest_joints(const kinematics::SerialChain& chain,
                           const Eigen::Vector3d& point_base_m,
                           const kinematics::JointRef& reference_q_rad,
                           const ArmConfigurationOptions& options);

}  // namespace vrreg::planning
