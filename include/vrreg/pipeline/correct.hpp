// SPDX-License-Identifier: Apache-2.0
#pragma once
// The front door, step 3: RRBC-corrected robot-frame positions for points measured by the sensor
// (Eq. 7, 8, then mapped with {R, tau}): what the robot should be commanded to.
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/correction/orientation_field.hpp"
#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/pipeline/field_model.hpp"
#include "vrreg/pipeline/interpolation_choice.hpp"
#include "vrreg/pipeline/model.hpp"
#include "vrreg/pipeline/points.hpp"

namespace vrreg {

/// Options of correct; unset members take the model's value.
struct CorrectOptions {
  std::optional<int> config{};  ///< correct points with this label only (default: the model's)
  InterpolationChoice interpolation{};  ///< over the model's stored interpolation
  /// The arm (to the marker) for the joint-space field model; default: the model's.
  std::optional<kinematics::SerialChain> robot{};
  /// Fit the corrector again even when the model's own answers (its fiducials unchanged: the
  /// same numbers unless the code that fits has changed). Off: the model's corrector is used
  /// whenever it was fitted for the interpolation asked.
  bool refit = false;
  /// Kriging and RBF: correct with the model itself rather than its table (within 1/20 of the noise,
  /// measured when fitted; CorrectorOptions::tabulate). Slower: kriging's sd costs O(J^2) a point.
  bool exact = false;
  /// Correct points outside the method's support too (every method), status "extrapolated",
  /// with a widened sd (CorrectionQuery::extrapolate). Off: they are left uncorrected.
  bool extrapolate = false;
};

/// The corrected points, in the order given.
struct CorrectResult {
  InterpolationSettings interpolation{};  ///< as used
  TargetCorrection correction{};  ///< corrected_robot_m is what to command (uncorrected if flagged)
  std::vector<std::string> names{};  ///< point labels; empty for arrays given without names
  std::vector<std::optional<int>> configs{};  ///< configuration labels; empty when none were given
  /// Field models: the cross-validation table when `auto` chose the method.
  std::optional<CrossValidation> cross_validation{};
  /// The points' corrected orientations (corrected_R_robot_marker: what to command), when the
  /// model's fiducials carry measured and commanded orientations and every point a measured one
  /// (a measurement set's sensor_q columns; docs/orientation.md).
  std::optional<OrientationCorrection> orientation{};
};

/// Corrects the target rows of a measurement set (robot columns needed by octuplet and Strategy 3
/// only; errors name `points.source`), following the model's Procedure 2 strategy.
CorrectResult correct(const RegistrationModel& model, const MeasurementSet& points,
                      const CorrectOptions& options = {});

/// Corrects points given as arrays [m]: sensor_m always; robot_m (nominal) for octuplet; configs
/// and joints_rad for models built with Strategy 2 or 3.
CorrectResult correct(const RegistrationModel& model, const MeasuredPoints& points,
                      const CorrectOptions& options = {});

}  // namespace vrreg
