// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to pipeline: a registration model's fiducials as correction data, and the corrector
// evaluate and correct use: the model's own when it answers what is asked, else one fitted now.
#include <optional>

#include "vrreg/correction/corrector.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/pipeline/model.hpp"
#include "vrreg/planning/procedure2.hpp"

namespace vrreg::pipeline_detail {

/// The model's fiducials as correction data; `robot` (to the marker) for the joint-space model.
CorrectorData corrector_data(const RegistrationModel& model,
                             const std::optional<kinematics::SerialChain>& robot);

/// The corrector options for `settings` under Procedure 2's `strategy` (Strategy 3: octuplets
/// whose corners are in the configuration nearest the target's, by `norm`).
CorrectorOptions corrector_options(const InterpolationSettings& settings,
                                   planning::Strategy strategy, kinematics::JointNorm norm);

/// What evaluate and correct ask of a model's corrector.
struct CorrectorRequest {
  InterpolationSettings settings;
  planning::Strategy strategy = planning::Strategy::kNone;
  kinematics::JointNorm norm = kinematics::JointNorm::kL2;
  /// A robot given now instead of the model's (the joint-space model is fitted for it).
  std::optional<kinematics::SerialChain> robot;
  bool refit = false;  ///< fit again even when the model's corrector answers the request
  bool exact = false;  ///< the field model itself, not its table (CorrectorOptions::tabulate)
  bool extrapolate = false;  ///< correct outside the support too (CorrectionQuery::extrapolate)
};

/// The model's corrector when it was fitted for the request, else one fitted now on the model's
/// fiducials. Throws InputError when the method cannot be used on them.
Corrector corrector_for(const RegistrationModel& model, const CorrectorRequest& request);

}  // namespace vrreg::pipeline_detail
