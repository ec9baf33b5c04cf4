// SPDX-License-Identifier: Apache-2.0
#pragma once
// A smooth vector field predicted at query points: the mean and the standard deviation of the
// latent field, per axis (kriging, RBF; docs/field-models.md).
#include "vrreg/core/types.hpp"

namespace vrreg {

/// Prediction of a 3-vector field at N query points; column n belongs to query point n.
struct FieldPrediction {
  Points3 mean_m{};  ///< predicted field value per axis [m]
  /// Predicted standard deviation of the latent field per axis [m]: without the measurement
  /// noise (nugget) of a new observation, which the caller adds in quadrature if it needs it.
  Points3 sd_m{};
};

}  // namespace vrreg
