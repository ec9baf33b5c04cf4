// SPDX-License-Identifier: Apache-2.0
#pragma once
// An immutable serial chain of revolute and prismatic joints: DH table, joint limits, base and tool
// transforms (from a DH robot file, or from any URDF chain, see joint_chain.hpp).
// Frames: "base" is the robot frame poses are given in, "dh0" the DH base frame, "flange" the last
// DH frame, "tcp" the tool centre point (e.g. the centre of a tracked sphere).
// Joints and rows: each DH row is one physical joint. Its value is usually a joint variable of its
// own; a coupled chain (URDF <mimic> joints) has rows whose value is a linear map of another
// joint's variable, and then fewer variables than rows. Every function that takes joint values
// takes the variables (n_joints() of them), the ones a controller commands.
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
  bool operator==(const JointLimits&) const = default;
};

/// How one DH row's joint value follows the joint variables (a URDF <mimic> joint):
/// q_row = multiplier * q[variable] + offset.
struct JointCoupling {
  int variable = 0;         ///< 0-based index of the joint variable the row follows
  double multiplier = 1.0;  ///< finite, non-zero [row unit per variable unit]
  double offset = 0.0;      ///< [rad; m if the row is prismatic]
  bool operator==(const JointCoupling&) const = default;
};

/// One joint variable of a coupled chain: what the controller commands.
struct JointVariable {
  std::string name{};                     ///< the joint it is (for messages)
  JointType type = JointType::kRevolute;  ///< its unit: rad, or m if prismatic
  JointLimits limits{};                   ///< its own range [rad; m if prismatic]
  bool operator==(const JointVariable&) const = default;
};

/// The couplings of a chain: one per DH row, and the variables they follow.
struct JointCouplings {
  std::vector<JointCoupling> rows{};
  std::vector<JointVariable> variables{};
  bool operator==(const JointCouplings&) const = default;
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
  /// Number of joint variables (what joint vectors hold); n_rows() unless joints are coupled.
  [[nodiscard]] int n_joints() const {
    return coupled() ? static_cast<int>(couplings_.variables.size()) : n_rows();
  }
  /// Number of DH rows (physical joints).
  [[nodiscard]] int n_rows() const { return static_cast<int>(rows_.size()); }
  [[nodiscard]] const std::vector<DhRow>& rows() const { return rows_; }
  [[nodiscard]] const DhRow& row(int i) const { return rows_[static_cast<std::size_t>(i)]; }
  /// Limits of each DH row (as constructed) [rad; m if prismatic].
  [[nodiscard]] const std::vector<JointLimits>& limits() const { return limits_; }
  /// Range of joint variable `i`: its own, narrowed to where every row following it stays within
  /// that row's limits [rad; m if prismatic].
  [[nodiscard]] const JointLimits& limit(int i) const {
    return (coupled() ? variable_limits_ : limits_)[static_cast<std::size_t>(i)];
  }
  /// True when joint variable `i` slides [m] rather than turns [rad].
  [[nodiscard]] bool prismatic(int i) const;
  /// True when a full turn of joint variable `i` gives the same pose (a revolute variable whose
  /// rows all turn by whole turns with it): its values may be wrapped and shifted by 2 pi.
  [[nodiscard]] bool wraps(int i) const;

  /// True when some row follows another joint's variable (URDF mimic joints).
  [[nodiscard]] bool coupled() const { return !couplings_.rows.empty(); }
  /// The couplings; empty lists when every row is its own variable.
  [[nodiscard]] const JointCouplings& couplings() const { return couplings_; }
  /// The same chain with these couplings (one per row; variables each followed by some row).
  /// Throws InputError naming the row or variable on an index out of range, a zero or
  /// non-finite multiplier or offset, bad limits, or a variable whose rows' limits leave no range.
  [[nodiscard]] SerialChain with_couplings(JointCouplings couplings) const;
  /// The same rows with every row its own variable (the chain a coupled one expands to).
  [[nodiscard]] SerialChain uncoupled() const;
  /// The value of every DH row at joint variables `q` (q itself on an uncoupled chain)
  /// [rad; m if prismatic]. Throws InputError unless q has n_joints() finite entries.
  [[nodiscard]] JointVector row_values(const JointRef& q) const;
  /// d q_row / d q_variable: n_rows() x n_joints() (the identity on an uncoupled chain).
  [[nodiscard]] Eigen::MatrixXd coupling_matrix() const;
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
  /// Names of the URDF links the chain runs between, when it came from a URDF (else empty).
  [[nodiscard]] const std::string& urdf_base_link() const { return urdf_base_link_; }
  [[nodiscard]] const std::string& urdf_tip_link() const { return urdf_tip_link_; }
  /// The same chain recording the URDF links it runs between.
  [[nodiscard]] SerialChain with_urdf_links(std::string base_link, std::string tip_link) const;

  /// Maps a TCP pose in the base frame to the flange pose in the DH base frame.
  [[nodiscard]] Eigen::Isometry3d dh0_flange_from_base_tcp(
      const Eigen::Isometry3d& T_base_tcp) const;
  /// True when every joint variable of `q_rad` lies in its limits (limit(i)), widened by
  /// `tolerance_rad`.
  [[nodiscard]] bool within_limits(const JointRef& q_rad, double tolerance_rad = 0.0) const;
  /// Throws InputError unless `q_rad` has n_joints() finite entries; `what` names the caller.
  void check_joints(const JointRef& q_rad, const char* what) const;

 private:
  // Copies what with_tool, with_base and with_name keep besides the constructor's arguments.
  SerialChain& keep_extras_of(const SerialChain& other);

  std::string name_{};
  std::vector<DhRow> rows_{};
  std::vector<JointLimits> limits_{};
  JointCouplings couplings_{};
  std::vector<JointLimits> variable_limits_{};  // limit(i) of a coupled chain
  std::string urdf_base_link_{};
  std::string urdf_tip_link_{};
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
