// SPDX-License-Identifier: Apache-2.0
#pragma once
// Lost motion (gear backlash and transmission compliance) as a corrector term: each joint j stops
// short of its command by beta_j / 2 against the direction s_j (-1, 0, +1) of its last move, so
// the reached position deviates from the commanded one by -J_pos(q) diag(s) beta / 2 (first
// order; J_pos the position rows of the geometric Jacobian at the commanded joints).
#include <Eigen/Core>
#include <string>

#include "vrreg/correction/interpolation.hpp"

namespace vrreg {

/// Whether a corrector fits the lost-motion term (CorrectorOptions::lost_motion).
enum class LostMotionMode {
  kAuto,  ///< fitted when the data allow it; enters when cross-validation finds it clearly better
  kOff,   ///< never fitted
  kOn,    ///< fitted and applied; InputError when the data cannot carry it
};

/// Lower-case name (auto, off, on) as on the command line.
const char* to_string(LostMotionMode mode);
/// Parses auto, off or on; throws InputError otherwise.
LostMotionMode parse_lost_motion_mode(const std::string& text);

/// A fitted lost-motion term: one play per commanded joint, with its covariance, and how it was
/// judged (cross-validation decides whether it enters the correction).
struct LostMotionTerm {
  Eigen::VectorXd play_rad{};          ///< beta_j per commanded joint: the play taken up [rad]
  Eigen::MatrixXd covariance_rad2{};   ///< of play_rad [rad^2]
  /// Whether the term enters the correction (its cross-validated error beat the method alone).
  bool applied = false;
  double cv_rms_with_m = 0.0;     ///< cross-validated RMS (3D) of the method with the term [m]
  double cv_rms_without_m = 0.0;  ///< of the method alone, on the same held-out fiducials [m]
  std::string reason{};           ///< why it is or is not applied, one line
  /// The method the cross-validation compared with and without the term.
  InterpolationMethod judged_by = InterpolationMethod::kTrilinear;
  Eigen::Index n_compared = 0;  ///< held-out fiducials both predicted (0: not cross-validated)
};

}  // namespace vrreg
