// SPDX-License-Identifier: Apache-2.0
#pragma once
// A simulated dataset as a measurement CSV (design.md 6): one row per tracker reading in visiting
// order, joints and (LWR) configuration labels included, and a comment header that states the
// test bed, dataset, seed, every error parameter and the robot the seed drew.
#include <string>
#include <vector>

#include "vrreg/io/measurement_csv_writer.hpp"
#include "vrreg/simulation/acquisition.hpp"

namespace vrreg::io {

/// The readings of `data` as measurement-file rows (config only for the LWR, repeat always).
std::vector<Reading> simulated_readings(const simulation::SimulatedDataset& data);

/// Comment lines describing `data`: test bed, dataset, seed, counts, tracker pose, error model
/// and drawn robot errors, in mm / deg / arcmin.
std::vector<std::string> simulated_dataset_comments(const simulation::SimulatedDataset& data);

/// Writes `data` as a measurement CSV to `path` atomically (whole or not at all).
void write_simulated_dataset_csv(const std::string& path, const simulation::SimulatedDataset& data);

}  // namespace vrreg::io
