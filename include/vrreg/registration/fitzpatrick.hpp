// SPDX-License-Identifier: Apache-2.0
#pragma once
// Expected registration errors for isotropic, independent fiducial localisation error (FLE),
// Fitzpatrick, West and Maurer, IEEE TMI 17(5), 1998.
#include <Eigen/Core>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// <TRE^2> at `target_m` ~ <FLE^2>/N (1 + 1/3 sum_k d_k^2 / f_k^2), where d_k is the target's
/// distance from the k-th principal axis of the fiducials and f_k the fiducials' RMS distance from
/// it [m^2]. fiducials_m: fiducial positions [m]; fle_sq_m2: <FLE^2> = 3 sigma^2 per axis.
double expected_tre_squared(const ConstPoints3Ref& fiducials_m, const Eigen::Vector3d& target_m,
                            double fle_sq_m2);

/// <FRE^2> ~ (1 - 2/N) <FLE^2> [m^2] for N fiducials.
double expected_fre_squared(Eigen::Index n_fiducials, double fle_sq_m2);

}  // namespace vrreg
