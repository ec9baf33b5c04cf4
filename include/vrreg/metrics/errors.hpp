// SPDX-License-Identifier: Apache-2.0
#pragma once
// Registration errors: TRE per target (Eq. 3), RMS_T (Eq. 4), FRE (Eq. 2).
#include <Eigen/Core>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// TRE(T_X) = ||R T_X + tau - T_Y|| per target (Eq. 3) [m]; targets in sensor / robot frame [m].
Eigen::VectorXd target_registration_errors(const SimilarityTransform& T_robot_sensor,
                                           const ConstPoints3Ref& targets_sensor_m,
                                           const ConstPoints3Ref& targets_robot_m);

/// TRE of already-mapped points: ||mapped_robot - targets_robot|| per column (Eq. 3) [m].
Eigen::VectorXd point_errors(const ConstPoints3Ref& mapped_robot_m,
                             const ConstPoints3Ref& targets_robot_m);

/// Root mean square of errors (Eq. 4 for TRE, Eq. 2 for fiducial residuals); 0 for no values.
double root_mean_square(const Eigen::Ref<const Eigen::VectorXd>& errors);

}  // namespace vrreg
