#pragma once
// Internal to pipeline: the steps of Procedure 2 (paper section 4.4) on a measurement set, with
// errors that name its source: relabelling (Strategy 2) and Strategy 3's registration and
// correction.
#include <cstddef>
#include <optional>
#include <vector>

#include "model_corrector.hpp"
#include "vrreg/core/measurement.hpp"
#include "vrreg/correction/cross_validation.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/pipeline/model.hpp"
#include "vrreg/planning/strategy2_labels.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg::pipeline_detail {

/// Throws naming `set.source` unless it has configuration labels and joints.
void require_configurations(const MeasurementSet& set, planning::Strategy strategy);

/// Strategy 2 labels for the whole set (its visiting path).
planning::Strategy2Result relabel(const MeasurementSet& set, kinematics::JointNorm norm);

/// Strategy 3: the model from every fiducial of `set` and the registration of the 8 volume
/// corners; `registered_sensor_m` / `registered_robot_m` receive those 8.
RegistrationModel volume_corner_model(const MeasurementSet& set, const planning::Procedure2& p2,
                                      const RegistrationOptions& registration,
                                      const InterpolationSettings& interpolation,
                                      RegistrationResult& registration_result,
                                      Points3& registered_sensor_m, Points3& registered_robot_m);

/// The `rows` of `set` corrected (Eq. 7, 8) by the model's corrector for `request`, or one fitted
/// now (model_corrector.hpp): Strategy 3's nearest-configuration octuplets, the paper's stencils
/// with the rows' file lines as their visiting order, or a field model (docs/field-models.md).
/// nominal_robot_m: the rows' nominal robot positions [m], or 0 columns where the method does not
/// need them. `cross_validation` receives auto's table when auto was asked.
TargetCorrection correct_rows(const RegistrationModel& model, const MeasurementSet& set,
                              const std::vector<std::size_t>& rows,
                              const CorrectorRequest& request, const Points3& nominal_robot_m,
                              std::optional<CrossValidation>* cross_validation = nullptr);

}  // namespace vrreg::pipeline_detail
