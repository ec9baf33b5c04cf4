// SPDX-License-Identifier: Apache-2.0
#pragma once
// The local size of a model's cross-validated error: at each query point, the RMS over the
// held-out errors of its nearest fiducials (docs/field-models.md, "Predicted uncertainty").
#include "vrreg/core/types.hpp"

namespace vrreg {

/// Per query point (a column of `queries_m`), sqrt of the mean of `squared_m2` over the
/// min(k, #known) points of `points_m` nearest to it [m]. Entries of `squared_m2` that are NaN
/// (points without a held-out error) are left out. Throws InputError when none is known or
/// k < 1.
Eigen::VectorXd local_rms(const ConstPoints3Ref& points_m, const Eigen::VectorXd& squared_m2,
                          const ConstPoints3Ref& queries_m, int k);

}  // namespace vrreg
