// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to pipeline: the steps of Procedure 2 (paper section 4.4) on a measurement set, with
// errors that name its source: relabelling (Strategy 2) and Strategy 3's registration and
// correction.
#include <cstddef>
#include <optional>
#include <vector>

#include "model_corrector.hpp"
#include "vrreg/core/measurement.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/correction/cross_validation.hpp"
#include "vrreg/correction/orientation_field.hpp"
#include "vrreg/pipeline/model.hpp"
#include "vrreg/planning/strategy2_labels.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg::pipeline_detail {

/// Throws naming `set.source` unless it has configuration labels and joints.
void require_configurations(const MeasurementSet& set, planning::Strategy strategy);

/// Strategy 2 labels for the whole set (its visiting path).
planning::Strategy2Result relabel(const MeasurementSet& set, kinematics::JointNorm norm,
                                  const std::optional<kinematics::SerialChain>& robot);

/// Strategy 3: the model from every fiducial of `set` and the registration of the 8 volume
/// corners; `registered_sensor_m` / `registered_robot_m` receive those 8.
RegistrationModel volume_corner_model(const MeasurementSet& set, const planning::Procedure2& p2,
                                      const RegistrationOptions& registration,
                                      const InterpolationSettings& interpolation,
                                      RegistrationResult& registration_result,
                                      Points3& registered_sensor_m, Points3& registered_robot_m);

/// The points of a measurement set that evaluate and correct hand to the corrector, prepared the
/// same way for both: robot positions from the model's marker offset (hand-eye models), the
/// Strategy 2 labels of their own path, and the rows of the configuration asked for.
struct PointsToCorrect {
  const MeasurementSet* set = nullptr;  ///< the file's set, or one of the two below
  std::vector<std::size_t> rows;
  std::optional<planning::Strategy2Summary> relabelled;  ///< Strategy 2's relabelling
  MeasurementSet registered;  ///< sensor positions in the registration's frame (after a bump)
  MeasurementSet moved;                                  ///< robot positions from the offset
  MeasurementSet relabelled_set;

  PointsToCorrect() = default;
  PointsToCorrect(const PointsToCorrect&) = delete;  // `set` may point into this object
  PointsToCorrect& operator=(const PointsToCorrect&) = delete;
};

/// Fills `out` from `file_set` for `strategy` and `norm`, keeping the rows of `config` (all when
/// nullopt). `robot_positions_required`: every row must have a robot position after the marker
/// offset (evaluate compares against it; correct only uses it where a method needs it).
void prepare_points(const RegistrationModel& model, const MeasurementSet& file_set,
                    planning::Strategy strategy, kinematics::JointNorm norm,
                    std::optional<int> config, bool robot_positions_required,
                    PointsToCorrect& out);

/// The `rows` of `set` corrected (Eq. 7, 8) by the model's corrector for `request`, or one fitted
/// now (model_corrector.hpp): Strategy 3's nearest-configuration octuplets, the paper's stencils
/// with the rows' file lines as their visiting order, or a field model (docs/field-models.md).
/// nominal_robot_m: the rows' nominal robot positions [m], or 0 columns where the method does not
/// need them. `cross_validation` receives auto's table when auto was asked; `orientation` the
/// rows' corrected orientations when the model's fiducials and the rows carry them
/// (orientation_rows.hpp), else nullopt.
TargetCorrection correct_rows(const RegistrationModel& model, const MeasurementSet& set,
                              const std::vector<std::size_t>& rows, const CorrectorRequest& request,
                              const Points3& nominal_robot_m,
                              std::optional<CrossValidation>* cross_validation = nullptr,
                              std::optional<OrientationCorrection>* orientation = nullptr);

}  // namespace vrreg::pipeline_detail
