// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to correction: the joint model's support inside each joint's range. A range is not
// all measured: an arm on a rail measured at three carriage positions has none in between, where
// a ripple of the carriage (shorter than twice their spacing) is as unknown as beyond the range.
// A joint has a wide gap where two of its fiducials' neighbouring values are further apart, in
// the marker's motion, than kWideGapSpacings layout spacings. What such a gap leaves is measured
// by holding out the fiducials at each interior value next to it (two at least) and predicting
// them from the rest: a point inside the gap gets that error added to its sd (in proportion to
// its distance from the nearer measured value, whole from one spacing on). Where nothing
// measures it (fewer than two interior values), a point more than a quarter spacing from a
// measured value is outside the support.
#include <Eigen/Core>
#include <vector>

#include "vrreg/correction/corrector_data.hpp"
#include "vrreg/kinematics/joint_vector.hpp"

namespace vrreg::detail {

class JointGaps {
 public:
  /// A joint gap error: the joint has no wide gap.
  static constexpr double kNoWideGap = -1.0;
  /// A joint gap error: the joint has a wide gap with no interior value to measure it by.
  static constexpr double kUnmeasured = -2.0;

  /// Judges no gap.
  JointGaps() = default;
  /// The gaps of the joints of `data` (its fiducials' commanded joints, the robot and the marker
  /// at `p_flange_marker_m` on its flange) with the errors `gap_error_m` (one per joint variable:
  /// the RMS error [m] a wide gap leaves, or kNoWideGap / kUnmeasured); empty: not measured yet
  /// (every joint with a wide gap kUnmeasured, see interior_values()).
  JointGaps(const CorrectorData& data, const Eigen::Vector3d& p_flange_marker_m,
            Eigen::VectorXd gap_error_m = {});

  /// The values of joint `joint` to hold out to measure its wide gaps (interior values next to
  /// one, at most a few); empty when it has none.
  [[nodiscard]] std::vector<double> interior_values(int joint) const;
  /// The columns of `q_rad` whose joint `joint` has the value `value` (within the tolerance
  /// values are merged by).
  [[nodiscard]] std::vector<Eigen::Index> at_value(const Eigen::MatrixXd& q_rad, int joint,
                                                   double value) const;
  /// Sets joint `joint`'s gap error [m] (or kUnmeasured).
  void set_error(int joint, double error_m);
  [[nodiscard]] const Eigen::VectorXd& gap_error_m() const { return gap_error_m_; }
  /// True when some joint has a wide gap.
  [[nodiscard]] bool judges() const;

  struct Answer {
    double sd_m = 0.0;  ///< what the point's gaps add to its sd [m]
    /// In a wide gap nothing measured, away from its ends: the marker's motion from the nearest
    /// measured value [m] (the largest over the joints); 0 otherwise.
    double unmeasured_m = 0.0;
  };
  /// The gaps' answer at commanded joints `q_rad`.
  [[nodiscard]] Answer at(const kinematics::JointRef& q_rad) const;

 private:
  /// Whether the gap between two neighbouring values of joint `joint` is wide.
  [[nodiscard]] bool wide(int joint, double width) const;

  std::vector<std::vector<double>> values_{};  ///< per joint, the distinct values, sorted
  Eigen::VectorXd lever_m_{};  ///< per joint, the marker's median motion per unit [m/rad; m/m]
  double spacing_m_ = 0.0;     ///< the fiducials' layout spacing [m]
  Eigen::VectorXd gap_error_m_{};
};

}  // namespace vrreg::detail
