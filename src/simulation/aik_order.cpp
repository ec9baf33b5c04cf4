// SPDX-License-Identifier: Apache-2.0
#include "vrreg/simulation/aik_order.hpp"

#include <algorithm>
#include <utility>

#include "vrreg/kinematics/joint_distance.hpp"

namespace vrreg::simulation {

std::vector<kinematics::IkSolution> aik_order(std::vector<kinematics::IkSolution> solutions,
                                              const kinematics::JointRef& home_q_rad) {
  std::vector<std::pair<double, std::size_t>> key;
  key.reserve(solutions.size());
  for (std::size_t s = 0; s < solutions.size(); ++s) {
    key.emplace_back(kinematics::joint_distance_l2(solutions[s].q_rad, home_q_rad), s);
  }
  std::stable_sort(key.begin(), key.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<kinematics::IkSolution> ordered;
  ordered.reserve(solutions.size());
  for (const auto& k : key) ordered.push_back(std::move(solutions[k.second]));
  return ordered;
}

}  // namespace vrreg::simulation
