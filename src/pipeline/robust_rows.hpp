// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to pipeline: the robust branch of register_fiducials (RegisterOptions::robust).
#include <cstddef>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"

namespace vrreg::pipeline_detail {

/// The fiducial rows that survive the robust check, and how the rejected ones are kept.
struct RobustRows {
  std::vector<std::size_t> registered;  ///< rows to register (the inliers)
  RobustReport report;                  ///< outliers by name (filled or dropped)
};

/// Judges the fiducial `rows` of `set` against their neighbours (correction/outliers.hpp) with
/// the noise of these rows' repeats and options.sigma_rep_m; throws (naming the set) when the
/// set is unusable.
RobustRows robust_rows(const MeasurementSet& set, const std::vector<std::size_t>& rows,
                       const RegisterOptions& options);

/// The model's fiducials and corrections (Eq. 6) under T_robot_sensor: every row of `rows` except
/// the dropped outliers, the filled ones with their neighbours' correction and the sensor
/// position that correction implies (so that Eq. 6 holds for every fiducial of the model).
void fill_model_fiducials(const MeasurementSet& set, const std::vector<std::size_t>& rows,
                          const RobustReport& report, const SimilarityTransform& T_robot_sensor,
                          RegistrationModel& model);

}  // namespace vrreg::pipeline_detail
