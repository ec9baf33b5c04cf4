// SPDX-License-Identifier: Apache-2.0
#pragma once
// An immutable serial chain of revolute and prismatic joints: DH table, joint limits, base and tool
// transforms (from a DH robot file, or from any URDF chain, see joint_chain.hpp).
// Frames: "base" is the robot frame poses are given in, "dh0" the DH base frame, "flange" the last
// DH frame, "tcp" the tool centre point (e.g. the centre of a tracked sphere).
#include <Eigen/Geometry>
#include <numbers>
#include <string>
#include <vector>

#include "vrreg/kinematics/dh.hpp"
#include "vrreg/kinematics/joint_vector.hpp"

namespace vrreg::kinematics {

/// Range of one joint [rad; m for a prismatic joint, in spite of the names], inclusive.
struct JointLimits {
  double lower_rad = -2.0 * std::numbers::pi;
  double upper_rad = 2.0 * std::numbers::pi;
};

/// The structure a chain has, which decides the analytic IK that applies to it.
enum class ChainFamily {
  kGeneric,  ///< no analytic IK
  kUr,       ///< Universal Robots geometry (6R, parallel joints 2-4, see ur_ik.hpp)
  kLwr,      ///< KUKA LWR 4+ geometry (7R, spherical shoulder and wrist, see lwr_ik.hpp)
};

/// Lower-case name of a family ("generic", "ur", "lwr").
const char* to_string(ChainFamily family);

/// Immutable serial chain; every constructor argument is validated (throws InputError).
class SerialChain {
 public:
  /// Rows are standard DH (frame i-1 -> i); limits one per row; T_base_dh0: DH base frame in
  /// the robot base frame; T_flange_tcp: TCP in the flange (last DH) frame. Lengths in m.
  SerialChain(std::string name, std::vector<DhRow> rows, std::vector<JointLimits> limits,
              const Eigen::Isometry3d& T_base_dh0 = Eigen::Isometry3d::Identity(),
              const Eigen::Isometry3d& T_flange_tcp = Eigen::Isometry3d::Identity());

  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] int n_joints() const { return static_cast<int>(rows_.size()); }
  [[nodiscard]] const std::vector<DhRow>& rows() const { return rows_; }
  [[nodiscard]] const DhRow& row(int i) const { return rows_[static_cast<std::size_t>(i)]; }
  [[nodiscard]] const std::vector<JointLimits>& limits() const { return limits_; }
  [[nodiscard]] const JointLimits& limit(int i) const {
    return limits_[static_cast<std::size_t>(i)];
  }
  [[nodiscard]] const Eigen::Isometry3d& T_base_dh0() const { return T_base_dh0_; }
  [[nodiscard]] const Eigen::Isometry3d& T_flange_tcp() const { return T_flange_tcp_; }
  /// True when both the base and the tool transform are the identity.
  [[nodiscard]] bool tcp_is_flange_in_dh0() const { return plain_; }
  [[nodiscard]] ChainFamily family() const { return family_; }

  /// The same chain with another tool (TCP in the flange frame, m).
  [[nodiscard]] SerialChain with_tool(const Eigen::Isometry3d& T_flange_tcp) const;
  /// The same chain with another base transform (DH base frame in the robot base frame, m).
  [[nodiscard]] SerialChain with_base(const Eigen::Isometry3d& T_base_dh0) const;
  /// The same chain under another name.
  [[nodiscard]] SerialChain with_name(std::string name) const;

  /// Maps a TCP pose in the base frame to the flange pose in the DH base frame.
  [[nodiscard]] Eigen::Isometry3d dh0_flange_from_base_tcp(
      const Eigen::Isometry3d& T_base_tcp) const;
  /// True when every joint of `q_rad` lies in its limits, widened by `tolerance_rad`.
  [[nodiscard]] bool within_limits(const JointRef& q_rad, double tolerance_rad = 0.0) const;
  /// Throws InputError unless `q_rad` has n_joints() finite entries; `what` names the caller.
  void check_joints(const JointRef& q_rad, const char* what) const;

 private:
  std::string name_{};
  std::vector<DhRow> rows_{};
  std::vector<JointLimits> limits_{};
  Eigen::Isometry3d T_base_dh0_{};
  Eigen::Isometry3d T_flange_tcp_{};
  Eigen::Isometry3d T_dh0_base_{};
  Eigen::Isometry3d T_tcp_flange_{};
  bool plain_ = true;
  ChainFamily family_ = ChainFamily::kGeneric;
};

/// Family of a DH table: its structure, checked to `tolerance` (m and rad).
ChainFamily detect_family(const std::vector<DhRow>& rows, double tolerance = 1e-12);

}  // namespace vrreg::kinematics
