// SPDX-License-Identifier: Apache-2.0
#pragma once
// A small synthetic cell for Procedure 2 (paper section 4.4) tests: a 5 x 5 x 5 grid (20 mm) of
// nominal points, each measured in two arm configurations A and B whose robot errors differ
// (smooth within an arm, a jump between arms), targets at the 8 all-odd nodes (centres of 40 mm
// cubes of fiducials). The file lists the arms as labels 1, 2 for x < 40 mm and 2, 1 from there
// on (an IK that changes its order), so Strategy 1's label 1 mixes arms; Strategy 2 should switch
// every location with x >= 40 mm (3/5 of them).
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "vrreg/core/random.hpp"

namespace vrreg::testing {

struct TwoArmCellOptions {
  std::uint64_t seed = 5;
  double noise_mm = 0.005;  ///< sensor noise per axis
  bool with_joints = true;  ///< write q1_rad..q7_rad
  bool with_config = true;  ///< write the config column
  double spacing_mm = 20.0;
};

inline double wrap_pi(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }

/// Joints [rad] of arm `b` (false: A, true: B) at nominal position p [mm].
inline Eigen::Matrix<double, 7, 1> two_arm_joints(const Eigen::Vector3d& p_mm, bool b) {
  const Eigen::Vector3d p = p_mm / 1000.0;
  Eigen::Matrix<double, 7, 1> q;
  q << 0.2 + 3 * p.x(), 0.6 + 2 * p.y(), -0.3 + 2 * p.z(), 1.2 + p.x(), 0.1 - p.y(), 0.9 + p.z(),
      0.05;
  if (b) {
    const double pi = std::numbers::pi;
    Eigen::Matrix<double, 7, 1> flip;
    flip << pi, -1.2, pi, -2.4, pi, 0.8, 0.0;
    q += flip;
  }
  for (int i = 0; i < 7; ++i) q(i) = wrap_pi(q(i));
  return q;
}

/// Robot-frame error [mm] of arm `b` at nominal position p [mm]: smooth per arm, arms differ.
inline Eigen::Vector3d two_arm_error_mm(const Eigen::Vector3d& p, bool b) {
  if (!b)
    return 0.2 * Eigen::Vector3d(std::sin(p.x() / 30), std::cos(p.y() / 40), std::sin(p.z() / 50));
  return Eigen::Vector3d(0.6, -0.4, 0.5) +
         0.3 * Eigen::Vector3d(std::cos(p.x() / 25), std::sin(p.z() / 30), std::cos(p.y() / 35));
}

/// The cell as a measurement CSV (mm, rad), points visited in file order (x fastest).
inline std::string two_arm_cell_csv(const TwoArmCellOptions& o = {}) {
  Random rng(o.seed);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d t_mm(1000.0, -500.0, 2000.0);
  std::ostringstream out;
  out.precision(12);
  out << "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm";
  if (o.with_config) out << ",config";
  if (o.with_joints) out << ",q1_rad,q2_rad,q3_rad,q4_rad,q5_rad,q6_rad,q7_rad";
  out << "\n";
  for (int k = 0; k < 5; ++k) {
    for (int j = 0; j < 5; ++j) {
      for (int i = 0; i < 5; ++i) {
        const Eigen::Vector3d p = o.spacing_mm * Eigen::Vector3d(i, j, k);
        const bool target = i % 2 == 1 && j % 2 == 1 && k % 2 == 1;
        const std::string name = std::string(target ? "T" : "F") + std::to_string(i) +
                                 std::to_string(j) + std::to_string(k);
        const int n_labels = o.with_config ? 2 : 1;
        for (int label = 1; label <= n_labels; ++label) {
          const bool arm_b = (label == 2) != (i >= 2);  // labels swap from x = 40 mm on
          const Eigen::Vector3d s =
              R * (p + two_arm_error_mm(p, arm_b)) + t_mm + rng.normal3(o.noise_mm);
          out << name << ',' << (target ? "target" : "fiducial") << ',' << p.x() << ',' << p.y()
              << ',' << p.z() << ',' << s.x() << ',' << s.y() << ',' << s.z();
          if (o.with_config) out << ',' << label;
          if (o.with_joints) {
            const auto q = two_arm_joints(p, arm_b);
            for (int a = 0; a < 7; ++a) out << ',' << q(a);
          }
          out << "\n";
        }
      }
    }
  }
  return out.str();
}

}  // namespace vrreg::testing
