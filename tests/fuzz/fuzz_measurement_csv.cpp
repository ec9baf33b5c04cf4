// SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the measurement CSV reader (design.md 6), default and sensor-only options.
#include <cmath>
#include <sstream>

#include "fuzz_support.hpp"
#include "vrreg/io/measurement_csv.hpp"

namespace vrreg::fuzz {
namespace {

void check(const MeasurementSet& set) {
  for (const Location& l : set.locations) {
    require(!l.point.empty(), "measurement CSV: accepted an empty point label");
    require(l.n_readings >= 1, "measurement CSV: a location without readings");
    require(l.sensor_m.allFinite() && l.robot_m.allFinite() && l.sensor_sq_dev_m2.allFinite(),
            "measurement CSV: accepted a non-finite value");
    require(static_cast<int>(l.q_rad.size()) == set.n_joints,
            "measurement CSV: joint count differs from the header's");
  }
}

}  // namespace

int measurement_csv(const std::uint8_t* data, std::size_t size) {
  const std::string text = as_text(data, size);
  io::CsvReadOptions sensor_only;
  sensor_only.require_robot = false;
  sensor_only.max_line_bytes = 256;
  for (const io::CsvReadOptions& options : {io::CsvReadOptions{}, sensor_only}) {
    MeasurementSet set;
    if (reads_or_refuses("measurement CSV", [&] {
          std::istringstream in(text);
          set = io::parse_measurement_csv(in, "fuzz.csv", options);
        })) {
      check(set);
    }
  }
  return 0;
}

}  // namespace vrreg::fuzz

VRREG_FUZZ_ENTRY(vrreg::fuzz::measurement_csv)
