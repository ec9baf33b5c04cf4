// SPDX-License-Identifier: Apache-2.0
#include "vrreg/core/measurement.hpp"

#include "vrreg/core/check.hpp"

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

void update_approach_sign(const Eigen::Ref<const Eigen::VectorXd>& q_from_rad,
                          const Eigen::Ref<const Eigen::VectorXd>& q_to_rad,
                          Eigen::Ref<Eigen::VectorXd> sign_out) {
  VRREG_THROW_UNLESS(q_from_rad.size() == q_to_rad.size() && sign_out.size() == q_to_rad.size(),
                     "approach sign: " << q_from_rad.size() << " from-joints, " << q_to_rad.size()
                                       << " joints, " << sign_out.size() << " signs");
  for (Eigen::Index j = 0; j < q_to_rad.size(); ++j) {
    const double move_rad = q_to_rad(j) - q_from_rad(j);
    if (move_rad > 0.0) sign_out(j) = 1.0;
    if (move_rad < 0.0) sign_out(j) = -1.0;
  }
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
