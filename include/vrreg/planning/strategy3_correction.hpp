// SPDX-License-Identifier: Apache-2.0
#pragma once
// Strategy 3 of Procedure 2 (paper section 4.4), correction half: for every target, each of the 8
// fiducials at the corners of the cube around it (Eq. 7, weights 1/8) is taken in the arm
// configuration whose joints are nearest the target's; then Eq. 8 with the single registration.
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/correction/rrbc.hpp"
#include "vrreg/kinematics/joint_distance.hpp"

namespace vrreg::planning {

/// Options of the Strategy 3 stencils.
struct Strategy3CorrectionOptions {
  double cube_edge_m = 0.0;         ///< octuplet cube edge a [m] (> 4 x match_tolerance_m)
  double match_tolerance_m = 1e-6;  ///< how far a fiducial may be from a cube corner [m]
  kinematics::JointNorm norm = kinematics::JointNorm::kL2;  ///< joint-space distance (wrapped)
  /// Throws InputError on a cube edge or tolerance that cannot be used.
  void validate() const;
};

/// Strategy 3 stencils, one per target: the fiducials at the 8 corners of the cube of edge a
/// around the target's nominal robot position (x fastest), each the one among the fiducials at
/// that corner whose joints are nearest the target's (ties: the earlier fiducial); weights 1/8.
/// kMissingCorner when a corner has no fiducial. Throws InputError when a target or a candidate
/// fiducial has no joints, or their joint counts differ.
std::vector<Stencil> nearest_configuration_stencils(const std::vector<Location>& fiducials,
                                                    const std::vector<Location>& targets,
                                                    const Strategy3CorrectionOptions& options);

/// Corrects `targets` (their sensor_m, robot_m nominal and q_rad) with `fiducials` that hold all
/// arm configurations and whose corrections [m, sensor] are against the single registration
/// T_robot_sensor (Eq. 6, 7, 8). Flagged targets (missing corner) keep the uncorrected mapping.
TargetCorrection correct_targets_strategy3(const SimilarityTransform& T_robot_sensor,
                                           const std::vector<Location>& fiducials,
                                           const ConstPoints3Ref& corrections_sensor_m,
                                           const std::vector<Location>& targets,
                                           const Strategy3CorrectionOptions& options);

}  // namespace vrreg::planning
