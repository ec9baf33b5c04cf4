// SPDX-License-Identifier: Apache-2.0
#pragma once
// The front door, step 2: the true accuracy of a model on independent targets — TRE and RMS_T
// uncorrected and RRBC-corrected (Eq. 3, 4, 7, 8), gamma, N_bad, Delta TRE (section 5.1) —
// following the model's Procedure 2 strategy (section 4.4).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/correction/orientation_field.hpp"
#include "vrreg/kinematics/joint_distance.hpp"
#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/metrics/improvement.hpp"
#include "vrreg/metrics/multidirectional.hpp"
#include "vrreg/metrics/uncertainty_calibration.hpp"
#include "vrreg/pipeline/field_model.hpp"
#include "vrreg/pipeline/interpolation_choice.hpp"
#include "vrreg/pipeline/model.hpp"
#include "vrreg/pipeline/points.hpp"
#include "vrreg/planning/procedure2.hpp"
#include "vrreg/planning/strategy2_labels.hpp"

namespace vrreg {

/// Options of evaluate; unset members take the model's value.
struct EvaluateOptions {
  std::optional<int> config{};  ///< evaluate targets with this label only (default: the model's)
  InterpolationChoice interpolation{};  ///< over the model's stored interpolation
  /// The model's strategy (the default), or 1 on a model built without one (per configuration).
  std::optional<planning::Strategy> strategy{};
  /// Strategy 3: the joint distance for nearest configurations; Strategy 2: must be the model's.
  std::optional<kinematics::JointNorm> joint_norm{};
  /// The arm (to the marker) for the joint-space field model; default: the model's.
  std::optional<kinematics::SerialChain> robot{};
  /// Fit the corrector again even when the model's own answers (its fiducials unchanged: the
  /// same numbers unless the code that fits has changed). Off: the model's corrector is used
  /// whenever it was fitted for the interpolation asked.
  bool refit = false;
  /// Kriging and RBF: correct with the model itself rather than its table (within 1/20 of the noise,
  /// measured when fitted; CorrectorOptions::tabulate). Slower: kriging's sd costs O(J^2) a point.
  bool exact = false;
  /// Field models: correct points outside the fiducials' support too, status "extrapolated",
  /// with a widened sd (CorrectionQuery::extrapolate). Off: they are left uncorrected.
  bool extrapolate = false;
};

/// The targets' orientations (rigid-body markers, docs/orientation.md): each error is the angle
/// between the commanded orientation and the registered (un)corrected one [rad].
struct OrientationEvaluation {
  OrientationCorrection correction{};  ///< corrected and uncorrected orientations, robot frame
  Eigen::VectorXd unc_error_rad{};     ///< per target
  Eigen::VectorXd cor_error_rad{};     ///< per target; flagged targets keep the uncorrected one
  double unc_rms_rad = 0.0;  ///< RMS over the corrected targets (as the positions' summary)
  double cor_rms_rad = 0.0;  ///< RMS over the corrected targets
  UncertaintyCalibration calibration{};  ///< cor_error_rad against correction.predicted_sd_rad
};

/// The evaluated targets, in the order given.
struct EvaluateResult {
  planning::Strategy strategy = planning::Strategy::kNone;  ///< as used
  std::optional<int> config{};                              ///< the configuration evaluated, if one
  InterpolationSettings interpolation{};  ///< as used (the model's with the options applied)
  TargetCorrection correction{};          ///< stencils, corrected and uncorrected robot positions
  std::vector<std::string> names{};       ///< target labels; empty for arrays given without names
  std::vector<std::optional<int>> configs{};  ///< their configuration labels (Strategy 2: new ones)
  Points3 targets_robot_m{};                  ///< nominal robot positions [m]
  Eigen::VectorXd unc_tre_m{};                ///< TRE(T_X) per target (Eq. 3) [m]
  Eigen::VectorXd cor_tre_m{};  ///< TRE(T^_X) per target; flagged targets keep the uncorrected one
  /// RMS_T (Eq. 4) both ways, gamma, N_bad, Delta TRE over the targets that were corrected only
  /// (n_targets of them; bad_targets index all targets). The flagged ones are counted apart.
  ImprovementSummary summary{};
  /// RMS_T of the targets left uncorrected (correction.n_flagged of them) as registered (Eq. 2,
  /// 4) [m]; 0 when there are none.
  double flagged_rms_t_m = 0.0;
  /// The targets RRBC made worse: their names, or "#k" (k-th target, from 1) without names.
  std::vector<std::string> bad_targets{};
  std::optional<planning::Strategy2Summary> relabelled{};  ///< Strategy 2: the targets' relabelling
  /// Field models: the cross-validation table when `auto` chose the method.
  std::optional<CrossValidation> cross_validation{};
  /// Field models: cor TRE against correction.predicted_sd_m (n = 0 for the paper's stencils).
  UncertaintyCalibration calibration{};
  /// When the model's fiducials and the targets carry measured and commanded orientations.
  std::optional<OrientationEvaluation> orientation{};
  /// ISO 9283's multi-directional accuracy over the corrected targets (metrics/multidirectional.hpp),
  /// when some target point was visited from more than one approach direction.
  std::optional<MultidirectionalAccuracy> multidirectional{};

  /// Every target evaluated, corrected or not.
  [[nodiscard]] int n_targets() const { return static_cast<int>(unc_tre_m.size()); }
};

/// Evaluates `model` on the target rows of a measurement set (errors name `targets.source`).
EvaluateResult evaluate(const RegistrationModel& model, const MeasurementSet& targets,
                        const EvaluateOptions& options = {});

/// Evaluates `model` on targets given as arrays [m] (robot_m required).
EvaluateResult evaluate(const RegistrationModel& model, const MeasuredPoints& targets,
                        const EvaluateOptions& options = {});

}  // namespace vrreg
