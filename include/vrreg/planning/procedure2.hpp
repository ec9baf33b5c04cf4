// SPDX-License-Identifier: Apache-2.0
#pragma once
// Procedure 2 (paper section 4.4): how a model treats the robot's arm configurations.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "vrreg/kinematics/joint_distance.hpp"

namespace vrreg::planning {

/// The strategies of section 4.4 (the numbers are the paper's).
enum class Strategy {
  kNone = 0,           ///< rows as given: one registration, no configuration handling
  kAsListed = 1,       ///< labels as the IK lists them; one registration per label
  kAlongPath = 2,      ///< labels re-assigned along the visiting path; one registration per label
  kVolumeCorners = 3,  ///< one registration from the volume corners; nearest-configuration stencils
};

/// The paper's number of a strategy (0 for none).
int strategy_number(Strategy strategy);
/// The strategy with the paper's number 0..3; throws InputError otherwise.
Strategy strategy_from_number(int number);

/// How a model was built with respect to arm configurations.
struct Procedure2 {
  Strategy strategy = Strategy::kNone;
  kinematics::JointNorm joint_norm = kinematics::JointNorm::kL2;  ///< Strategies 2 and 3
  std::optional<std::uint64_t> seed{};  ///< Strategy 3: seed of the random corner configurations
  /// Strategy 3: the fiducials (indices into the model's) of the one registration (Eq. 2).
  std::vector<std::size_t> registration_fiducials{};
};

}  // namespace vrreg::planning
