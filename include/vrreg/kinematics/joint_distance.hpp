// SPDX-License-Identifier: Apache-2.0
#pragma once
// Distances between arm configurations in joint space, with angle wrapping, and selection of the
// nearest configuration (paper section 4.4, Strategies 2 and 3; design.md section 4).
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// Joint-space norm. L2 may pick a branch that jumps by ~pi in one joint; Linf bounds every joint.
enum class JointNorm { kL2, kLinf };

/// Lower-case name of a norm ("l2", "linf").
const char* to_string(JointNorm norm);

/// Which joints are slides. A revolute joint's difference wraps into [-pi, pi); a prismatic
/// joint's [m] does not (a carriage 6.4 m along is not near one at 0.1 m), nor does that of a
/// revolute joint that other joints follow by other than whole turns (SerialChain::wraps). In the
/// norms a metre of travel weighs as a radian: both move an arm's marker by about its reach.
class JointKinds {
 public:
  JointKinds() = default;  ///< every joint revolute
  explicit JointKinds(const SerialChain& chain);
  /// a_i - b_i, wrapped unless joint i does not wrap [rad or m].
  [[nodiscard]] double difference(Eigen::Index i, double a, double b) const;

 private:
  std::vector<bool> prismatic_{};  // true: the joint's differences are not wrapped
};

/// sqrt(sum wrap(a_i - b_i)^2) [rad]; sizes must match (throws InputError).
double joint_distance_l2(const JointRef& a_rad, const JointRef& b_rad,
                         const JointKinds& kinds = {});
/// max |wrap(a_i - b_i)| [rad]; sizes must match (throws InputError).
double joint_distance_linf(const JointRef& a_rad, const JointRef& b_rad,
                           const JointKinds& kinds = {});
/// Distance in the chosen norm [rad].
double joint_distance(const JointRef& a_rad, const JointRef& b_rad, JointNorm norm,
                      const JointKinds& kinds = {});

/// Index of the column of `candidates_rad` (one configuration per column) nearest `reference_rad`;
/// ties go to the lower index; empty when there are no columns.
std::optional<int> nearest_configuration(const Eigen::Ref<const Eigen::MatrixXd>& candidates_rad,
                                         const JointRef& reference_rad, JointNorm norm,
                                         const JointKinds& kinds = {});
/// Column indices of `candidates_rad` sorted by distance to `reference_rad` (stable for ties).
std::vector<int> order_by_distance(const Eigen::Ref<const Eigen::MatrixXd>& candidates_rad,
                                   const JointRef& reference_rad, JointNorm norm,
                                   const JointKinds& kinds = {});

/// The 2 pi shift of each joint of `q_rad` that lies in the chain's limits and is nearest
/// `reference_rad` (what a controller commands); empty if some joint has no shift in its limits.
/// Joints that do not wrap (prismatic ones, SerialChain::wraps) are not shifted, only checked.
std::optional<JointVector> shift_nearest(const SerialChain& chain, const JointRef& q_rad,
                                         const JointRef& reference_rad);
/// The 2 pi shift of each joint within the limits with the smallest |q|; empty if none fits.
std::optional<JointVector> shift_into_limits(const SerialChain& chain, const JointRef& q_rad);

}  // namespace vrreg::kinematics
