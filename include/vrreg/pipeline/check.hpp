// SPDX-License-Identifier: Apache-2.0
#pragma once
// Does a registration still hold? The model's monitor points, read again today, are compared with
// their readings at registration (metrics/monitor_check.hpp): unchanged, the sensor moved rigidly
// (a bump: re-register from a few points, pipeline/update.hpp), one monitor point moved, the
// robot changed smoothly (drift: which fiducials to read again), or today's readings scatter more
// than the registration's (noisier today: no change found, check again). With the checks since
// the registration (the cell's history), a change that came at once is a bump and one that grew
// over them a drift.
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/metrics/monitor_check.hpp"
#include "vrreg/pipeline/model.hpp"

namespace vrreg {

/// One monitor point: its visits then and today and how far it moved.
struct MonitorPointCheck {
  std::string point{};
  std::optional<int> config{};
  int baseline_visits = 0;
  int today_visits = 0;
  Eigen::Vector3d difference_m = Eigen::Vector3d::Zero();  ///< today - then, registration frame
  double difference_sd_m = 0.0;                            ///< per axis [m]
  double today_mean_sd_m = 0.0;  ///< sd of today's mean per axis [m] (today's visits)
};

/// A check made before today, of the same model (its history): point, config, difference_m and
/// today_mean_sd_m of each point it read are used.
struct EarlierCheck {
  std::string time{};   ///< when, as recorded (for the message)
  double time_s = 0.0;  ///< the same in seconds, on the clock of CheckOptions::time_s
  std::vector<MonitorPointCheck> points{};
  bool changed = false;  ///< it found a change (a verdict other than valid or noisier today)
};

/// Options of check_cell.
struct CheckOptions {
  double false_alarm_rate = 0.01;  ///< P(not valid) on an unchanged cell
  /// The sd of one visit's mean reading per axis [m] (robot repeatability and tracker noise), when
  /// known; empty: estimated from the scatter of the monitor points' visits, then and today apart.
  std::optional<double> visit_sd_m{};
  int remeasure = 10;  ///< how many fiducials to name for reading again (`remeasure` below)
  /// The checks of this model since its registration (classify_change_onset); those at or after
  /// `time_s` are left out.
  std::vector<EarlierCheck> earlier{};
  /// When today's points were read [s, the earlier checks' clock]; needed with `earlier`.
  std::optional<double> time_s{};
  /// Throws InputError on a rate outside (0, 0.5), a sd <= 0, a count < 4, or earlier checks
  /// without today's time.
  void validate() const;
};

/// The check's outcome.
struct CheckResult {
  MonitorCheck statistics{};                ///< verdict, test statistics, the rigid change
  std::vector<MonitorPointCheck> points{};  ///< the monitor points read today, in model order
  double false_alarm_rate = 0.0;            ///< as asked
  double visit_sd_m = 0.0;        ///< the registration's sd of one visit used [m] (or given)
  double today_visit_sd_m = 0.0;  ///< today's, as the test used it [m]
  /// Degrees of freedom of the difference variance the test used (Welch-Satterthwaite when then
  /// and today were estimated apart; 0: known).
  double variance_dof = 0.0;
  /// Today's scatter against the registration's (tested when today has several visits): when
  /// today is significantly noisier and nothing changed, the verdict is kNoisier.
  VisitNoiseComparison noise{};
  /// How a change came, from options.earlier (kUnknown when valid or without earlier checks).
  ChangeOnsetTest onset{};
  /// The earlier checks' times the onset test used, oldest first.
  std::vector<std::string> onset_times{};
  int model_monitors = 0;  ///< monitor points the model has
  /// Fiducials to read again, spread over the volume (planning/spread_points.hpp), as "name" or
  /// "name@config": after a smooth change, for update_model (CellChange::kDrift); after a rigid
  /// change seen from fewer than 3 monitor points (or points on a line), to read with them for
  /// CellChange::kBump.
  std::vector<std::string> remeasure{};
  std::string source{};    ///< today's file
  std::string model_id{};  ///< monitor_baseline_id(model)
};

/// Compares the monitor rows of `today` (role monitor; any visits) with the model's. The false-
/// alarm rate is shared by the change test and, when today has several visits, the test that
/// today is noisier (Sidak). Throws InputError (about the model: its caller names the model's
/// file) when the model has no monitor points, and FileError naming `today.source` (and the line)
/// when today's file has none or one unknown to the model, or the visits' sd cannot be estimated.
CheckResult check_cell(const RegistrationModel& model, const MeasurementSet& today,
                       const CheckOptions& options = {});

/// A location's name in lists: "name", or "name@config" when it has a configuration label.
std::string location_key(const Location& location);

/// What a check history records to tell this model's checks from others': 16 hex digits of a hash
/// of its monitor points' readings, their sensor move (T_registered_sensor) and lineage length.
/// Changes with every update_model.
std::string monitor_baseline_id(const RegistrationModel& model);

}  // namespace vrreg
