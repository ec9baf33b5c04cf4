// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared by `vrreg fk` and `vrreg ik`: the ROBOT argument, --tool-mm, pose and joint printing.
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/kinematics/ik_result.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::cli {

/// The robot named on the command line (built-in name or robot file), with the tool offset
/// replaced by `tool_mm` when given.
kinematics::SerialChain robot_from_args(const std::string& robot,
                                        const std::vector<double>& tool_mm);

/// One line naming the frames the poses are in, e.g. "flange in the DH base frame".
std::string pose_frame_description(const kinematics::SerialChain& chain);

/// Pose as JSON: xyz_mm, rpy_deg (R = Rz(yaw) Ry(pitch) Rx(roll)) and rotation (3 rows).
void pose_to_json(const Eigen::Isometry3d& pose, nlohmann::json& j);

/// "x y z" in mm with `decimals` places.
std::string xyz_mm_text(const Eigen::Vector3d& metres, int decimals = 6);
/// "roll pitch yaw" in deg with `decimals` places.
std::string rpy_deg_text(const Eigen::Matrix3d& rotation, int decimals = 6);

/// Names of the singularity flags as a JSON array of strings.
nlohmann::json singular_json(std::uint8_t flags);

/// Joint values in degrees as a JSON array.
nlohmann::json degrees_json(const Eigen::Ref<const Eigen::VectorXd>& q_rad);

/// Joint `i`'s value as shown: deg for a revolute joint, mm for a prismatic one.
double shown_joint_value(const kinematics::SerialChain& chain, int i, double q);
/// Joint values as shown (deg, mm for prismatic joints) as a JSON array.
nlohmann::json shown_joints_json(const kinematics::SerialChain& chain,
                                 const Eigen::Ref<const Eigen::VectorXd>& q);
/// "" for an all-revolute chain, else e.g. " (q1 in mm: prismatic)".
std::string prismatic_note(const kinematics::SerialChain& chain);

/// Throws InputError unless every value is finite; `what` names the option.
void check_finite(const std::vector<double>& values, const char* what);

}  // namespace vrreg::cli
