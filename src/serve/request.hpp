// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a client of the correction service asks and what it is answered, whatever the protocol
// (the line protocol for robot controllers, HTTP/JSON for cell software; docs/serve.md).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

namespace vrreg::serve {

/// How a request gives the marker's measured orientation, and its reply the corrected one.
enum class OrientationForm {
  kNone,            ///< a position only
  kRotationVector,  ///< rx, ry, rz [rad]: the axis times the angle (a URScript pose's rotation)
  kQuaternion,      ///< qx, qy, qz, qw
  kKukaAbc,         ///< A, B, C [deg], R = Rz(A) Ry(B) Rx(C) (a KRL FRAME's orientation)
};

/// How many numbers an orientation of `form` takes (0, 3 or 4).
int orientation_numbers(OrientationForm form);

/// One point to correct.
struct PointRequest {
  std::string model;                 ///< the served model's name
  Eigen::Vector3d sensor_mm = Eigen::Vector3d::Zero();  ///< measured point, sensor frame [mm]
  std::optional<int> config;         ///< arm configuration label (Procedure 2 models)
  std::vector<double> joints_rad;    ///< commanded joints (the joint-space model) [rad]
  /// The joints the robot comes from [rad] (`from`), one per commanded joint, or empty.
  std::vector<double> from_rad;
  /// Per commanded joint, the sign (-1, 0, +1) of its last move before the point (`approach`,
  /// or sign(joints - from) when `from` is given); empty when the request gives no direction.
  std::vector<double> approach_sign;
  bool extrapolate = false;          ///< correct outside the support too (status "extrapolated")
  /// The marker's measured orientation, sensor frame (a rigid-body marker; docs/orientation.md),
  /// and the form it was given in, which the reply takes.
  std::optional<Eigen::Quaterniond> q_sensor_marker;
  OrientationForm orientation_form = OrientationForm::kNone;
};

/// Per joint, the sign of the move from `from_rad` to `joints_rad` (update_approach_sign from
/// unknown: 0 where the joint does not move). Both of the same size.
std::vector<double> approach_sign_of_move(const std::vector<double>& from_rad,
                                          const std::vector<double>& joints_rad);

/// Reply codes: 0 is an answer; every other code is a refusal the client must handle. On the line
/// protocol the code is sent as a negative sd, so a robot program tests `sd < 0`.
enum class ReplyCode : int {
  kOk = 0,
  kMalformed = 1,       ///< the request could not be read
  kUnknownModel = 2,    ///< no model of that name is served
  kNotCorrectable = 3,  ///< outside the method's support (or grid, hull): no correction
  kInput = 4,           ///< the model needs what the request lacks (joints, configuration)
  kUnauthorized = 5,    ///< a token is required and was not given or is wrong
  kLimit = 6,           ///< a bound was hit (line or body length, batch size, connections)
  kInternal = 7,        ///< the service failed: a bug, reported, never a silent default
  kTooFar = 8,          ///< extrapolation asked farther from the fiducials than the service allows
};

/// The name of a code for logs and JSON ("ok", "malformed", ...).
const char* to_string(ReplyCode code);

/// The answer to one point.
struct PointAnswer {
  ReplyCode code = ReplyCode::kOk;
  std::string status;  ///< the corrector's status ("ok", "extrapolated", "outside support", ...)
  std::string reason;  ///< why, when code != kOk
  Eigen::Vector3d robot_mm = Eigen::Vector3d::Zero();  ///< what to command, robot frame [mm]
  Eigen::Vector3d uncorrected_robot_mm = Eigen::Vector3d::Zero();  ///< R X + tau [mm]
  /// Predicted sd of the corrected point's 3D error [mm]; 0 when the method predicts none (the
  /// paper's stencils).
  double sd_mm = 0.0;
  /// When the request gave an orientation: the orientation to command, robot frame, the
  /// uncorrected R R_sensor_marker, the rotation applied (log, robot frame) [rad], and the
  /// predicted sd of the corrected orientation's angle error [rad] (0 when the method predicts
  /// none).
  std::optional<Eigen::Quaterniond> q_robot_marker;
  std::optional<Eigen::Quaterniond> uncorrected_q_robot_marker;
  Eigen::Vector3d rotation_applied_rad = Eigen::Vector3d::Zero();
  double angle_sd_rad = 0.0;

  static PointAnswer refusal(ReplyCode code, std::string reason);
};

}  // namespace vrreg::serve
