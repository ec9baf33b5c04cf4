// SPDX-License-Identifier: Apache-2.0
#pragma once
// A simulated cell of a robot whose joints may follow others (URDF mimic joints): the as-built
// arm has errors of its own per physical joint (DH deltas of every row, a zero offset and, for a
// slide, a scale error of every row), the commanded joints are the chain's variables, and the
// tracker reads the marker with noise in a frame of its own. What the joint-space model and the
// command line are tested on.
#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "vrreg/core/random.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::testing {

/// One measured location: commanded joints, nominal TCP and tracker reading [m].
struct CoupledCellLocation {
  kinematics::JointVector q;  ///< the chain's variables
  Eigen::Vector3d nominal_m;  ///< FK of the nominal chain (robot frame)
  Eigen::Vector3d actual_m;   ///< where the TCP really is (robot frame)
  Eigen::Vector3d sensor_m;   ///< the tracker's reading (sensor frame, with noise)
};

/// The as-built chain of `nominal`'s rows, every row its own joint.
struct CoupledCellRobot {
  kinematics::SerialChain actual;  ///< uncoupled: one variable per row
  Eigen::VectorXd row_offset;      ///< zero offset of each row [rad or m]
  Eigen::VectorXd row_scale;       ///< 1 + scale error of each row
};

inline CoupledCellRobot as_built(const kinematics::SerialChain& nominal, Random& rng) {
  std::vector<kinematics::DhRow> rows = nominal.rows();
  CoupledCellRobot r{nominal.uncoupled(), Eigen::VectorXd(nominal.n_rows()),
                     Eigen::VectorXd(nominal.n_rows())};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].a_m += rng.normal(0.2e-3);
    rows[i].alpha_rad += rng.normal(2e-4);
    (rows[i].prismatic() ? rows[i].theta_offset_rad : rows[i].d_m) +=
        rows[i].prismatic() ? rng.normal(2e-4) : rng.normal(0.2e-3);
    const auto k = static_cast<Eigen::Index>(i);
    r.row_offset(k) = rows[i].prismatic() ? rng.normal(0.3e-3) : rng.normal(1e-3);
    r.row_scale(k) = 1.0 + (rows[i].prismatic() ? rng.normal(2e-3) : rng.normal(2e-4));
  }
  r.actual = kinematics::SerialChain(nominal.name() + "-as-built", rows, nominal.limits(),
                                     nominal.T_base_dh0(), nominal.T_flange_tcp());
  return r;
}

/// `n` locations at joints drawn uniformly within `half_range` of `home` (clamped to the
/// limits), read by a tracker at `T_sensor_robot` with noise `noise_m` per axis.
inline std::vector<CoupledCellLocation> coupled_cell(const kinematics::SerialChain& nominal,
                                                     const CoupledCellRobot& robot,
                                                     const kinematics::JointVector& home,
                                                     const kinematics::JointVector& half_range,
                                                     int n, const Eigen::Isometry3d& T_sensor_robot,
                                                     double noise_m, Random& rng) {
  std::vector<CoupledCellLocation> out;
  for (int j = 0; j < n; ++j) {
    CoupledCellLocation l;
    l.q = home;
    for (int i = 0; i < nominal.n_joints(); ++i) {
      const kinematics::JointLimits& lim = nominal.limit(i);
      l.q(i) = std::clamp(home(i) + rng.uniform(-half_range(i), half_range(i)), lim.lower_rad,
                          lim.upper_rad);
    }
    l.nominal_m = kinematics::forward_kinematics(nominal, l.q).translation();
    const kinematics::JointVector q_row = nominal.row_values(l.q);
    const kinematics::JointVector q_as_built =
        robot.row_scale.cwiseProduct(q_row) + robot.row_offset;
    l.actual_m = kinematics::forward_kinematics(robot.actual, q_as_built).translation();
    l.sensor_m = T_sensor_robot * l.actual_m + rng.normal3(noise_m);
    out.push_back(l);
  }
  return out;
}

/// Writes `fiducials` then `targets` as a measurement CSV (mm, joints in rad).
inline void write_coupled_cell_csv(const std::string& path,
                                   const std::vector<CoupledCellLocation>& fiducials,
                                   const std::vector<CoupledCellLocation>& targets) {
  std::ofstream out(path);
  const auto n = fiducials.front().q.size();
  out << "point,role,robot_x_mm,robot_y_mm,robot_z_mm,sensor_x_mm,sensor_y_mm,sensor_z_mm";
  for (Eigen::Index i = 0; i < n; ++i) out << ",q" << i + 1 << "_rad";
  out << "\n";
  out.precision(17);
  int point = 0;
  for (const auto* set : {&fiducials, &targets}) {
    for (const CoupledCellLocation& l : *set) {
      out << (set == &fiducials ? "f" : "t") << point++ << ","
          << (set == &fiducials ? "fiducial" : "target");
      for (int a = 0; a < 3; ++a) out << "," << 1e3 * l.nominal_m(a);
      for (int a = 0; a < 3; ++a) out << "," << 1e3 * l.sensor_m(a);
      for (Eigen::Index i = 0; i < n; ++i) out << "," << l.q(i);
      out << "\n";
    }
  }
}

}  // namespace vrreg::testing
