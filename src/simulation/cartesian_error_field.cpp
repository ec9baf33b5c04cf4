// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/cartesian_error_field.hpp"

#include <cmath>
#include <numbers>

namespace vrreg {

Eigen::Vector3d CartesianErrorField::error_m(const Eigen::Vector3d& nominal_robot_m) const {
  const Eigen::Vector3d p = nominal_robot_m - centre_m;
  Eigen::Vector3d e = linear * p + quadratic_per_m * p.cwiseProduct(p);
  for (const Wave& w : waves) {
    e += w.amplitude_m *
         std::sin(2.0 * std::numbers::pi * p.dot(w.direction) / w.wavelength_m + w.phase_rad);
  }
  return e;
}

CartesianErrorField CartesianErrorField::random(Random& rng, const Eigen::Vector3d& centre_m,
                                                double half_extent_m, double smooth_rms_m,
                                                double wavy_rms_m) {
  CartesianErrorField f;
  f.centre_m = centre_m;
  // Linear and quadratic parts each give about smooth_rms / sqrt(2) at the volume's edge scale.
  const double lin = smooth_rms_m / half_extent_m / std::sqrt(2.0);
  const double quad = smooth_rms_m / (half_extent_m * half_extent_m) / std::sqrt(2.0);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      f.linear(r, c) = rng.normal(lin / std::sqrt(3.0));
      f.quadratic_per_m(r, c) = rng.normal(quad / std::sqrt(3.0));
    }
  }
  for (Wave& w : f.waves) {
    // A sine has RMS amplitude / sqrt(2); three waves share the wavy budget.
    w.amplitude_m = rng.normal3(wavy_rms_m * std::sqrt(2.0 / 3.0) / std::sqrt(3.0));
    Eigen::Vector3d d(rng.normal(), rng.normal(), rng.normal());
    w.direction = d.normalized();
    w.wavelength_m = rng.uniform(0.06, 0.15);
    w.phase_rad = rng.uniform(0.0, 2.0 * std::numbers::pi);
  }
  return f;
}

}  // namespace vrreg
