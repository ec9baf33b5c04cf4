// SPDX-License-Identifier: Apache-2.0
#pragma once
// The front door, step 1: register fiducials (Eq. 2), check the rigid-body condition (Eq. 1) and
// the noise (Eq. 9), and compute the RRBC corrections (Eq. 6) into a model — in one call, with
// Procedure 2's strategies (section 4.4) and the robust variant as options.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/correction/interpolation.hpp"
#include "vrreg/correction/lost_motion_term.hpp"
#include "vrreg/correction/outliers.hpp"
#include "vrreg/metrics/noise.hpp"
#include "vrreg/metrics/rigid_body.hpp"
#include "vrreg/metrics/rigid_body_sampled.hpp"
#include "vrreg/pipeline/field_model.hpp"
#include "vrreg/pipeline/model.hpp"
#include "vrreg/pipeline/points.hpp"
#include "vrreg/planning/procedure2.hpp"
#include "vrreg/planning/strategy2_labels.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg {

/// Options of register_fiducials; the defaults are the paper's (no scale, no strategy).
struct RegisterOptions {
  std::optional<int> config{};  ///< register only the fiducials with this configuration label
  RegistrationOptions
      registration{};  ///< e.g. estimate_scale: a similarity instead (not the paper)
  /// Find fiducials whose correction disagrees with their neighbours' (a displaced or swapped
  /// marker; correction/outliers.hpp), register without them and fill their corrections from the
  /// neighbours. The noise scale is sigma_noise (Eq. 9) of these fiducials and sigma_rep_m.
  std::optional<OutlierOptions> robust{};
  std::optional<double> sigma_rep_m{};  ///< robot repeatability for sigma_noise and rho (Eq. 9) [m]
  bool rigid_body_statistics = true;  ///< sigma_L over all pairs (Eq. 1); off: sigma_L = 0
  /// Above sigma_l.exact_max_points fiducials sigma_L is sampled (result and model say so).
  SigmaLOptions sigma_l{};
  InterpolationSettings interpolation{};  ///< stored in the model: evaluate's and correct's default
  /// Procedure 2: strategy 1 and 2 need `config`; 3 registers the volume corners (needs joints and
  /// configuration labels; octuplet interpolation with a cube edge) with procedure2.seed (1).
  planning::Procedure2 procedure2{};
  /// The arm the fiducials' joints belong to, up to the marker: stored in the model for the
  /// joint-space field model (interpolation joint or auto).
  std::optional<kinematics::SerialChain> robot{};
  /// The lost-motion term of the fitted corrector (CorrectorOptions::lost_motion): needs joints,
  /// `robot` and the fiducials' approach directions; on needs a fitted corrector (not linear).
  LostMotionMode lost_motion = LostMotionMode::kAuto;
  /// Throws InputError on combinations that cannot work (see the members).
  void validate() const;
};

/// A fiducial the robust check rejected, by name.
struct RejectedFiducial {
  std::string point{};
  std::optional<int> config{};
  double deviation_m = 0.0;  ///< |eps_j - its neighbours' prediction| (Eq. 6 correction) [m]
  double sigmas = 0.0;       ///< the same in standard deviations of that difference
  /// true: kept in the model with the correction its neighbours predict (a grid stays complete);
  /// false: too few neighbours, dropped (grid interpolation may then fall back to scattered).
  bool filled = false;
};

/// What the robust check found (RegisterOptions::robust).
struct RobustReport {
  OutlierDetection detection{};  ///< scale, bound, fiducials judged (columns: the fiducial rows)
  std::vector<RejectedFiducial> rejected{};  ///< in file order
  double false_alarm_rate = 0.0;             ///< the rate the bound was set for (OutlierOptions)
};

/// What register_fiducials found, besides the model.
struct RegisterResult {
  RegistrationModel model{};
  RegistrationResult registration{};  ///< the fit (Eq. 2): FRE, residuals, spread, of `registered`
  std::size_t n_registered = 0;     ///< fiducials in the fit (8 for Strategy 3)
  RigidBodyStatistics rigid_body{};      ///< L_ij over the registered fiducials (Eq. 1)
  SigmaLSampling sigma_l_sampling{};     ///< exact (all pairs) or sampled, with its interval
  NoiseFigures noise{};                  ///< sigma_opt, sigma_noise, rho (Eq. 9)
  std::vector<std::string> rejected{};   ///< robust: names of the rejected fiducials
  std::optional<RobustReport> robust{};  ///< robust: the outliers, their deviations, the scale
  std::optional<planning::Strategy2Summary> relabelled{};  ///< Strategy 2: what was relabelled
  /// interpolation auto: the cross-validation table; the model stores the method it chose.
  std::optional<CrossValidation> cross_validation{};
};

/// Builds a model from the fiducial rows of a measurement set (Role::kFiducial; errors name
/// `fiducials.source`). Strategy 2 relabels along the set's visiting path (fiducials and targets).
RegisterResult register_fiducials(const MeasurementSet& fiducials,
                                  const RegisterOptions& options = {});

/// Builds a model from fiducials given as arrays [m] (every location is a fiducial; the visiting
/// path is their order). Throws InputError on mismatched sizes, non-finite values, fewer than 3
/// fiducials, collinear or coincident ones.
RegisterResult register_fiducials(const MeasuredPoints& fiducials,
                                  const RegisterOptions& options = {});

/// The same from the two point sets alone, as Eigen::umeyama(src, dst) takes them: column j of
/// `sensor_m` [m] was measured where the robot was commanded to column j of `robot_m` [m].
RegisterResult register_fiducials(const ConstPoints3Ref& sensor_m, const ConstPoints3Ref& robot_m,
                                  const RegisterOptions& options = {});

}  // namespace vrreg
