// SPDX-License-Identifier: Apache-2.0
#pragma once
// How well the monitor check (pipeline/check.hpp) and the update from a few points
// (pipeline/update.hpp) keep simulated UR5 A1 cells calibrated: per seed, a cell is registered
// with its monitor points, then checked unchanged, after a bump of the tracker and after a
// warm-up drift of the robot; after the bump it is re-registered from the monitors and a few
// fiducials, after the drift updated from the fiducials the check names; RMS_T (Eq. 4) of the
// cell's targets before, with the stale model and after the update.
#include <cstdint>
#include <string>
#include <vector>

#include "vrreg/metrics/monitor_check.hpp"

namespace vrreg::experiments {

/// Options of drift_study.
struct DriftStudyOptions {
  int seeds = 200;  ///< cells: seeds first_seed .. first_seed + seeds - 1
  std::uint64_t first_seed = 1;
  int monitors = 3;           ///< monitor points (spread over the fiducials)
  int visits = 12;            ///< visits of each monitor point, at registration and per check
  double bump_rms_m = 1e-4;   ///< the bump's RMS displacement over the cell's targets [m]
  double drift_rms_m = 2e-4;  ///< the warm-up's RMS displacement of the TCP over the targets [m]
  int update_points = 10;     ///< points read for an update, monitors included
  double false_alarm_rate = 0.01;
  /// Throws InputError on fewer than 1 seed, monitors < 3, visits < 1, sizes < 0, too few points.
  void validate() const;
};

/// What is done to a registered cell before it is checked.
enum class DriftScenario { kUnchanged, kBump, kDrift };

/// One cell under one scenario.
struct DriftStudyCell {
  std::uint64_t seed = 0;
  DriftScenario scenario = DriftScenario::kUnchanged;
  MonitorVerdict verdict = MonitorVerdict::kValid;
  double change_rms_m = 0.0;     ///< RMS difference at the monitor points (3D)
  double cor_rms_t_m = 0.0;      ///< corrected RMS_T right after registration
  double stale_rms_t_m = 0.0;    ///< corrected RMS_T with the registered model, after the change
  double updated_rms_t_m = 0.0;  ///< corrected RMS_T with the updated model (bump, drift)
  double update_fit_rms_m = 0.0;
};

/// All cells, scenario-major.
struct DriftStudy {
  DriftStudyOptions options{};
  std::vector<DriftStudyCell> cells{};
};

/// Runs the study (seeds in parallel; the same options give the same numbers).
DriftStudy drift_study(const DriftStudyOptions& options);

/// The table `vrreg drift-study` prints: per scenario the verdicts, the detection rate and RMS_T
/// before, stale and updated (mean, worst ratio updated / before).
std::string drift_study_text(const DriftStudy& study);

const char* to_string(DriftScenario scenario);

}  // namespace vrreg::experiments
