// SPDX-License-Identifier: Apache-2.0
#include "vrreg/pipeline/marker_offset.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "set_rows.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg {
namespace {

using pipeline_detail::fail;

// The joints of location `i` as a vector; fails naming the line unless there are n of them.
Eigen::VectorXd joints_of(const MeasurementSet& set, std::size_t i, int n) {
  const Location& loc = set.locations[i];
  if (static_cast<int>(loc.q_rad.size()) != n) {
    fail(set,
         "point '" + loc.point + "' has " + std::to_string(loc.q_rad.size()) +
             " joint angles; the robot has " + std::to_string(n) +
             " (the marker offset is estimated from joints: q1_rad..qN_rad)",
         loc.source_line);
  }
  return Eigen::Map<const Eigen::VectorXd>(loc.q_rad.data(), n);
}

double rotation_angle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const double c = 0.5 * ((a.transpose() * b).trace() - 1.0);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

// Which of the poses share the orientation most of them have (within the tolerance); all of them
// when no orientation is shared by at least half.
std::vector<bool> dominant_orientation(const std::vector<Eigen::Isometry3d>& flange) {
  const std::size_t n = flange.size();
  std::size_t best = 0, best_count = 0;
  for (std::size_t a = 0; a < n; ++a) {
    std::size_t count = 0;
    for (std::size_t b = 0; b < n; ++b) {
      count +=
          rotation_angle(flange[a].linear(), flange[b].linear()) <= kRrbcOrientationToleranceRad
              ? 1
              : 0;
    }
    if (count > best_count) {
      best_count = count;
      best = a;
    }
  }
  std::vector<bool> keep(n, true);
  if (2 * best_count < n) return keep;
  for (std::size_t b = 0; b < n; ++b) {
    keep[b] =
        rotation_angle(flange[best].linear(), flange[b].linear()) <= kRrbcOrientationToleranceRad;
  }
  return keep;
}

void check_options(const RegisterOptions& options) {
  options.validate();
  const planning::Strategy s = options.procedure2.strategy;
  VRREG_THROW_UNLESS(s == planning::Strategy::kNone || s == planning::Strategy::kAsListed,
                     "the marker offset is estimated for one registration: `strategy` "
                         << planning::strategy_number(s) << " is not available with it");
  VRREG_THROW_UNLESS(!options.robust, "`robust` is not available with the marker offset estimate");
  VRREG_THROW_UNLESS(!options.registration.estimate_scale,
                     "`scale` is not available with the marker offset estimate");
}

}  // namespace

Eigen::Isometry3d MarkerOffsetModel::flange_pose(const kinematics::JointRef& q_rad) const {
  return kinematics::forward_kinematics(flange_chain, q_rad);
}

Eigen::Vector3d MarkerOffsetModel::marker_robot_m(const kinematics::JointRef& q_rad) const {
  return flange_pose(q_rad) * p_flange_marker_m;
}

MeasurementSet with_marker_offset(const RegistrationModel& model, const MeasurementSet& set,
                                  Role role, bool require_joints) {
  if (!model.marker_offset) return set;
  const MarkerOffsetModel& offset = *model.marker_offset;
  const int n = offset.flange_chain.n_joints();
  MeasurementSet out = set;
  for (std::size_t i = 0; i < out.locations.size(); ++i) {
    Location& loc = out.locations[i];
    if (loc.q_rad.empty() && !(require_joints && loc.role == role)) continue;
    loc.robot_m = offset.marker_robot_m(joints_of(set, i, n));
    loc.has_robot = true;
  }
  return out;
}

namespace {

// The arm up to the marker: the flange chain with the marker offset as its tool.
kinematics::SerialChain chain_to_marker(const kinematics::SerialChain& flange_chain,
                                        const Eigen::Vector3d& p_flange_marker_m) {
  return flange_chain.with_tool(Eigen::Isometry3d(Eigen::Translation3d(p_flange_marker_m)));
}

// The fiducial rows' flange poses (FK of the robot without its tool).
std::vector<Eigen::Isometry3d> flange_poses(const MeasurementSet& fiducials,
                                            const kinematics::SerialChain& flange_chain,
                                            const std::vector<std::size_t>& rows) {
  std::vector<Eigen::Isometry3d> flange;
  flange.reserve(rows.size());
  for (const std::size_t i : rows) {
    flange.push_back(kinematics::forward_kinematics(
        flange_chain, joints_of(fiducials, i, flange_chain.n_joints())));
  }
  return flange;
}

// The model on FK positions with offset `offset`: RRBC on the fiducials at the common
// orientation; the tilted ones served the offset only (their names appended to `offset_only`).
RegisterResult register_on_offset(const MeasurementSet& fiducials, const MarkerOffsetModel& offset,
                                  const std::vector<std::size_t>& rows,
                                  const std::vector<Eigen::Isometry3d>& flange,
                                  const RegisterOptions& options,
                                  std::vector<std::string>& offset_only) {
  RegistrationModel seed;
  seed.marker_offset = offset;
  MeasurementSet moved = with_marker_offset(seed, fiducials, Role::kFiducial, true);
  const std::vector<bool> keep = dominant_orientation(flange);
  std::vector<bool> drop(moved.locations.size(), false);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (keep[k]) continue;
    drop[rows[k]] = true;
    offset_only.push_back(moved.locations[rows[k]].point);
  }
  if (!offset_only.empty()) {
    std::vector<Location> kept;
    for (std::size_t i = 0; i < moved.locations.size(); ++i) {
      if (!drop[i]) kept.push_back(std::move(moved.locations[i]));
    }
    moved.locations = std::move(kept);
  }
  // The model keeps the arm up to the marker (whatever tool a robot in `options` had): the
  // positions are the marker's, so the joint model and `auto` use that chain, and evaluate and
  // correct never ask for the robot again.
  RegisterOptions with_robot = options;
  with_robot.robot = chain_to_marker(offset.flange_chain, offset.p_flange_marker_m);
  RegisterResult out = register_fiducials(moved, with_robot);
  out.model.marker_offset = offset;
  return out;
}

// The uncertainty of p from joint zero-offset errors (sigma per joint, independent): the
// estimate's sensitivity to the marker positions, (J'J)^-1 J', times their sensitivity to the
// joint offsets (the FK Jacobian of the marker point), propagated as sigma^2 M M'.
Eigen::Vector3d joint_offset_std(const MarkerOffsetResult& e,
                                 const kinematics::SerialChain& flange_chain,
                                 const MeasurementSet& fiducials,
                                 const std::vector<std::size_t>& rows,
                                 const std::vector<Eigen::Isometry3d>& flange, double sigma_rad) {
  if (sigma_rad == 0.0) return Eigen::Vector3d::Zero();
  const auto n = static_cast<Eigen::Index>(rows.size());
  const int n_joints = flange_chain.n_joints();
  const kinematics::SerialChain marker_chain = chain_to_marker(flange_chain, e.p_flange_marker_m);
  Eigen::MatrixXd jac(3 * n, 9);
  Eigen::MatrixXd g(3 * n, n_joints);
  for (Eigen::Index j = 0; j < n; ++j) {
    const Location& loc = fiducials.locations[rows[static_cast<std::size_t>(j)]];
    const Eigen::Vector3d ry = e.T_robot_sensor.rotation * loc.sensor_m;
    Eigen::Matrix3d skew;
    skew << 0.0, -ry.z(), ry.y(), ry.z(), 0.0, -ry.x(), -ry.y(), ry.x(), 0.0;
    jac.block<3, 3>(3 * j, 0) = -skew;
    jac.block<3, 3>(3 * j, 3) = Eigen::Matrix3d::Identity();
    jac.block<3, 3>(3 * j, 6) = -flange[static_cast<std::size_t>(j)].linear();
    g.middleRows<3>(3 * j) =
        kinematics::jacobian(marker_chain,
                             joints_of(fiducials, rows[static_cast<std::size_t>(j)], n_joints))
            .topRows<3>();
  }
  const Eigen::MatrixXd m = (jac.transpose() * jac).ldlt().solve(jac.transpose() * g);
  const Eigen::Matrix3d cov =
      sigma_rad * sigma_rad * (m.bottomRows<3>() * m.bottomRows<3>().transpose());
  return cov.diagonal().cwiseMax(0.0).cwiseSqrt();
}

// The sensor's marker orientations of `rows` when every one has one (a rigid-body tracker: the
// estimator then also uses them); empty otherwise.
std::vector<Eigen::Quaterniond> marker_orientations(const MeasurementSet& set,
                                                    const std::vector<std::size_t>& rows) {
  std::vector<Eigen::Quaterniond> q;
  for (const std::size_t i : rows) {
    if (!set.locations[i].q_sensor_marker) return {};
    q.push_back(*set.locations[i].q_sensor_marker);
  }
  return q;
}

}  // namespace

MarkerOffsetRegisterResult register_with_marker_offset(const MeasurementSet& fiducials,
                                                       const kinematics::SerialChain& robot,
                                                       const RegisterOptions& options,
                                                       const MarkerOffsetOptions& estimation) {
  check_options(options);
  estimation.validate();
  const kinematics::SerialChain flange_chain = robot.with_tool(Eigen::Isometry3d::Identity());
  const std::vector<std::size_t> rows =
      pipeline_detail::select_rows(fiducials, Role::kFiducial, options.config);
  const std::vector<Eigen::Isometry3d> flange = flange_poses(fiducials, flange_chain, rows);
  if (rows.size() < 5) {
    fail(fiducials,
         "the marker offset needs at least 5 fiducial poses, found " + std::to_string(rows.size()));
  }
  MarkerOffsetRegisterResult out;
  out.estimate = estimate_marker_offset(flange, fiducials.sensor_points(rows),
                                        marker_orientations(fiducials, rows), estimation);
  if (!out.estimate.ok()) return out;
  out.p_std_joint_offsets_m = joint_offset_std(out.estimate, flange_chain, fiducials, rows, flange,
                                               estimation.joint_offset_sigma_rad);
  out.p_std_total_m =
      (out.estimate.p_std_m.cwiseAbs2() + out.p_std_joint_offsets_m.cwiseAbs2()).cwiseSqrt();
  out.registered = register_on_offset(
      fiducials, MarkerOffsetModel{out.estimate.p_flange_marker_m, out.p_std_total_m, flange_chain},
      rows, flange, options, out.offset_only);
  return out;
}

MarkerOffsetRegisterResult register_with_known_marker_offset(
    const MeasurementSet& fiducials, const kinematics::SerialChain& robot,
    const Eigen::Vector3d& p_flange_marker_m, const RegisterOptions& options) {
  check_options(options);
  VRREG_THROW_UNLESS(p_flange_marker_m.allFinite(), "the marker offset must be finite");
  const kinematics::SerialChain flange_chain = robot.with_tool(Eigen::Isometry3d::Identity());
  const std::vector<std::size_t> rows =
      pipeline_detail::select_rows(fiducials, Role::kFiducial, options.config);
  const std::vector<Eigen::Isometry3d> flange = flange_poses(fiducials, flange_chain, rows);
  MarkerOffsetRegisterResult out;
  out.estimate.p_flange_marker_m = p_flange_marker_m;
  out.estimate.orientation_spread = orientation_spread(flange);
  out.registered = register_on_offset(
      fiducials, MarkerOffsetModel{p_flange_marker_m, Eigen::Vector3d::Zero(), flange_chain}, rows,
      flange, options, out.offset_only);
  out.estimate.T_robot_sensor = out.registered->model.T_robot_sensor.rigid();
  out.estimate.fre_m = out.registered->model.fre_m;
  return out;
}

MarkerOffsetRegisterResult register_with_marker_offset(const MeasuredPoints& fiducials,
                                                       const kinematics::SerialChain& robot,
                                                       const RegisterOptions& options,
                                                       const MarkerOffsetOptions& estimation) {
  VRREG_THROW_UNLESS(fiducials.joints_rad.cols() == fiducials.size() && fiducials.size() > 0,
                     "the marker offset is estimated from joints: joints_rad needs one column per "
                     "fiducial ("
                         << fiducials.size() << "), has " << fiducials.joints_rad.cols());
  MeasuredPoints with_robot = fiducials;
  if (with_robot.robot_m.cols() == 0) {  // robot positions come from FK; none needed here
    with_robot.robot_m = Points3::Zero(3, fiducials.size());
  }
  return register_with_marker_offset(with_robot.to_measurement_set(Role::kFiducial, true), robot,
                                     options, estimation);
}

}  // namespace vrreg
