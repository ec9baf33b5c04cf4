// SPDX-License-Identifier: Apache-2.0
#pragma once
// Does a registration still hold? A few monitor points, read when the cell was registered and
// read again today (sensor frame), are compared: a statistical test at a stated false-alarm rate
// says whether the cell is unchanged, the tracker moved rigidly (a bump: its 6-DOF change and
// uncertainty), one monitor point disagrees (an outlier), or the change is not rigid (the robot
// drifted, e.g. warming up).
#include <Eigen/Core>
#include <optional>
#include <string>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// What a check decides.
enum class MonitorVerdict {
  kValid,         ///< no change beyond the noise
  kRigidChange,   ///< the differences are a rigid motion of the sensor (a bump)
  kOutlier,       ///< one monitor point disagrees, the others are unchanged
  kSmoothChange,  ///< a change that is not rigid: the robot (drift, warm-up)
};

/// Lower-case name ("valid", "rigid change", "outlier", "smooth change").
const char* to_string(MonitorVerdict verdict);

/// Settings of check_monitors.
struct MonitorCheckOptions {
  /// P(verdict != kValid) on an unchanged cell; every later test shares the same rate.
  double false_alarm_rate = 0.01;
  /// Degrees of freedom of the variance estimate behind the difference sd (the visits' scatter):
  /// the tests then use the F distribution. 0: the sd is known (chi-square).
  double variance_dof = 0.0;
  /// Throws InputError when the rate is out of (0, 0.5) or the dof negative.
  void validate() const;
};

/// A small rigid motion of the sensor: today = baseline + omega x baseline + t (first order).
struct RigidChange {
  Eigen::Vector3d rotation_rad = Eigen::Vector3d::Zero();  ///< omega, sensor frame
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();  ///< (omega, t)
  double displacement_rms_m = 0.0;  ///< RMS over the monitor points of the fitted motion
};

/// The outcome, with the statistics that decided it.
struct MonitorCheck {
  MonitorVerdict verdict = MonitorVerdict::kValid;
  double chi2 = 0.0;                      ///< sum of squared standardised differences
  int dof = 0;                            ///< 3 N
  double threshold = 0.0;                 ///< its bound, the test when N < 3
  double rigid_chi2 = 0.0;                ///< the part a rigid motion explains (6 dof; N >= 3)
  double rigid_threshold = 0.0;           ///< its bound
  double residual_threshold = 0.0;        ///< the bound of what the rigid motion leaves (N >= 3)
  double change_rms_m = 0.0;              ///< RMS of the differences (3D)
  std::optional<RigidChange> rigid{};     ///< fitted when the cell changed and N >= 3
  double rigid_residual_chi2 = 0.0;       ///< what the rigid motion leaves (3 N - 6 dof)
  std::optional<Eigen::Index> outlier{};  ///< kOutlier: which point
  std::string message{};                  ///< the decision in words
};

/// Compares `today_sensor_m` with `baseline_sensor_m` (3 x N, the same monitor points in the same
/// order, sensor frame [m]); `difference_sd_m` (N): the standard deviation of each point's
/// difference per axis [m] (readings' noise of both times and the robot's repeatability).
/// With 3 or more points the squared standardised differences split into the part a rigid motion
/// explains (6 dof) and the rest (3 N - 6), two independent tests at a rate split so that an
/// unchanged cell alarms at the stated rate (split_rate): only the first alarms -> a rigid change;
/// the rest alarms -> one moved point when the others are unchanged (Sidak), else a smooth
/// change. Fewer points: one test of the sum (3 N dof).
/// Throws InputError on mismatched sizes, non-finite values or a sd <= 0.
MonitorCheck check_monitors(const ConstPoints3Ref& baseline_sensor_m,
                            const ConstPoints3Ref& today_sensor_m,
                            const Eigen::Ref<const Eigen::VectorXd>& difference_sd_m,
                            const MonitorCheckOptions& options = {});

}  // namespace vrreg
