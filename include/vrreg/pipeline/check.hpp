// SPDX-License-Identifier: Apache-2.0
#pragma once
// Does a registration still hold? The model's monitor points, read again today, are compared with
// their readings at registration (metrics/monitor_check.hpp): unchanged, the sensor moved rigidly
// (a bump: re-register from a few points, pipeline/update.hpp), one monitor point moved, or the
// robot changed smoothly (drift: which fiducials to read again).
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/metrics/monitor_check.hpp"
#include "vrreg/pipeline/model.hpp"

namespace vrreg {

/// Options of check_cell.
struct CheckOptions {
  double false_alarm_rate = 0.01;  ///< P(not valid) on an unchanged cell
  /// The sd of one visit's mean reading per axis [m] (robot repeatability and tracker noise), when
  /// known; empty: estimated from the scatter of the monitor points' visits, then and today.
  std::optional<double> visit_sd_m{};
  int remeasure = 10;  ///< after a smooth change: how many fiducials to name for reading again
  /// Throws InputError on a rate outside (0, 0.5), a sd <= 0 or a count < 4.
  void validate() const;
};

/// One monitor point: its visits then and today and how far it moved.
struct MonitorPointCheck {
  std::string point{};
  std::optional<int> config{};
  int baseline_visits = 0;
  int today_visits = 0;
  Eigen::Vector3d difference_m = Eigen::Vector3d::Zero();  ///< today - then, registration frame
  double difference_sd_m = 0.0;                            ///< per axis [m]
};

/// The check's outcome.
struct CheckResult {
  MonitorCheck statistics{};                ///< verdict, test statistics, the rigid change
  std::vector<MonitorPointCheck> points{};  ///< the monitor points read today, in model order
  double false_alarm_rate = 0.0;            ///< as asked
  double visit_sd_m = 0.0;                  ///< the sd of one visit used [m]
  double variance_dof = 0.0;  ///< its degrees of freedom when estimated (0: given as known)
  int model_monitors = 0;     ///< monitor points the model has
  /// Smooth change: fiducials to read again and give to update_model (CellChange::kDrift), spread
  /// over the volume (planning/spread_points.hpp); as "name" or "name@config".
  std::vector<std::string> remeasure{};
  std::string source{};  ///< today's file
};

/// Compares the monitor rows of `today` (role monitor; any visits) with the model's. Throws
/// InputError (naming `today.source` and the line) when the model has no monitor points, today's
/// file has none, one is unknown to the model, or the visits' sd cannot be estimated.
CheckResult check_cell(const RegistrationModel& model, const MeasurementSet& today,
                       const CheckOptions& options = {});

/// A location's name in lists: "name", or "name@config" when it has a configuration label.
std::string location_key(const Location& location);

}  // namespace vrreg
