// SPDX-License-Identifier: Apache-2.0
#pragma once
// Poses that make the marker offset observable (hand-eye registration, docs/hand-eye.md): with one
// fixed tool orientation the marker's position on the flange cannot be told from the registration's
// translation (the paper's datasets). A small set of tilts about two axes, as the hand-eye
// literature recommends, at a few positions (the corners and centre of the planned volume)
// separates them; the plan's own locations keep their orientation, so RRBC interpolates an error
// field measured at one orientation.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/planning/arm_configuration.hpp"
#include "vrreg/planning/plan.hpp"

namespace vrreg::planning {

/// The tilts, as rotations about the TCP's own axes: +x, +y, -x, -y by `tilt_rad`.
std::vector<Eigen::Matrix3d> offset_tilts(double tilt_rad);

/// Label prefix of the offset poses: "offset-<position>-<tilt>".
inline constexpr const char* kOffsetPosePrefix = "offset-";

/// What add_offset_poses did.
struct OffsetPoseSummary {
  double tilt_rad = 0.0;
  long long n_added = 0;        ///< offset poses added (at the start of the visiting order)
  long long n_unreachable = 0;  ///< tilted poses without an IK solution (left out)
};

/// Adds, before the plan's locations, the poses for the marker offset: at the 8 corners and the
/// centre of the box around the plan's locations, the tool tilted by each of offset_tilts, with
/// the IK solution nearest the joints of the plan's location closest to it (same arm
/// configuration). Fiducials; part = the nearest part point. Throws InputError unless
/// 0 < tilt_rad <= 60 deg or on an empty plan.
OffsetPoseSummary add_offset_poses(const kinematics::SerialChain& chain, PlanResult& plan,
                                   const ArmConfigurationOptions& arm, double tilt_rad);

}  // namespace vrreg::planning
