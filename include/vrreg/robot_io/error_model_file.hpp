// SPDX-License-Identifier: Apache-2.0
#pragma once
// Error-model files of the simulated test beds (vrreg simulate --errors / --write-errors): the
// robot's error spreads and the tracker, in JSON or YAML, units in every key. Absent keys keep
// the test bed's defaults; unknown keys are errors.
//
//   {"format": "vrreg-simulation-errors", "testbed": "ur5",
//    "robot": {"joint_offset_sigma_deg": 0.1, "link_length_sigma_mm": 0.1,
//              "link_offset_sigma_mm": 0.1, "twist_sigma_deg": 0.01,
//              "transmission_amplitude_arcmin": [1.75, ...], "transmission_period_deg": [20, ...],
//              "repeatability_sigma_mm": 0.04, "compliance": false, "link_mass_kg": [...],
//              "joint_stiffness_nm_per_rad": [...], "payload_kg": 0.1},
//    "tracker": {"distance_m": 2.1, "azimuth_deg": 20, "elevation_deg": 30,
//                "noise_sigma_mm": [0.058, 0.058, 0.058], "readings_per_location": 12}}
#include <string>

#include "vrreg/simulation/testbed.hpp"

namespace vrreg::io {

/// The JSON text of `model` for test bed `testbed_name` (every key written).
std::string format_error_model(const simulation::TestbedErrorModel& model,
                               const std::string& testbed_name);

/// Writes format_error_model(model, testbed_name) to `path` atomically.
void write_error_model_file(const std::string& path, const simulation::TestbedErrorModel& model,
                            const std::string& testbed_name);

/// Parses error-model `text` (JSON if it starts with '{', else YAML) over the defaults of
/// `testbed`; `source` names it in errors. Throws FileError naming the key (and line for YAML)
/// on unknown keys, wrong types, wrong list lengths, invalid values or another test bed's name.
simulation::TestbedErrorModel parse_error_model(const std::string& text, const std::string& source,
                                                const simulation::Testbed& testbed);

/// Reads the error-model file at `path` for `testbed` (see parse_error_model).
simulation::TestbedErrorModel read_error_model_file(const std::string& path,
                                                    const simulation::Testbed& testbed);

}  // namespace vrreg::io
