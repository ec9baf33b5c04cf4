// SPDX-License-Identifier: Apache-2.0
#include "vrreg/metrics/errors.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg {

Eigen::VectorXd target_registration_errors(const SimilarityTransform& T_robot_sensor,
                                           const ConstPoints3Ref& targets_sensor_m,
                                           const ConstPoints3Ref& targets_robot_m) {
  VRREG_THROW_UNLESS(targets_sensor_m.cols() == targets_robot_m.cols(),
                     "TRE needs corresponding targets: " << targets_sensor_m.cols() << " vs "
                                                         << targets_robot_m.cols());
  Eigen::VectorXd tre(targets_sensor_m.cols());
  for (Eigen::Index n = 0; n < tre.size(); ++n) {
    tre[n] = (T_robot_sensor.apply(targets_sensor_m.col(n)) - targets_robot_m.col(n)).norm();
  }
  return tre;
}

Eigen::VectorXd point_errors(const ConstPoints3Ref& mapped_robot_m,
                             const ConstPoints3Ref& targets_robot_m) {
  VRREG_THROW_UNLESS(mapped_robot_m.cols() == targets_robot_m.cols(),
                     "point errors need corresponding points: " << mapped_robot_m.cols() << " vs "
                                                                << targets_robot_m.cols());
  return (mapped_robot_m - targets_robot_m).colwise().norm().transpose();
}

double root_mean_square(const Eigen::Ref<const Eigen::VectorXd>& errors) {
  if (errors.size() == 0) return 0.0;
  return std::sqrt(errors.squaredNorm() / static_cast<double>(errors.size()));
}

}  // namespace vrreg
