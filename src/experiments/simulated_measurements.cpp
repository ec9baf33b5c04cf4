#include "vrreg/experiments/simulated_measurements.hpp"

namespace vrreg::experiments {

MeasurementSet to_measurement_set(const simulation::SimulatedDataset& data) {
  MeasurementSet set;
  set.source = data.testbed + " " + simulation::to_string(data.dataset) + " seed " +
               std::to_string(data.seed);
  const bool lwr = data.dataset == simulation::Dataset::kGrid;
  set.has_config = lwr;
  set.has_repeat = true;
  set.locations.resize(data.visits.size());
  for (std::size_t v = 0; v < data.visits.size(); ++v) {
    const simulation::SimulatedVisit& visit = data.visits[v];
    const simulation::PlannedLocation& planned =
        data.locations[static_cast<std::size_t>(visit.location)];
    Location& loc = set.locations[v];
    loc.point = planned.point;
    loc.role = planned.role;
    if (lwr) loc.config = visit.config;
    loc.robot_m = planned.robot_m;
    loc.q_rad.assign(visit.q_rad.data(), visit.q_rad.data() + visit.q_rad.size());
    set.n_joints = static_cast<int>(visit.q_rad.size());
  }
  // Welford's running mean and squared deviations, as the CSV reader does.
  for (const simulation::SimulatedReading& r : data.readings) {
    Location& loc = set.locations[static_cast<std::size_t>(r.visit)];
    ++loc.n_readings;
    const Eigen::Vector3d delta = r.sensor_m - loc.sensor_m;
    loc.sensor_m += delta / loc.n_readings;
    loc.sensor_sq_dev_m2 += delta.cwiseProduct(r.sensor_m - loc.sensor_m);
  }
  return set;
}

}  // namespace vrreg::experiments
