// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/rail_cell.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/kinematics/dh.hpp"
#include "vrreg/kinematics/inverse_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/simulation/plan_acquisition.hpp"

namespace vrreg::simulation {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kToolM = 0.1;
constexpr std::uint64_t kTargetStream = 7;

// The carriage's DH row: it slides along the DH base frame's z (the robot's x, see below), and
// leaves a frame whose z points up again.
constexpr kinematics::DhRow kCarriage{0.0, kPi / 2, 0.0, -kPi / 2, kinematics::JointType::kPrismatic};

Eigen::Isometry3d rail_base() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(-1.0, 0.5, 0.25);
  return T;
}

Eigen::Isometry3d tool() { return Eigen::Isometry3d(Eigen::Translation3d(0.0, 0.0, kToolM)); }

Eigen::Matrix3d tool_down() { return Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal(); }

}  // namespace

kinematics::SerialChain ur5_on_rail() {
  const kinematics::SerialChain arm = kinematics::ur5();
  std::vector<kinematics::DhRow> rows{kCarriage};
  std::vector<kinematics::JointLimits> limits{{0.0, 2.0}};
  for (int i = 0; i < arm.n_rows(); ++i) {
    rows.push_back(arm.row(i));
    limits.push_back(arm.limits()[static_cast<std::size_t>(i)]);
  }
  return kinematics::SerialChain("ur5_on_rail", std::move(rows), std::move(limits), rail_base());
}

Testbed rail_testbed(double ripple_amplitude_m, double ripple_period_m) {
  TestbedErrorModel errors;
  RobotErrorModel& r = errors.robot;
  r.joint_offset_sigma_rad = units::deg_to_rad(0.05);
  r.link_length_sigma_m = 0.1e-3;
  r.link_offset_sigma_m = 0.1e-3;
  r.twist_sigma_rad = units::deg_to_rad(0.01);
  // The carriage's ripple only; the arm's joints have none here (period 1 rad, amplitude 0).
  r.transmission_amplitude_rad = {ripple_amplitude_m, 0, 0, 0, 0, 0, 0};
  r.transmission_period_rad = {ripple_period_m, 1, 1, 1, 1, 1, 1};
  r.repeatability_sigma_m = 0.01e-3;
  errors.tracker.distance_m = 2.4;
  errors.tracker.azimuth_rad = units::deg_to_rad(-60.0);
  errors.tracker.elevation_rad = units::deg_to_rad(20.0);
  errors.tracker.noise_sigma_m.setConstant(0.02e-3);
  errors.tracker.readings_per_location = 3;
  kinematics::JointVector home(7);
  home << 1.0, 0.0, -1.9, -1.6, -1.2, 1.57, 0.4;
  return Testbed{.kind = TestbedKind::kUr5,
                 .name = "ur5_on_rail",
                 .nominal = ur5_on_rail().with_tool(tool()),
                 .tcp_rotation = tool_down(),
                 .volume_centre_m = Eigen::Vector3d(0.0, 0.0, 0.2),
                 .arm_angle_rad = 0.0,
                 .home_q_rad = home,
                 .sigma_rep_spec_m = 0.02e-3,
                 .default_errors = errors};
}

RailCell rail_cell(const RailCellOptions& options) {
  VRREG_THROW_UNLESS(!options.stations_m.empty(), "rail cell: no carriage positions");
  VRREG_THROW_UNLESS(options.targets >= 0 && options.target_lo_m <= options.target_hi_m,
                     "rail cell: targets " << options.targets << " between "
                                           << options.target_lo_m << " and "
                                           << options.target_hi_m << " m");
  const Testbed testbed = rail_testbed(options.ripple_amplitude_m, options.ripple_period_m);
  const kinematics::SerialChain arm = kinematics::ur5().with_tool(tool());
  // The arm's joints for a TCP position with the carriage at s: the UR5's own IK from the
  // carriage's frame, the branch nearest the previous location's (one branch throughout).
  kinematics::JointVector arm_q = testbed.home_q_rad.tail(6);
  const auto joints_at = [&](double s_m, const Eigen::Vector3d& p_m) {
    const Eigen::Isometry3d T_base_arm = rail_base() * kinematics::dh_transform(kCarriage, s_m);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = tool_down();
    pose.translation() = p_m;
    const kinematics::IkResult ik =
        kinematics::inverse_kinematics_nearest(arm, T_base_arm.inverse() * pose, arm_q);
    VRREG_THROW_UNLESS(ik.ok() && !ik.solutions.empty(),
                       "rail cell: no arm joints reach (" << p_m.transpose() << ") m from the "
                                                          << "carriage at " << s_m << " m");
    arm_q = ik.solutions.front().q_rad;
    kinematics::JointVector q(7);
    q << s_m, arm_q;
    return q;
  };
  const Eigen::Vector3d centre_m(0.0, 0.0, 0.2);
  std::vector<CommandedLocation> plan;
  for (std::size_t c = 0; c < options.stations_m.size(); ++c) {
    int k = 0;
    for (const double x : {-0.15, -0.075, 0.0, 0.075, 0.15}) {
      for (const double y : {-0.1, 0.0, 0.1}) {
        for (const double z : {-0.1, 0.0, 0.1}) {
          const Eigen::Vector3d p = centre_m + Eigen::Vector3d(x, y, z);
          plan.push_back({"f" + std::to_string(k++) + "_c" + std::to_string(c + 1),
                          Role::kFiducial, p, std::nullopt, joints_at(options.stations_m[c], p)});
        }
      }
    }
  }
  const auto n_fid = static_cast<Eigen::Index>(plan.size());
  Random rng = Random::stream(options.seed, kTargetStream);
  for (int t = 0; t < options.targets; ++t) {
    const Eigen::Vector3d p =
        centre_m + Eigen::Vector3d(rng.uniform(-0.14, 0.14), rng.uniform(-0.09, 0.09),
                                   rng.uniform(-0.09, 0.09));
    const double s_m = rng.uniform(options.target_lo_m, options.target_hi_m);
    plan.push_back({"t" + std::to_string(t), Role::kTarget, p, std::nullopt, joints_at(s_m, p)});
  }
  SimulationOptions simulation;
  simulation.seed = options.seed;
  const SimulatedDataset data = simulate_plan(testbed, plan, simulation);
  const Points3 means = visit_means_m(data);
  RailCell cell{.robot = testbed.nominal};
  const auto n_tgt = static_cast<Eigen::Index>(plan.size()) - n_fid;
  cell.fiducials_robot_m.resize(3, n_fid);
  cell.fiducials_sensor_m.resize(3, n_fid);
  cell.fiducials_q_rad.resize(7, n_fid);
  cell.targets_robot_m.resize(3, n_tgt);
  cell.targets_sensor_m.resize(3, n_tgt);
  cell.targets_q_rad.resize(7, n_tgt);
  for (std::size_t v = 0; v < plan.size(); ++v) {
    const auto i = static_cast<Eigen::Index>(v);
    const bool fiducial = i < n_fid;
    const Eigen::Index j = fiducial ? i : i - n_fid;
    (fiducial ? cell.fiducials_robot_m : cell.targets_robot_m).col(j) = plan[v].robot_m;
    (fiducial ? cell.fiducials_sensor_m : cell.targets_sensor_m).col(j) = means.col(i);
    (fiducial ? cell.fiducials_q_rad : cell.targets_q_rad).col(j) = plan[v].q_rad;
  }
  const TrackerModel& tracker = testbed.default_errors.tracker;
  cell.noise_sd_m = tracker.noise_sigma_m.norm() / std::sqrt(3.0 * tracker.readings_per_location);
  return cell;
}

}  // namespace vrreg::simulation
