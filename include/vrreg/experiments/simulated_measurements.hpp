// SPDX-License-Identifier: Apache-2.0
#pragma once
// A simulated dataset seen the way a measurement file is read (design.md 6): one location per
// visit with its repeat readings averaged, in visiting order.
#include "vrreg/core/measurement.hpp"
#include "vrreg/simulation/acquisition.hpp"

namespace vrreg::experiments {

/// One Location per visit of `data` (index = visit index): nominal robot position, mean sensor
/// reading, per-axis squared deviations, joints, the configuration label for the LWR, and
/// source_line = visit index + 1 (the visiting order, for octuplet corners measured twice).
MeasurementSet to_measurement_set(const simulation::SimulatedDataset& data);

}  // namespace vrreg::experiments
