// SPDX-License-Identifier: Apache-2.0
#pragma once
// Correcting targets with a registration model: pick fiducials and weights (octuplet, grid or
// scattered), interpolate the corrections (Eq. 7), correct (Eq. 8) and map to the robot frame.
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/correction_guard.hpp"
#include "vrreg/correction/interpolation.hpp"
#include "vrreg/correction/rrbc.hpp"

namespace vrreg {

/// What RRBC interpolates (Eq. 6-8): the registration and, per fiducial, its nominal robot
/// position, its correction and where it was read.
struct CorrectionField {
  SimilarityTransform T_robot_sensor{};  ///< Y ~ R X + tau (Eq. 2)
  Points3 fiducials_robot_m{};           ///< nominal robot positions of the fiducials [m]
  Points3 corrections_sensor_m{};        ///< epsilon_j (Eq. 6) per fiducial, sensor frame [m]
  /// Where each fiducial was read (its file line: the visiting order), or empty when unknown.
  std::vector<std::size_t> fiducials_sequence{};
};

/// Result of correct_targets; every per-target vector has one entry per target.
struct TargetCorrection {
  InterpolationMethod method_used = InterpolationMethod::kLinear;  ///< never kAuto after a call
  std::string layout{};  ///< what was used, e.g. "grid 6 x 7 x 5 nodes, 50 mm (every 2nd fiducial)"
  std::vector<Stencil> stencils{};
  Points3 corrections_sensor_m{};  ///< epsilon(T_X) per target (zero where status != kOk)
  Points3 corrected_sensor_m{};    ///< T_X + epsilon(T_X) (Eq. 8)
  Points3 corrected_robot_m{};     ///< R (T_X + epsilon) + tau; uncorrected mapping where flagged
  Points3 uncorrected_robot_m{};   ///< R T_X + tau
  int n_flagged = 0;             ///< targets with status != kOk
  /// Field models (docs/field-models.md): the predicted standard uncertainty of each corrected
  /// target's 3D error [m] (NaN where flagged); empty for the paper's stencils unless some target
  /// was extrapolated (then NaN but there; docs/uncertainty.md).
  Eigen::VectorXd predicted_sd_m{};
  /// Whether the correction was applied and the figures that decided it (correction_guard.hpp);
  /// none when the corrector was not guarded.
  std::optional<CorrectionGuard> guard{};
};

/// Corrects targets measured in the sensor frame with the fiducial corrections of `field`.
/// targets_sensor_m: measured targets [m]; targets_robot_nominal_m: their nominal robot positions
/// [m] (needed by octuplet only; may have 0 columns otherwise). Throws InputError when the method
/// cannot be used at all (e.g. grid on fiducials that hold no complete grid, octuplet without a
/// cube edge, scattered on coplanar fiducials). Not guarded (CorrectorOptions::guard): the
/// paper's method as published. targets_sequence: where each target was read (its
/// file line), or empty; with it and the fiducials' source lines, octuplet accepts corners
/// measured more than once and takes the reading nearest the target's.
TargetCorrection correct_targets(const CorrectionField& field,
                                 const ConstPoints3Ref& targets_sensor_m,
                                 const ConstPoints3Ref& targets_robot_nominal_m,
                                 const InterpolationSettings& settings,
                                 const std::vector<std::size_t>& targets_sequence = {});

}  // namespace vrreg
