#pragma once
// A simulated dataset seen the way a measurement file is read (design.md 6): one location per
// visit with its repeat readings averaged, in visiting order.
#include "vrreg/core/measurement.hpp"
#include "vrreg/simulation/acquisition.hpp"

namespace vrreg::experiments {

/// One Location per visit of `data` (index = visit index): nominal robot position, mean sensor
/// reading, per-axis squared deviations, joints, and the configuration label for the LWR.
MeasurementSet to_measurement_set(const simulation::SimulatedDataset& data);

}  // namespace vrreg::experiments
