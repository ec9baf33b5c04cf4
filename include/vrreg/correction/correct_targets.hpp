#pragma once
// Correcting targets with a registration model: pick fiducials and weights (octuplet, grid or
// scattered), interpolate the corrections (Eq. 7), correct (Eq. 8) and map to the robot frame.
#include <string>
#include <vector>

#include "vrreg/core/model.hpp"
#include "vrreg/core/types.hpp"
#include "vrreg/correction/rrbc.hpp"

namespace vrreg {

/// Result of correct_targets; every per-target vector has one entry per target.
struct TargetCorrection {
  InterpolationMethod method_used = InterpolationMethod::kAuto;  ///< never kAuto after a call
  std::string layout;  ///< what was used, e.g. "grid 6 x 7 x 5 nodes, 50 mm (every 2nd fiducial)"
  std::vector<Stencil> stencils;
  Points3 corrections_sensor_m;  ///< epsilon(T_X) per target (zero where status != kOk)
  Points3 corrected_sensor_m;    ///< T_X + epsilon(T_X) (Eq. 8)
  Points3 corrected_robot_m;     ///< R (T_X + epsilon) + tau; uncorrected mapping where flagged
  Points3 uncorrected_robot_m;   ///< R T_X + tau
  int n_flagged = 0;             ///< targets with status != kOk
};

/// Corrects targets measured in the sensor frame with the model's fiducial corrections.
/// targets_sensor_m: measured targets [m]; targets_robot_nominal_m: their nominal robot positions
/// [m] (needed by octuplet only; may have 0 columns otherwise). Throws InputError when the method
/// cannot be used at all (e.g. grid on fiducials that hold no complete grid, octuplet without a
/// cube edge, scattered on coplanar fiducials). targets_sequence: where each target was read (its
/// file line), or empty; with it and the fiducials' source lines, octuplet accepts corners
/// measured more than once and takes the reading nearest the target's.
TargetCorrection correct_targets(const RegistrationModel& model,
                                 const ConstPoints3Ref& targets_sensor_m,
                                 const ConstPoints3Ref& targets_robot_nominal_m,
                                 const InterpolationSettings& settings,
                                 const std::vector<std::size_t>& targets_sequence = {});

}  // namespace vrreg
