// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a correction method is fitted on (paper Eq. 6-8): the registration and, per fiducial, its
// nominal and registered robot positions, its correction, where it was read and its joints.
#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/correction_values.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg {

/// The fiducials of one registration as every correction method sees them, one column each.
struct CorrectorData {
  SimilarityTransform T_robot_sensor{};  ///< Y ~ R X + tau (Eq. 2)
  Points3 fiducials_robot_m{};           ///< nominal Y_j, robot frame [m]
  Points3 registered_robot_m{};          ///< R X_j + tau, robot frame [m]
  Points3 corrections_sensor_m{};        ///< epsilon_j (Eq. 6), sensor frame [m]
  /// Where each fiducial was read (its file line: the visiting order), or empty when unknown.
  std::vector<std::size_t> sequence{};
  Eigen::MatrixXd joints_rad{};  ///< joint angles, one column per fiducial, or 0 x 0 without
  /// Per fiducial and joint, the sign (-1, 0, +1) of the joint's last move before it was read
  /// (Location::approach_sign), same shape as joints_rad, or 0 x 0 when unknown.
  Eigen::MatrixXd approach_sign{};
  /// Arm configuration labels (Strategy 3 keeps every configuration), or empty.
  std::vector<std::optional<int>> configs{};
  std::optional<kinematics::SerialChain> robot{};  ///< the arm the joints belong to (to the marker)
  /// The measured noise of one fiducial's averaged reading per axis (Eq. 9) [m], when known.
  std::optional<double> noise_sd_m{};
  /// What corrections_sensor_m holds (the field is a length in every method's arithmetic).
  CorrectionValues values = CorrectionValues::kLengthM;

  /// Data of fiducials measured at `fiducials_sensor_m` and commanded to `fiducials_robot_m`
  /// [m], with their corrections (Eq. 6): the registered positions are T applied to the former.
  static CorrectorData of(const SimilarityTransform& T_robot_sensor,
                          const ConstPoints3Ref& fiducials_sensor_m,
                          const ConstPoints3Ref& fiducials_robot_m,
                          const ConstPoints3Ref& corrections_sensor_m);

  [[nodiscard]] Eigen::Index size() const { return fiducials_robot_m.cols(); }
  [[nodiscard]] bool has_joints() const { return joints_rad.size() > 0; }
  [[nodiscard]] bool has_approach() const { return approach_sign.size() > 0; }
  /// The fiducials whose columns are `keep`, in that order (a cross-validation fold).
  [[nodiscard]] CorrectorData subset(const std::vector<Eigen::Index>& keep) const;
  /// Throws InputError when the members disagree in size or hold non-finite values.
  void validate() const;
};

}  // namespace vrreg
