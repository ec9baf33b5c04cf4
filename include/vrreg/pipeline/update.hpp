// SPDX-License-Identifier: Apache-2.0
#pragma once
// Keeping a registered model true without measuring every fiducial again: after a bump (the sensor
// moved), T_robot_sensor is updated from a few points while the fitted correction field is kept;
// after a drift (the robot changed smoothly, e.g. warming up), a smooth change fitted to a few
// fiducials read again moves every fiducial and the model is registered and fitted again. The new
// model records where it came from (ModelUpdate).
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/pipeline/check.hpp"
#include "vrreg/pipeline/model.hpp"

namespace vrreg {

/// What changed in the cell (what check_cell decided).
enum class CellChange {
  kBump,   ///< the sensor moved rigidly
  kDrift,  ///< the robot changed smoothly
};

/// "bump" or "drift".
const char* to_string(CellChange change);

/// Options of update_model.
struct UpdateOptions {
  CellChange change = CellChange::kBump;
  std::string parent{};  ///< the model's name for the lineage (its file)
  std::string time{};    ///< when the points were read, for the lineage (ISO 8601)
  /// Update even when nothing changed. Otherwise an update whose monitor rows, checked again
  /// (check_cell with `check`), show no change (valid, or only noisier today), or, without monitor
  /// rows to check, whose `last_verdict` was valid, is refused: it would fit the day's noise into
  /// the model.
  bool even_if_unchanged = false;
  /// The verdict of this model's last check (its history), when known.
  std::optional<MonitorVerdict> last_verdict{};
  CheckOptions check{};  ///< how today's monitor rows are checked again
};

/// The updated model and the fit that made it.
struct UpdateResult {
  RegistrationModel model{};
  std::vector<std::string> points{};  ///< the points used ("name" or "name@config")
  int n_monitors = 0;                 ///< of them, monitor points (their visits averaged)
  int n_fiducials = 0;                ///< of them, fiducials read again
  double fit_rms_m = 0.0;             ///< weighted RMS residual of the fit [m]
  /// Bump: today's sensor frame -> the registration's (the model's T_registered_sensor).
  RigidTransform T_registered_sensor{};
  /// Drift: the fitted change of a fiducial's reading, d(p) = A p + b for its commanded robot
  /// position p [m]: columns A then b (registration sensor frame).
  Eigen::Matrix<double, 3, 4> drift{Eigen::Matrix<double, 3, 4>::Zero()};
  /// Today's monitor rows checked again, when there were any and their sd could be estimated.
  std::optional<CheckResult> today_check{};
};

/// Updates `model` from `today`: its monitor rows (paired with the model's by (point, config)) and
/// fiducial rows (paired with the model's fiducials). Bump: the rigid motion of the sensor that
/// best maps today's readings onto the registration's (Eq. 2, weighted by each pair's visits;
/// 3 or more points, not collinear); the model's fiducials, corrections and corrector are kept.
/// Drift: an affine change in the robot position fitted to the same pairs (4 or more points, not
/// coplanar), added to every fiducial's and monitor's reading, then registered again (Eq. 2, 6)
/// and the corrector fitted again with the model's interpolation. Throws InputError naming
/// today's file on too few or degenerate points, an unknown point, (drift) a model built with a
/// Procedure 2 strategy or a marker offset, or no change found (UpdateOptions::even_if_unchanged).
UpdateResult update_model(const RegistrationModel& model, const MeasurementSet& today,
                          const UpdateOptions& options);

}  // namespace vrreg
