// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/simulated_measurements.hpp"

#include <algorithm>

#include "vrreg/core/rotation.hpp"

namespace vrreg::experiments {

MeasurementSet to_measurement_set(const simulation::SimulatedDataset& data) {
  MeasurementSet set;
  set.source = data.testbed + " " + simulation::to_string(data.dataset) + " seed " +
               std::to_string(data.seed);
  set.has_config = data.has_config;
  set.has_repeat = true;
  set.locations.resize(data.visits.size());
  // With via points the simulation CSV names the joints each visit came from (from_q columns).
  const bool with_from =
      std::any_of(data.visits.begin(), data.visits.end(),
                  [](const simulation::SimulatedVisit& v) { return v.via_q_rad.has_value(); });
  set.approach = data.visits.empty() || data.visits.front().q_rad.size() == 0
                     ? ApproachSource::kNone
                 : with_from ? ApproachSource::kFromJoints
                             : ApproachSource::kRowOrder;
  // Approach directions along the visits, as the CSV reader takes them from the rows: the first
  // visit's are unknown (a file does not say where the arm stood before).
  Eigen::VectorXd sign;
  for (std::size_t v = 0; v < data.visits.size(); ++v) {
    const kinematics::JointVector& q = data.visits[v].q_rad;
    if (v == 0 || with_from) sign = Eigen::VectorXd::Zero(q.size());
    if (with_from) {
      const kinematics::JointVector& via = data.visits[v].via_q_rad.value_or(
          v > 0 ? data.visits[v - 1].q_rad : q);
      update_approach_sign(via, q, sign);
    } else if (v > 0) {
      update_approach_sign(data.visits[v - 1].q_rad, q, sign);
    }
    set.locations[v].approach_sign.assign(sign.data(), sign.data() + sign.size());
  }
  for (std::size_t v = 0; v < data.visits.size(); ++v) {
    const simulation::SimulatedVisit& visit = data.visits[v];
    const simulation::PlannedLocation& planned =
        data.locations[static_cast<std::size_t>(visit.location)];
    Location& loc = set.locations[v];
    loc.point = planned.point;
    loc.role = planned.role;
    if (data.has_config) loc.config = visit.config;
    if (visit.round >= 0) loc.visit = visit.round;
    loc.robot_m = planned.robot_m;
    loc.source_line = v + 1;  // the visiting order, as a file's line order would give it
    loc.q_rad.assign(visit.q_rad.data(), visit.q_rad.data() + visit.q_rad.size());
    set.n_joints = static_cast<int>(visit.q_rad.size());
  }
  // Welford's running mean and squared deviations, as the CSV reader does.
  std::vector<Eigen::Matrix4d> orientation_sums;
  for (const simulation::SimulatedReading& r : data.readings) {
    const auto v = static_cast<std::size_t>(r.visit);
    Location& loc = set.locations[v];
    ++loc.n_readings;
    const Eigen::Vector3d delta = r.sensor_m - loc.sensor_m;
    loc.sensor_m += delta / loc.n_readings;
    loc.sensor_sq_dev_m2 += delta.cwiseProduct(r.sensor_m - loc.sensor_m);
    if (r.q_sensor_marker) {
      orientation_sums.resize(set.locations.size(), Eigen::Matrix4d::Zero());
      if (!loc.q_sensor_marker) loc.q_sensor_marker = r.q_sensor_marker;
      orientation_sums[v] += r.q_sensor_marker->coeffs() * r.q_sensor_marker->coeffs().transpose();
      loc.q_robot_marker = Eigen::Quaterniond(data.visits[v].R_commanded);
    }
  }
  // The mean orientation as the CSV reader takes it (the dominant eigenvector of sum q q').
  for (std::size_t v = 0; v < orientation_sums.size(); ++v) {
    Location& loc = set.locations[v];
    if (!loc.q_sensor_marker) continue;
    const QuaternionMean mean =
        quaternion_mean(orientation_sums[v], loc.n_readings, *loc.q_sensor_marker);
    loc.q_sensor_marker = mean.mean;
    loc.orientation_sq_dev_rad2 = mean.sq_dev_rad2;
  }
  return set;
}

}  // namespace vrreg::experiments
