// SPDX-License-Identifier: Apache-2.0
#pragma once
// A fitted corrector: a correction method (paper Eq. 7, or a model of the whole field beyond it)
// fitted once on a registration's fiducials, then asked for any number of points (Eq. 8 and the
// map {R, tau}) with a predicted uncertainty for the field models. Fit once, correct many: it is
// immutable, cheap to copy (copies share the fitted state) and safe to use from many threads at
// once; saved and restored, it corrects with the same bits.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/correct_targets.hpp"
#include "vrreg/correction/correction_method.hpp"
#include "vrreg/correction/correction_guard.hpp"
#include "vrreg/correction/corrector_data.hpp"
#include "vrreg/correction/cross_validation.hpp"
#include "vrreg/correction/interpolation.hpp"
#include "vrreg/correction/lost_motion_term.hpp"

namespace vrreg {

/// How a corrector is fitted.
struct CorrectorOptions {
  /// The method (kLinear: grid on a complete regular grid, else scattered; kAuto: the lowest
  /// cross-validated error), the octuplet cube edge and the match tolerance.
  InterpolationSettings interpolation{};
  /// Strategy 3 (paper section 4.4): octuplet corners in the configuration nearest the target's.
  std::optional<kinematics::JointNorm> nearest_configuration{};
  int cv_folds = 5;           ///< cross-validation of `auto` and of the field models' sd
  std::uint64_t cv_seed = 1;  ///< of the shuffle that deals fiducials to folds
  /// Kriging and RBF correct from a table of the fitted field (tricubic, its deviation from the
  /// exact model measured and stated in describe(): within a quarter of the fiducials' noise,
  /// or, for a rougher field, a third of the model's smallest sd with the RMS deviation added
  /// to every sd): microseconds a point where kriging's exact sd costs milliseconds. Off: the
  /// exact model.
  bool tabulate = true;
  /// Judge the fitted correction by its cross-validated error against no correction's and,
  /// when it is not better, answer every target uncorrected (correction_guard.hpp). Off: for a
  /// field fitted inside another corrector that judges itself (the orientations').
  bool guard = true;
  /// The lost-motion term (lost_motion_term.hpp, docs/joint-space-model.md "Lost motion"): a
  /// first stage fitted on the fiducials' corrections when they carry joints, the robot and
  /// approach directions with some joint approached from both sides; the method then fits what
  /// it leaves. auto: it enters when cross-validation finds it clearly better.
  LostMotionMode lost_motion = LostMotionMode::kAuto;
  /// Throws InputError on settings that cannot work (octuplet without a cube edge, folds < 2).
  void validate() const;
};

/// Where a corrector's predicted sd comes from (field models; none for the paper's stencils).
enum class SdSource {
  kNone,       ///< the paper's stencils
  kModel,      ///< the method's own (kriging's posterior sd and nugget)
  kLocalCv,    ///< RMS of the held-out errors of the target's 16 nearest fiducials
  kGlobalCv,   ///< the method's cross-validated RMS, the same for every target (joint model)
};

/// Points to correct, one column (entry) per point. A view: the arrays must outlive it.
struct CorrectionQuery {
  /// Points measured by the sensor [m]; nothing else is needed unless the method says so.
  explicit CorrectionQuery(const ConstPoints3Ref& sensor_m);
  CorrectionQuery(const ConstPoints3Ref& sensor_m, const ConstPoints3Ref& robot_nominal_m,
                  const Eigen::Ref<const Eigen::MatrixXd>& joints_rad,
                  std::span<const std::size_t> sequence = {});
  /// With the points' approach directions (`approach_sign`, n_joints x N, or 0 x 0).
  CorrectionQuery(const ConstPoints3Ref& sensor_m, const ConstPoints3Ref& robot_nominal_m,
                  const Eigen::Ref<const Eigen::MatrixXd>& joints_rad,
                  std::span<const std::size_t> sequence,
                  const Eigen::Ref<const Eigen::MatrixXd>& approach_sign);
  ConstPoints3Ref sensor_m;            ///< measured positions, sensor frame [m]
  ConstPoints3Ref robot_nominal_m;     ///< nominal robot positions [m] (octuplet, Strategy 3)
  Eigen::Ref<const Eigen::MatrixXd> joints_rad;  ///< commanded joints [rad] (joint, Strategy 3)
  std::span<const std::size_t> sequence{};  ///< where each point was read (file line), or empty
  /// Per point and commanded joint, the sign (-1, 0, +1) of the joint's last move before the
  /// robot reached the point (its approach direction, update_approach_sign), n_joints x N; 0 x 0
  /// when unknown, 0 entries where one joint's direction is unknown. A corrector with a
  /// lost-motion term (Corrector::lost_motion) uses it; without it, never silently one
  /// direction: the term's mean over both (none) with an sd that covers either.
  Eigen::Ref<const Eigen::MatrixXd> approach_sign;
  /// Correct points outside the method's support (grid, hull, box, joint ranges) too, status
  /// kExtrapolated, instead of leaving them uncorrected: every method alike, with the correction
  /// at the support's nearest point plus half the field's affine trend from there, and an sd
  /// that covers whether the trend goes on or stops (docs/uncertainty.md). Holes inside a layout
  /// (an octuplet's missing corner within the fiducials' box) and flat layouts stay flagged.
  bool extrapolate = false;
};

/// A corrector's saved form: everything restore() needs besides the fiducials it was fitted on.
struct SavedCorrector {
  InterpolationSettings requested{};  ///< as asked (e.g. kAuto or kLinear)
  std::optional<kinematics::JointNorm> nearest_configuration{};
  int cv_folds = 5;
  std::uint64_t cv_seed = 1;
  InterpolationMethod method = InterpolationMethod::kLinear;  ///< as fitted
  MethodState state{};                                        ///< the fitted method's own state
  std::optional<CrossValidation> cross_validation{};          ///< `auto`'s table
  SdSource sd_source = SdSource::kNone;
  double cv_rms_m = 0.0;  ///< the method's cross-validated RMS (kGlobalCv, kLocalCv) [m]
  /// Held-out squared error (3D) per fiducial [m^2], NaN where not predicted (kLocalCv).
  Eigen::VectorXd cv_squared_error_m2{};
  /// Whether the correction is applied, and the figures that decided it; none: not guarded
  /// (a model saved without the guard is applied).
  std::optional<CorrectionGuard> guard{};
  /// The lost-motion term, when it was fitted (applied or not); none for older models.
  std::optional<LostMotionTerm> lost_motion{};
};

/// A correction method fitted on one registration's fiducials (see the file comment).
class Corrector {
 public:
  /// Fits the method of `options` on `data` (auto: cross-validates every candidate first).
  /// Throws InputError when the method cannot be used on these fiducials, saying why.
  static Corrector fit(const CorrectorData& data, const CorrectorOptions& options);
  /// fit(), or nullopt with the reason in `why` when the method does not apply to these
  /// fiducials (too few, no grid, no joints); other failures still throw.
  static std::optional<Corrector> try_fit(const CorrectorData& data,
                                          const CorrectorOptions& options, std::string& why);
  /// The corrector `saved` describes, on the fiducials it was fitted on, without fitting.
  static Corrector restore(const SavedCorrector& saved, const CorrectorData& data);
  /// The exact model behind a tabulated corrector, restored on the same fiducials (no fit);
  /// the corrector itself when it is not tabulated.
  [[nodiscard]] Corrector exact(const CorrectorData& data) const;
  /// True when the corrector reads a table of its field model (CorrectorOptions::tabulate).
  [[nodiscard]] bool tabulated() const;
  [[nodiscard]] SavedCorrector save() const;

  /// Corrects every point of `query` (Eq. 7, 8, then {R, tau}); points without a prediction
  /// keep the uncorrected mapping, flagged by their stencil status. Throws InputError when the
  /// query lacks what the method needs or holds non-finite values.
  [[nodiscard]] TargetCorrection correct(const CorrectionQuery& query) const;

  /// The method fitted (never kLinear or kAuto).
  [[nodiscard]] InterpolationMethod method() const;
  /// The settings as asked, e.g. kAuto, with the cube edge and tolerance.
  [[nodiscard]] const InterpolationSettings& requested() const;
  /// What was fitted, e.g. "grid 9 x 9 x 7 nodes, 25 mm" (TargetCorrection::layout).
  [[nodiscard]] std::string describe() const;
  /// Strategy 3's joint norm when the corrector is its nearest-configuration octuplet.
  [[nodiscard]] const std::optional<kinematics::JointNorm>& nearest_configuration() const;
  [[nodiscard]] MethodNeeds needs() const;
  [[nodiscard]] SdSource sd_source() const;
  /// `auto`'s cross-validation table (when it chose the method).
  [[nodiscard]] const std::optional<CrossValidation>& cross_validation() const;
  /// The guard's figures (CorrectorOptions::guard), none when the corrector was not guarded.
  [[nodiscard]] const std::optional<CorrectionGuard>& guard() const;
  /// The lost-motion term fitted beside the method (lost_motion_term.hpp), applied or not;
  /// none when it could not be fitted (no joints, robot or approach directions) or was not asked.
  [[nodiscard]] const std::optional<LostMotionTerm>& lost_motion() const;
  /// False when the guard found the correction not better than none: every target is then
  /// answered uncorrected with StencilStatus::kNotBetterThanNone.
  [[nodiscard]] bool applied() const;
  /// The arm's orientation error at commanded joints (FittedMethod::rotation_error_rad): the
  /// joint-space model's, nullopt for every other method; `joint_angles_only`: the part its
  /// joint-angle errors give on the nominal arm (JointErrorModel::predict_joint_angle_rotation_rad).
  [[nodiscard]] std::optional<Eigen::Vector3d> rotation_error_rad(
      const Eigen::Ref<const Eigen::VectorXd>& joints_rad, bool joint_angles_only = false) const;
  /// The joint-space model's fitted joint-angle errors at commanded joints [rad]; nullopt for
  /// every other method.
  [[nodiscard]] std::optional<Eigen::VectorXd> joint_angle_errors_rad(
      const Eigen::Ref<const Eigen::VectorXd>& joints_rad) const;
  /// True when `other` is this corrector or a copy of it (one fit, shared).
  [[nodiscard]] bool shares_fit_with(const Corrector& other) const { return impl_ == other.impl_; }
  /// The registration the corrector maps with (Eq. 2).
  [[nodiscard]] const SimilarityTransform& T_robot_sensor() const;

 private:
  struct Impl;
  explicit Corrector(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_{};
};

}  // namespace vrreg
