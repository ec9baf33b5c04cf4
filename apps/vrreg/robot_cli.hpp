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
#include "vrreg/robot_io/urdf_robot.hpp"

namespace CLI {
class App;
}

namespace vrreg::cli {

/// --tip-link and --base-link: which links of a URDF robot the chain runs between.
struct RobotLinkFlags {
  std::string tip_link;
  std::string base_link;
  /// Adds both options to `command` (whose robot option is `robot_option`, for the help text).
  void add_to(CLI::App& command, const std::string& robot_option);
  /// The links given, or those `remembered` (a saved model's robot) where none is given.
  [[nodiscard]] io::UrdfChainOptions links(
      const kinematics::SerialChain* remembered = nullptr) const;
};

/// The robot named on the command line (built-in name or robot file, the chain between `links`
/// for a URDF), with the tool offset replaced by `tool_mm` when given.
kinematics::SerialChain robot_from_args(const std::string& robot,
                                        const std::vector<double>& tool_mm,
                                        const io::UrdfChainOptions& links = {});

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
/// Names of a coupled chain's joint variables as a JSON array.
nlohmann::json joint_names_json(const kinematics::SerialChain& chain);
/// A coupled chain's joint variables and the joints that follow them, e.g.
/// "q1 lift, q2 shoulder_pan (column_lower = 0.5 q1, column_upper = 0.5 q1)".
std::string coupled_joints_text(const kinematics::SerialChain& chain);
/// "" for an all-revolute chain, else e.g. " (q1 in mm: prismatic)".
std::string prismatic_note(const kinematics::SerialChain& chain);

/// Throws InputError unless every value is finite; `what` names the option.
void check_finite(const std::vector<double>& values, const char* what);

}  // namespace vrreg::cli
