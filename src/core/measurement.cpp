// SPDX-License-Identifier: Apache-2.0
#include "vrreg/core/measurement.hpp"

namespace vrreg {

const char* to_string(Role role) {
  switch (role) {
    case Role::kFiducial:
      return "fiducial";
    case Role::kTarget:
      return "target";
    case Role::kMonitor:
      return "monitor";
  }
  return "fiducial";
}

std::vector<std::size_t> MeasurementSet::select(Role role, std::optional<int> config) const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < locations.size(); ++i) {
    const Location& loc = locations[i];
    if (loc.role != role) continue;
    if (config && loc.config != config) continue;
    out.push_back(i);
  }
  return out;
}

Points3 MeasurementSet::robot_points(const std::vector<std::size_t>& indices) const {
  Points3 out(3, static_cast<Eigen::Index>(indices.size()));
  for (std::size_t k = 0; k < indices.size(); ++k) {
    out.col(static_cast<Eigen::Index>(k)) = locations[indices[k]].robot_m;
  }
  return out;
}

Points3 MeasurementSet::sensor_points(const std::vector<std::size_t>& indices) const {
  Points3 out(3, static_cast<Eigen::Index>(indices.size()));
  for (std::size_t k = 0; k < indices.size(); ++k) {
    out.col(static_cast<Eigen::Index>(k)) = locations[indices[k]].sensor_m;
  }
  return out;
}

}  // namespace vrreg
