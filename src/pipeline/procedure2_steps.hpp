#pragma once
// Internal to pipeline: the steps of Procedure 2 (paper section 4.4) on a measurement set, with
// errors that name its source: relabelling (Strategy 2) and Strategy 3's registration and
// correction.
#include <cstddef>
#include <optional>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/pipeline/field_model.hpp"
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

/// Strategy 3 correction of the `rows` of `set` with the model's single registration.
TargetCorrection correct_volume_corners(const RegistrationModel& model, const MeasurementSet& set,
                                        const std::vector<std::size_t>& rows,
                                        const InterpolationSettings& settings,
                                        kinematics::JointNorm norm);

/// The `rows` of `set` corrected with the model (Eq. 7, 8) as `strategy` says: Strategy 3's
/// nearest-configuration octuplets, else `settings` on the model's correction field with the rows'
/// file lines as their visiting order. nominal_robot_m: the rows' nominal robot positions [m], or
/// 0 columns where the interpolation does not need them.
/// A field model (docs/field-models.md) instead when settings.method is one: fitted on the
/// model's fiducials (`robot` for the joint-space model), its cross-validation table, when `auto`
/// chose, into `cross_validation`.
TargetCorrection correct_rows(const RegistrationModel& model, const MeasurementSet& set,
                              const std::vector<std::size_t>& rows,
                              const InterpolationSettings& settings, planning::Strategy strategy,
                              kinematics::JointNorm norm, const Points3& nominal_robot_m,
                              const std::optional<kinematics::SerialChain>& robot = std::nullopt,
                              std::optional<CrossValidation>* cross_validation = nullptr);

}  // namespace vrreg::pipeline_detail
