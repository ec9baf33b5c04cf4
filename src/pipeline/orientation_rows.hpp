// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to pipeline: the orientations of the rows evaluate and correct hand to the corrector,
// corrected by an orientation field fitted with the positions' method (correction/
// orientation_field.hpp), when the model's fiducials carry measured and commanded orientations.
#include <cstddef>
#include <optional>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/correction/corrector.hpp"
#include "vrreg/correction/orientation_field.hpp"
#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/pipeline/model.hpp"

namespace vrreg::pipeline_detail {

/// The model's fiducials' rotation residuals (robot frame [rad]) and the noise of one averaged
/// orientation per axis [rad] when the fiducials have repeat readings. Requires
/// model.has_fiducial_orientations().
struct OrientationInputs {
  Points3 residuals_rad;
  std::optional<double> noise_sd_rad;
};
OrientationInputs orientation_inputs(const RegistrationModel& model);

/// The orientation field of the model's fiducials fitted with `positions` (its method, its joint
/// model); `robot` as for the positions' corrector data.
OrientationCorrector fit_orientation(const RegistrationModel& model, const Corrector& positions,
                                     const std::optional<kinematics::SerialChain>& robot);

/// The orientation field that answers with `positions`: the model's own when `positions` is the
/// model's corrector, else one fitted now; nullopt unless the model's fiducials carry measured
/// and commanded orientations.
std::optional<OrientationCorrector> orientation_field_for(
    const RegistrationModel& model, const Corrector& positions,
    const std::optional<kinematics::SerialChain>& robot);

/// Throws InputError when `n_orientations` points carry measured orientations and the model's
/// fiducials do not (there is no orientation field to correct them with).
void require_orientation_field(const RegistrationModel& model, std::size_t n_orientations);

/// The `rows` of `set` (the points of `query`, corrected for their positions by `positions`:
/// `answer`)
/// with their orientations corrected; nullopt unless the model's fiducials carry measured and
/// commanded orientations and every row a measured one. `robot`: as for the positions. The
/// model's own orientation field when `positions` is the model's corrector, else one fitted now.
std::optional<OrientationCorrection> correct_orientation_rows(
    const RegistrationModel& model, const MeasurementSet& set, const std::vector<std::size_t>& rows,
    const Corrector& positions, const CorrectionQuery& query, const TargetCorrection& answer,
    const std::optional<kinematics::SerialChain>& robot);

}  // namespace vrreg::pipeline_detail
