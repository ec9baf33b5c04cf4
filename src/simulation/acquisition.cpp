// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/acquisition.hpp"

#include <bit>
#include <sstream>

#include "acquisition_detail.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/lwr_ik.hpp"
#include "vrreg/kinematics/ur_ik.hpp"
#include "vrreg/simulation/aik_order.hpp"
#include "vrreg/simulation/simulated_robot.hpp"

namespace vrreg::simulation {
namespace {

// Independent random streams per purpose, so that e.g. K does not change the robot's draws.
constexpr std::uint64_t kRobotStream = 0;
constexpr std::uint64_t kVisitStream = 100;
constexpr std::uint64_t kReadingStream = 200;
// Its own stream: a rigid body leaves every position draw as it was.
constexpr std::uint64_t kOrientationStream = 300;

Eigen::Isometry3d tcp_pose(const Testbed& testbed, const Eigen::Vector3d& position_m) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = testbed.tcp_rotation;
  pose.translation() = position_m;
  return pose;
}

std::string where(const PlannedLocation& location) {
  std::ostringstream out;
  out << location.point << " at (" << 1e3 * location.robot_m.transpose() << ") mm";
  return out.str();
}

// UR controller: one solution, the one nearest the joints of the previous location.
void plan_ur_visits(const Testbed& testbed, SimulatedDataset& data) {
  kinematics::JointVector q_previous = testbed.home_q_rad;
  for (std::size_t n = 0; n < data.locations.size(); ++n) {
    const PlannedLocation& location = data.locations[n];
    const kinematics::IkResult ik = kinematics::ur_inverse_kinematics_nearest(
        testbed.nominal, tcp_pose(testbed, location.robot_m), q_previous);
    VRREG_THROW_UNLESS(ik.ok() && !ik.solutions.empty(), testbed.name << ": no IK solution for "
                                                                      << where(location) << ": "
                                                                      << ik.message);
    q_previous = ik.solutions.front().q_rad;
    data.visits.push_back({static_cast<int>(n), 0, q_previous, Eigen::Vector3d::Zero()});
  }
}

// LWR: every configuration the analytic IK gives at the test bed's arm angle, in its order.
void plan_lwr_visits(const Testbed& testbed, SimulatedDataset& data) {
  constexpr std::size_t kConfigurations = 4;
  for (std::size_t n = 0; n < data.locations.size(); ++n) {
    const PlannedLocation& location = data.locations[n];
    kinematics::IkResult ik = kinematics::lwr_inverse_kinematics(
        testbed.nominal, tcp_pose(testbed, location.robot_m), testbed.arm_angle_rad);
    VRREG_THROW_UNLESS(ik.ok() && ik.solutions.size() == kConfigurations,
                       testbed.name << ": " << ik.solutions.size() << " arm configurations (not "
                                    << kConfigurations << ") for " << where(location) << " "
                                    << ik.message);
    const auto ordered = aik_order(std::move(ik.solutions), testbed.home_q_rad);
    for (std::size_t m = 0; m < ordered.size(); ++m) {
      data.visits.push_back({static_cast<int>(n), static_cast<int>(m) + 1, ordered[m].q_rad,
                             Eigen::Vector3d::Zero()});
    }
  }
}

}  // namespace

SimulatedDataset simulate_dataset(const Testbed& testbed, Dataset dataset,
                                  const SimulationOptions& options) {
  check_dataset(testbed.kind, dataset);
  SimulatedDataset data;
  data.testbed = testbed.name;
  data.dataset = dataset;
  data.seed = options.seed;
  data.errors = options.errors.value_or(testbed.default_errors);
  data.errors.validate(testbed.nominal.n_joints());
  data.sigma_rep_spec_m = testbed.sigma_rep_spec_m;
  data.has_config = testbed.kind == TestbedKind::kLwr4;
  data.marker_flange_m = options.marker_flange_m;
  data.body_mount_rotation_rad = options.body_mount_rotation_rad;
  data.time_s = options.time_s;
  data.events = options.events;

  data.locations = plan_dataset(testbed, dataset);
  if (testbed.kind == TestbedKind::kUr5) {
    plan_ur_visits(testbed, data);
  } else {
    plan_lwr_visits(testbed, data);
  }
  detail::acquire_visits(testbed, data);
  return data;
}

namespace detail {

void acquire_visits(const Testbed& testbed, SimulatedDataset& data) {
  Random robot_rng = Random::stream(data.seed, kRobotStream);
  data.robot = draw_robot_errors(data.errors.robot, testbed.nominal.n_joints(), robot_rng);
  // The real marker: the controller's tool unless the cell's offset differs (hand-eye scenario).
  Eigen::Isometry3d T_flange_marker = testbed.nominal.T_flange_tcp();
  if (data.marker_flange_m) {
    VRREG_THROW_UNLESS(data.marker_flange_m->allFinite(), "the marker offset must be finite");
    T_flange_marker.translation() = *data.marker_flange_m;
  }
  data.events.validate();
  VRREG_THROW_UNLESS(std::isfinite(data.time_s), "the acquisition time must be finite");
  RobotErrorModel at_time = data.errors.robot;  // warmed up (or cooled) by time_s
  at_time.link_growth += data.events.thermal.growth_at(data.time_s);
  const SimulatedRobot robot(testbed.nominal.with_tool(T_flange_marker), at_time, data.robot);
  data.T_robot_sensor = tracker_pose(data.errors.tracker, testbed.volume_centre_m);
  if (data.time_s >= data.events.bump_time_s && data.events.bump_rms_m > 0.0) {
    const RigidTransform T_after_before =
        testbed_bump(testbed, data.T_robot_sensor, data.events.bump_rms_m, data.seed);
    data.T_robot_sensor = data.T_robot_sensor * T_after_before.inverse();
  }
  const RigidTransform T_sensor_robot = data.T_robot_sensor.inverse();

  // Another time, other noise: the streams of time 0 are those of every run before time existed.
  const auto dataset_index = static_cast<std::uint64_t>(data.dataset);
  const std::uint64_t at = data.time_s == 0.0 ? 0 : std::bit_cast<std::uint64_t>(data.time_s);
  Random visit_rng = Random::stream(data.seed ^ at, kVisitStream + dataset_index);
  Random reading_rng = Random::stream(data.seed ^ at, kReadingStream + dataset_index);
  Random orientation_rng = Random::stream(data.seed ^ at, kOrientationStream + dataset_index);
  const TrackerModel& tracker = data.errors.tracker;
  const bool rigid_body = tracker.rigid_body_radius_m > 0.0;
  VRREG_THROW_UNLESS(!data.body_mount_rotation_rad || data.body_mount_rotation_rad->allFinite(),
                     "the rigid body's mounting rotation must be finite");
  const Eigen::Matrix3d R_tool_body = data.body_mount_rotation_rad
                                          ? rotation_exp(*data.body_mount_rotation_rad)
                                          : Eigen::Matrix3d::Identity();
  const Eigen::Vector3d orientation_sigma_rad = orientation_noise_sigma_rad(tracker);
  const int k = tracker.readings_per_location;
  data.readings.reserve(data.visits.size() * static_cast<std::size_t>(k));
  // The arm visits in the order of data.visits, starting from home: that path decides on which
  // side of its play each joint arrives (lost motion).
  JointApproach approach(testbed.home_q_rad);
  for (std::size_t v = 0; v < data.visits.size(); ++v) {
    SimulatedVisit& visit = data.visits[v];
    if (visit.via_q_rad) (void)approach.move_to(*visit.via_q_rad);
    const kinematics::JointVector& sign = approach.move_to(visit.q_rad);
    visit.tcp_m = robot.visit_tcp_m(visit.q_rad, visit_rng, sign);
    if (rigid_body) {
      visit.R_commanded = kinematics::forward_kinematics(robot.nominal(), visit.q_rad).linear();
      visit.R_true = robot.actual_rotation(visit.q_rad, sign);
      if (data.body_mount_rotation_rad) visit.R_true = visit.R_true * R_tool_body;
    }
    for (int r = 0; r < k; ++r) {
      data.readings.push_back(
          {static_cast<int>(v), r,
           tracker_reading(T_sensor_robot, tracker.noise_sigma_m, visit.tcp_m, reading_rng)});
      if (rigid_body) {
        data.readings.back().q_sensor_marker = tracker_orientation_reading(
            T_sensor_robot, orientation_sigma_rad, visit.R_true, orientation_rng);
      }
    }
  }
}

}  // namespace detail

Points3 visit_means_m(const SimulatedDataset& data) {
  Points3 sum = Points3::Zero(3, static_cast<Eigen::Index>(data.visits.size()));
  Eigen::VectorXd count = Eigen::VectorXd::Zero(sum.cols());
  for (const SimulatedReading& r : data.readings) {
    sum.col(r.visit) += r.sensor_m;
    count(r.visit) += 1.0;
  }
  for (Eigen::Index v = 0; v < sum.cols(); ++v) {
    if (count(v) > 0.0) sum.col(v) /= count(v);
  }
  return sum;
}

}  // namespace vrreg::simulation
