// SPDX-License-Identifier: Apache-2.0
#pragma once
// A synthetic robot positioning error as a function of the nominal position: smooth (linear and
// quadratic, like a mis-calibrated arm) plus wavy (periodic, like transmission error). For
// examples and tests of RRBC before the kinematic test beds are used.
#include <array>

#include <Eigen/Core>

#include "vrreg/core/random.hpp"

namespace vrreg {

/// error(p) = A (p - c) + B ((p - c) o (p - c)) + sum_k a_k sin(2 pi (p - c) . n_k / lambda_k + phi_k) [m].
struct CartesianErrorField {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();       ///< c, robot frame
  Eigen::Matrix3d linear = Eigen::Matrix3d::Zero();         ///< A [m/m]
  Eigen::Matrix3d quadratic_per_m = Eigen::Matrix3d::Zero();  ///< B [1/m]
  struct Wave {
    Eigen::Vector3d amplitude_m = Eigen::Vector3d::Zero();  ///< a_k per axis
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX();   ///< n_k, unit
    double wavelength_m = 0.1;                              ///< lambda_k
    double phase_rad = 0.0;                                 ///< phi_k
  };
  std::array<Wave, 3> waves{};

  /// The robot's positioning error at a nominal robot-frame position [m].
  [[nodiscard]] Eigen::Vector3d error_m(const Eigen::Vector3d& nominal_robot_m) const;

  /// A random field of about `smooth_rms_m` smooth and `wavy_rms_m` wavy error over a volume of
  /// half-width `half_extent_m` around `centre_m`; wavelengths 60-150 mm.
  static CartesianErrorField random(Random& rng, const Eigen::Vector3d& centre_m,
                                    double half_extent_m, double smooth_rms_m, double wavy_rms_m);
};

}  // namespace vrreg
