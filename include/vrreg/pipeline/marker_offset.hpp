// SPDX-License-Identifier: Apache-2.0
#pragma once
// The front door for cells whose marker offset is unknown (hand-eye registration,
// docs/hand-eye.md): estimate T_robot_sensor and the marker's position on the flange together from
// the fiducials' joints, then build the usual model (Eq. 1, 2, 6) on forward kinematics with the
// estimated offset, so that evaluate, correct and RRBC work unchanged on top.
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/pipeline/points.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"
#include "vrreg/registration/marker_offset.hpp"

namespace vrreg {

/// What register_with_marker_offset found.
struct MarkerOffsetRegisterResult {
  MarkerOffsetResult estimate{};  ///< the joint estimate: offset, its uncertainty, condition, FRE
  /// The model and figures of register_fiducials on the fiducials' FK positions with the estimated
  /// offset (model.marker_offset set); empty when the estimate is not ok (e.g. unobservable).
  std::optional<RegisterResult> registered{};
  /// Fiducials used for the offset only, not for RRBC: those whose flange orientation differs
  /// (by more than kRrbcOrientationToleranceRad) from the orientation most fiducials share. RRBC
  /// interpolates an error field measured at one orientation; the tilted poses would mix others in.
  std::vector<std::string> offset_only{};
  /// p's standard uncertainty from the robot's joint zero offsets (estimation's
  /// joint_offset_sigma_rad; 0 when not given) [m], and with the noise's (the model stores it).
  Eigen::Vector3d p_std_joint_offsets_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_std_total_m = Eigen::Vector3d::Zero();
  [[nodiscard]] bool ok() const { return estimate.ok() && registered.has_value(); }
};

/// Orientation tolerance for "the same orientation" when choosing RRBC's fiducials [rad] (0.5 deg).
inline constexpr double kRrbcOrientationToleranceRad = 0.5 * 3.14159265358979323846 / 180.0;

/// Estimates the marker offset and registers: every fiducial row (of options.config) needs joints
/// for `robot` (its tool is ignored: the offset is from the flange). Strategies 2 and 3 and
/// --robust are not available with it (InputError). Errors name `fiducials.source` and the line.
MarkerOffsetRegisterResult register_with_marker_offset(const MeasurementSet& fiducials,
                                                       const kinematics::SerialChain& robot,
                                                       const RegisterOptions& options = {},
                                                       const MarkerOffsetOptions& estimation = {});

/// The same with the offset known (`p_flange_marker_m`, flange frame [m]): robot positions from FK
/// with it, no estimate (estimate.p_std_m = 0; estimate carries the offset, transform and FRE).
MarkerOffsetRegisterResult register_with_known_marker_offset(
    const MeasurementSet& fiducials, const kinematics::SerialChain& robot,
    const Eigen::Vector3d& p_flange_marker_m, const RegisterOptions& options = {});

/// The same from arrays: fiducials.joints_rad is required (one column per fiducial).
MarkerOffsetRegisterResult register_with_marker_offset(const MeasuredPoints& fiducials,
                                                       const kinematics::SerialChain& robot,
                                                       const RegisterOptions& options = {},
                                                       const MarkerOffsetOptions& estimation = {});

/// `set` with the robot position of every location that has joints replaced by forward kinematics
/// with the model's marker offset (`set` itself when the model has none). With `require_joints`,
/// a location of `role` without joints is an error naming its line.
MeasurementSet with_marker_offset(const RegistrationModel& model, const MeasurementSet& set,
                                  Role role, bool require_joints);

}  // namespace vrreg
