// SPDX-License-Identifier: Apache-2.0
#pragma once
// A registration model made ready to correct points one request at a time (a correction
// service, a cell program): validated and its corrector chosen, or fitted, once.
#include <memory>

#include "vrreg/pipeline/correct.hpp"

namespace vrreg {

/// An immutable model and corrector, shared between threads. correct(points) gives the numbers
/// vrreg::correct(model, points, options) gives, bit for bit, without choosing the corrector again.
class PreparedCorrector {
 public:
  /// Validates the model and fits or restores the corrector `options` ask for (throws InputError
  /// as correct() does when the method cannot be used on the model's fiducials).
  PreparedCorrector(std::shared_ptr<const RegistrationModel> model, CorrectOptions options);

  /// Paper Eq. 7, 8 then {R, tau} for points given as arrays [m] (see correct()); their
  /// orientations too when they carry them (throws InputError when the model cannot correct them).
  [[nodiscard]] CorrectResult correct(const MeasuredPoints& points) const;
  /// The same with `extrapolate` set for this call only (CorrectOptions::extrapolate).
  [[nodiscard]] CorrectResult correct(const MeasuredPoints& points, bool extrapolate) const;

  [[nodiscard]] const RegistrationModel& model() const { return *model_; }
  [[nodiscard]] const CorrectOptions& options() const { return options_; }
  /// The method that answers (never kAuto: auto's choice).
  [[nodiscard]] InterpolationMethod method() const;
  /// Joints a point must carry (the joint-space model), 0 when none are needed.
  [[nodiscard]] int joints_needed() const;
  /// Whether the method states a predicted sd per point (field models do, the paper's stencils not).
  [[nodiscard]] bool predicts_sd() const;
  /// Whether points' orientations (MeasuredPoints::q_sensor_marker) are corrected too: the model's
  /// fiducials carry measured and commanded orientations (docs/orientation.md).
  [[nodiscard]] bool corrects_orientation() const;
  /// Whether the orientation field states a predicted angle sd per point.
  [[nodiscard]] bool predicts_angle_sd() const;

 private:
  std::shared_ptr<const RegistrationModel> model_{};
  CorrectOptions options_{};
  /// Null when the points follow the set's way (Procedure 2 strategies, configuration labels,
  /// marker offsets): each call then chooses per point as correct() does.
  std::shared_ptr<const Corrector> corrector_{};
  /// The orientation field answering with corrector_ (null without fiducial orientations).
  std::shared_ptr<const OrientationCorrector> orientation_{};
  InterpolationMethod method_ = InterpolationMethod::kLinear;
  int joints_needed_ = 0;
  bool predicts_sd_ = false;
  bool corrects_orientation_ = false;
  bool predicts_angle_sd_ = false;
};

}  // namespace vrreg
