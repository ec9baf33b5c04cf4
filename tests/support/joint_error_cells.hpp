// SPDX-License-Identifier: Apache-2.0
#pragma once
// The joint-space error model on simulated test-bed cells: register all fiducials,
// fit the model to their observed errors, correct the targets, and compare with the noise floor
// (the same registration corrected by the robot's true systematic error).
#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/kinematics/joint_error_model.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/registration/rigid.hpp"
#include "vrreg/simulation/acquisition.hpp"
#include "vrreg/simulation/simulated_robot.hpp"

namespace vrreg::testing {

/// Per-target corrected and floor errors of one cell [m], in set.select(Role::kTarget) order.
struct JointCellOutcome {
  std::vector<std::size_t> targets;
  Eigen::VectorXd cor_tre_m;
  Eigen::VectorXd floor_tre_m;
  std::vector<int> degrees;
  int rank = 0;
  int n_parameters = 0;
  double residual_rms_m = 0.0;
};

inline std::vector<kinematics::JointVector> joints_of(const MeasurementSet& set,
                                                      const std::vector<std::size_t>& idx) {
  std::vector<kinematics::JointVector> q;
  for (std::size_t i : idx) {
    const std::vector<double>& v = set.locations[i].q_rad;
    q.push_back(Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())));
  }
  return q;
}

/// Joint-model correction of every target of `set` (simulated as `data` on `nominal`): e_j =
/// R X_j + tau - y_nominal_j at the fiducials; corrected target R X_t + tau - e(q_t).
inline JointCellOutcome joint_model_cell(const MeasurementSet& set,
                                         const simulation::SimulatedDataset& data,
                                         const kinematics::SerialChain& nominal,
                                         const kinematics::JointErrorModelOptions& options) {
  const std::vector<std::size_t> fid = set.select(Role::kFiducial);
  JointCellOutcome out;
  out.targets = set.select(Role::kTarget);
  const Points3 fid_robot = set.robot_points(fid);
  const RigidTransform T_robot_sensor =
      register_rigid(set.sensor_points(fid), fid_robot).T_robot_sensor.rigid();
  const Points3 e_fid = T_robot_sensor.apply_all(set.sensor_points(fid)) - fid_robot;
  const kinematics::JointErrorModel model =
      kinematics::JointErrorModel::fit(nominal, joints_of(set, fid), e_fid, options);
  const std::vector<kinematics::JointVector> q_tgt = joints_of(set, out.targets);
  const Points3 tgt_robot = set.robot_points(out.targets);
  const Points3 registered = T_robot_sensor.apply_all(set.sensor_points(out.targets));
  out.cor_tre_m = point_errors(registered - model.predict_m(q_tgt), tgt_robot);
  // The systematic error as this registration sees it: where the arm really stands (no
  // repeatability, no tracker noise), through the true and the fitted frame.
  const simulation::SimulatedRobot robot(nominal, data.errors.robot, data.robot);
  const RigidTransform T_seen = T_robot_sensor * data.T_robot_sensor.inverse();
  Points3 systematic(3, tgt_robot.cols());
  for (Eigen::Index t = 0; t < systematic.cols(); ++t) {
    systematic.col(t) =
        T_seen.apply(robot.actual_tcp_m(q_tgt[static_cast<std::size_t>(t)])) - tgt_robot.col(t);
  }
  out.floor_tre_m = point_errors(registered - systematic, tgt_robot);
  out.degrees = model.joint_degrees();
  out.rank = model.rank();
  out.n_parameters = model.n_parameters();
  out.residual_rms_m = model.residual_rms_m();
  return out;
}

/// RMS of the entries of `tre` at positions `rows` [m].
inline double rms_at(const Eigen::VectorXd& tre, const std::vector<Eigen::Index>& rows) {
  double s = 0.0;
  for (Eigen::Index r : rows) s += tre(r) * tre(r);
  return std::sqrt(s / static_cast<double>(rows.size()));
}

}  // namespace vrreg::testing
