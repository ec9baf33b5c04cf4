// SPDX-License-Identifier: Apache-2.0
#pragma once
// Does a registration still hold? A few monitor points, read when the cell was registered and
// read again today (sensor frame), are compared: a statistical test at a stated false-alarm rate
// says whether the cell is unchanged, the tracker moved rigidly (a bump: its 6-DOF change and
// uncertainty), one monitor point disagrees (an outlier), or the change is not rigid (the robot
// drifted, e.g. warming up). Beside it: whether today's readings scatter more than the
// registration's (compare_visit_noise), and whether a change came at once or grew over the
// checks before today (classify_change_onset).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// What a check decides.
enum class MonitorVerdict {
  kValid,         ///< no change beyond the noise
  kRigidChange,   ///< the differences are a rigid motion of the sensor (a bump)
  kOutlier,       ///< one monitor point disagrees, the others are unchanged
  kSmoothChange,  ///< a change that is not rigid: the robot (drift, warm-up)
  kNoisier,       ///< no change found, but today's readings scatter more than the registration's
};

/// Lower-case name ("valid", "rigid change", "outlier", "smooth change", "noisier today").
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
/// The translation is stated twice, each with the covariance of the same point: at the sensor
/// frame's origin (what T_registered_sensor holds; 2 m from the cell, the rotation's uncertainty
/// times that lever arm dominates it) and at the monitor points' centroid (where it is best known).
struct RigidChange {
  Eigen::Vector3d rotation_rad = Eigen::Vector3d::Zero();   ///< omega, sensor frame
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();  ///< the move of the sensor's origin
  /// Covariance of (omega [rad], translation_m [m]) [rad^2, rad m, m^2].
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Vector3d centroid_m = Eigen::Vector3d::Zero();  ///< the points' sd-weighted centroid
  Eigen::Vector3d translation_at_centroid_m = Eigen::Vector3d::Zero();  ///< the centroid's move
  /// Covariance of (omega, translation_at_centroid_m).
  Eigen::Matrix<double, 6, 6> covariance_at_centroid = Eigen::Matrix<double, 6, 6>::Zero();
  /// Rotation axes the points see: 3; 2 when they lie on a line (the turn about it is not seen
  /// and set to 0); 0 from one point (a translation only). Below 3 the origin's translation and
  /// covariance assume no unseen turn: only the centroid's are measured.
  int rotation_rank = 3;
  double displacement_rms_m = 0.0;  ///< RMS over the monitor points of the fitted motion
};

/// The outcome, with the statistics that decided it.
struct MonitorCheck {
  MonitorVerdict verdict = MonitorVerdict::kValid;
  double chi2 = 0.0;                      ///< sum of squared standardised differences
  int dof = 0;                            ///< 3 N
  double threshold = 0.0;                 ///< its bound, when it is the only test (one point)
  double rigid_chi2 = 0.0;                ///< the part a rigid motion explains (rigid_dof)
  int rigid_dof = 0;                      ///< 6; 5 for points on a line
  double rigid_threshold = 0.0;           ///< its bound (0: one test of the sum)
  double residual_threshold = 0.0;        ///< the bound of what the rigid motion leaves
  int residual_dof = 0;                   ///< 3 N - rigid_dof
  double change_rms_m = 0.0;              ///< RMS of the differences (3D)
  std::optional<RigidChange> rigid{};     ///< fitted when the cell changed
  double rigid_residual_chi2 = 0.0;       ///< what the rigid motion leaves (residual_dof)
  std::optional<Eigen::Index> outlier{};  ///< kOutlier: which point
  std::string message{};                  ///< the decision in words
  /// What these points cannot tell, from their number and layout (one sentence each): one point
  /// cannot tell a bump from a drift or from the point itself moving; points on a line miss a
  /// turn about it; points on a plane miss a change that grows along its normal from zero on it.
  std::vector<std::string> blind_spots{};
};

/// Compares `today_sensor_m` with `baseline_sensor_m` (3 x N, the same monitor points in the same
/// order, sensor frame [m]); `difference_sd_m` (N): the standard deviation of each point's
/// difference per axis [m] (readings' noise of both times and the robot's repeatability).
/// The squared standardised differences split into the part a rigid motion explains (6 dof; 5 for
/// points on a line, a turn about it unseen; 3 for one point, a translation) and the rest (3 N
/// minus that), two independent tests at a rate split so that an unchanged cell alarms at the
/// stated rate (split_rate): only the first alarms -> a rigid change; the rest alarms -> one moved
/// point when the others are unchanged (Sidak), else a smooth change. One point: one test of the
/// sum, a change of it called rigid (a translation is all one point can show).
/// Throws InputError on mismatched sizes, non-finite values or a sd <= 0.
MonitorCheck check_monitors(const ConstPoints3Ref& baseline_sensor_m,
                            const ConstPoints3Ref& today_sensor_m,
                            const Eigen::Ref<const Eigen::VectorXd>& difference_sd_m,
                            const MonitorCheckOptions& options = {});

/// What a set of monitor points (sensor frame [m]) cannot tell, one sentence each
/// (MonitorCheck::blind_spots).
std::vector<std::string> monitor_blind_spots(const ConstPoints3Ref& points_m);

/// Today's scatter of a visit against the registration's: a one-sided test that today is noisier.
struct VisitNoiseComparison {
  double variance_then_m2 = 0.0;   ///< one visit's variance per axis at registration [m^2]
  double dof_then = 0.0;           ///< its degrees of freedom (0: known, given)
  double variance_today_m2 = 0.0;  ///< today's [m^2]
  double dof_today = 0.0;          ///< its degrees of freedom (0: today's scatter not measured)
  double ratio = 1.0;              ///< variance today / then
  double p_value = 1.0;            ///< P(a ratio this large | the same noise both times)
  bool tested = false;             ///< both were known or estimated (dof_today > 0)
  bool noisier = false;            ///< p_value < the rate asked
};

/// F test of variance_today / variance_then with (dof_today, dof_then) degrees of freedom, or a
/// chi-square test of dof_today * ratio when the registration's variance is known (dof_then 0),
/// at false-alarm rate `rate`. Not tested (noisier false) when dof_today is 0.
/// Throws InputError on a variance <= 0 or non-finite, a negative dof or a rate outside (0, 1).
VisitNoiseComparison compare_visit_noise(double variance_then_m2, double dof_then,
                                         double variance_today_m2, double dof_today, double rate);

/// One check's readings of the monitor points against the registration's: its mean minus the
/// registration's mean per point (3 x N, sensor frame [m]), the sd of that check's mean per
/// axis (N [m]; 0 for a point that check did not read), and when it was made [s, any origin].
struct MonitorReadings {
  Points3 difference_m{};
  Eigen::VectorXd mean_sd_m{};
  double time_s = 0.0;
  bool changed = false;  ///< that check found a change (its verdict was not valid)
};

/// How a change came, from the checks since the registration.
enum class ChangeOnset {
  kUnknown,  ///< no earlier check to tell from
  kStep,     ///< the earlier checks were at the registration's values or at today's: at once
  kRamp,     ///< the earlier checks were part of the way: it grew over them
};

/// "unknown", "step", "ramp".
const char* to_string(ChangeOnset onset);

/// The onset test and its numbers.
struct ChangeOnsetTest {
  ChangeOnset onset = ChangeOnset::kUnknown;
  int earlier_checks = 0;  ///< used (the most recent, up to kMaxEarlierChecks)
  double step_chi2 = 0.0;  ///< weighted squares the best step leaves
  double ramp_chi2 = 0.0;  ///< those the best linear ramp leaves
  double statistic = 0.0;  ///< step_chi2 - ramp_chi2 (likelihood ratio, 1 parameter more)
  double bound = 0.0;      ///< its bound: chi2_1 at the rate asked
  /// Step: the change came after the earlier check of this index (0 the oldest used; -1: before
  /// all of them, they all show it already).
  int step_after = -1;
  /// Each earlier check's fraction of today's change, fitted free (for the message).
  std::vector<double> fractions{};
  std::string message{};
};

/// The most recent earlier checks classify_change_onset looks at: a long unchanged history adds
/// degrees of freedom and no information about today's change.
inline constexpr int kMaxEarlierChecks = 20;

/// A change found today: did it come at once (a step: a bump) or grow over the earlier checks (a
/// ramp: a drift)? Each check's mean m_c = mu + phi_c Delta + noise (sd per point as given; phi
/// 0 at the registration, 1 today). A step: the checks before it showed no change (phi 0) and
/// it is whole from the check that first found it on (phi 1; that check `changed`, or today).
/// Against it a linear ramp in time, phi = clamp((t - t_start) / (t_end - t_start), 0, 1), t_end
/// up to today, which a warm-up follows: its likelihood ratio over the best step above chi2_1's
/// bound at `rate` calls it a ramp (Monte Carlo: a step is called a ramp at the rate when it
/// came since the last check, at up to twice it when the earlier checks already show it).
/// `baseline_mean_sd_m` (N): the sd of the registration's mean per axis;
/// `earlier` oldest first, before today's time. Throws InputError on mismatched sizes, non-finite
/// values, earlier checks out of time order or not before today, or a rate outside (0, 1).
ChangeOnsetTest classify_change_onset(const Eigen::Ref<const Eigen::VectorXd>& baseline_mean_sd_m,
                                      const std::vector<MonitorReadings>& earlier,
                                      const MonitorReadings& today, double rate);

}  // namespace vrreg
