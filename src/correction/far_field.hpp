// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to correction: what a corrector answers beyond its fiducials' support when asked to
// extrapolate (CorrectionQuery::extrapolate), the same rule for every method.
//
// Inside the support the fiducials say what the correction field is; outside, nothing measured
// says whether its affine trend goes on (a tracker's scale error, a link length: the error keeps
// growing with the distance) or stops (a warp, a wave: the error stays of the size it has
// inside, but the registration's rotation, which absorbed part of the field's gradient, keeps
// turning the mapping). Both are common and the data inside cannot tell them apart, so the answer
// is their even mixture: the correction at the support's nearest point (the anchor) plus half
// the trend's change from there, with the mixture's spread as its sd. The rule and its
// calibration on the simulated far-field cells are in docs/uncertainty.md ("Extrapolation").
#include <Eigen/Core>
#include <memory>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/corrector_data.hpp"

namespace vrreg::detail {

class PointIndex;

/// The fiducials' field as extrapolation needs it; built once per corrector from its data.
class FarField {
 public:
  explicit FarField(const CorrectorData& data);
  ~FarField();
  FarField(FarField&&) noexcept;
  FarField& operator=(FarField&&) noexcept;

  /// Half the affine trend's change of the correction from `anchor_m` to `at_m` (registered
  /// positions, robot frame [m]), sensor frame [m]: what the answer adds to the anchor's.
  [[nodiscard]] Eigen::Vector3d trend_step_sensor_m(const Eigen::Vector3d& at_m,
                                                    const Eigen::Vector3d& anchor_m) const;

  /// The sd of the 3D error of that answer at `at_m` [m] (docs/uncertainty.md): the anchor's own
  /// sd `sd_anchor_m`; a quarter of the squared trend change and of its slope's variance (the
  /// even mixture); the absorbed rotation the corrections' curl shows, at the field's mean rate
  /// |G|_F / sqrt(3) per metre (kClampedJointsShare more when the point's joints were clamped
  /// into the fiducials' ranges); the change between neighbours over `moved_m`, at most the
  /// spread; and the registration's own growth from the anchor to the point (Fitzpatrick's TRE).
  [[nodiscard]] double extrapolated_sd_m(double sd_anchor_m, double moved_m,
                                         const Eigen::Vector3d& at_m,
                                         const Eigen::Vector3d& anchor_m,
                                         bool joints_clamped) const;

  /// The mean correction of the fiducials nearest `at_m` (nominal positions [m]) and the sd of
  /// that mean as the correction there: the anchor where the method does not answer at the
  /// support's edge (the paper's stencils) or where its joints were clamped, sensor frame [m].
  void nearest_mean(const Eigen::Vector3d& at_m, Eigen::Vector3d& correction_sensor_m,
                    double& sd_m) const;

  /// The fiducials' box (nominal positions [m]): the support of the methods that have no clamp
  /// of their own.
  [[nodiscard]] const Eigen::Vector3d& box_lo_m() const { return box_lo_m_; }
  [[nodiscard]] const Eigen::Vector3d& box_hi_m() const { return box_hi_m_; }

 private:
  Points3 fiducials_robot_m_;
  Points3 corrections_sensor_m_;
  std::unique_ptr<PointIndex> index_;
  Eigen::Vector3d box_lo_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d box_hi_m_ = Eigen::Vector3d::Zero();
  /// The affine trend: correction ~ a + G (y - centre), G sensor frame per robot-frame metre.
  Eigen::Matrix3d gradient_ = Eigen::Matrix3d::Zero();
  /// Covariance of one row of G per unit residual variance ((F'F)^-1's slope block) [1/m^2],
  /// and the fit's residual variance summed over the three components [m^2].
  Eigen::Matrix3d slope_covariance_per_m2_ = Eigen::Matrix3d::Zero();
  double residual_variance_m2_ = 0.0;
  /// The field's median |d correction| / |d position| between nearest neighbours, and its
  /// spread: sqrt(2) x the RMS (3D) of the corrections about their mean, the RMS difference of
  /// two values too far apart to be correlated [m].
  double neighbour_gradient_ = 0.0;
  double field_spread_m_ = 0.0;
  /// The fiducials' localisation error <FLE^2> [m^2], from the known noise, else half the
  /// median squared correction difference of nearest neighbours.
  double fle_sq_m2_ = 0.0;
  /// How much of an isotropic field's curl the corrections show, 0..1 (curl_share in the source).
  double curl_share_ = 1.0;
};

}  // namespace vrreg::detail
