#pragma once
// Internal to pipeline: correcting targets with a model of the whole correction field
// (docs/field-models.md), chosen by name or by cross-validation (`auto`), with a predicted
// uncertainty per target.
#include <optional>

#include "field_models.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/pipeline/field_model.hpp"
#include "vrreg/pipeline/model.hpp"

namespace vrreg::pipeline_detail {

/// The model's fiducials as field data; `robot` (to the marker) for the joint-space model.
FieldData field_data(const RegistrationModel& model,
                     const std::optional<kinematics::SerialChain>& robot);

/// A field model fitted on a registration model, and how sure it is.
struct FittedField {
  InterpolationMethod method = InterpolationMethod::kTrilinear;  ///< never kAuto
  std::unique_ptr<FieldModel> model;
  std::optional<CrossValidation> cross_validation;  ///< the table, when `auto` chose
  /// The method's cross-validated RMS (3D) over all fiducials [m].
  double cv_rms_m = 0.0;
  /// Per fiducial, its held-out squared error (3D) [m^2], NaN where it was not predicted: a
  /// target's sigma_pred is the RMS of these over its 16 nearest fiducials (local_rms). Empty
  /// when the model has its own uncertainty (kriging) or uses cv_rms_m for every target (joint).
  Eigen::VectorXd cv_squared_error_m2;
};

/// Fits `method` (a field model or kAuto) on `data`.
FittedField fit_field(InterpolationMethod method, const FieldData& data);

/// Corrects targets (Eq. 8 with the field's epsilon, then {R, tau}); flagged where the model
/// has no prediction. targets_joints_rad: one column per target, or 0 x 0.
TargetCorrection correct_with_field(const FittedField& field, const FieldData& data,
                                    const ConstPoints3Ref& targets_sensor_m,
                                    const Eigen::MatrixXd& targets_joints_rad);

}  // namespace vrreg::pipeline_detail
