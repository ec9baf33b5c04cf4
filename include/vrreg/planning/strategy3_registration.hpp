// SPDX-License-Identifier: Apache-2.0
#pragma once
// Strategy 3 of Procedure 2 (paper section 4.4), registration half: one registration {R, tau}
// for every arm configuration, from the 8 fiducials at the corners of the whole work volume, each
// in a randomly chosen configuration; then the corrections (Eq. 6) of all fiducials against it.
#include <array>
#include <cstdint>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg::planning {

/// Options of register_volume_corners.
struct Strategy3Options {
  std::uint64_t seed = 1;  ///< seeds vrreg::Random, which picks each corner's configuration
  double match_tolerance_m = 1e-6;  ///< how far a fiducial may be from a corner position [m]
  RegistrationOptions registration{};
  /// Throws InputError on a tolerance that is not > 0 or on bad registration options.
  void validate() const;
};

/// One registration for all configurations (Strategy 3).
struct Strategy3Registration {
  RegistrationResult registration{};  ///< Eq. 2 from the 8 volume-corner fiducials
  /// Index into the input of the fiducial used at each volume corner (x fastest, then y, z).
  std::array<std::size_t, 8> corner_fiducials{};
  Points3 corrections_sensor_m{};  ///< epsilon_j (Eq. 6) of every input fiducial, sensor frame [m]
};

/// Strategy 3 (section 4.4): at each corner of the bounding box of the fiducials' nominal robot
/// positions (the nearest position, see CornerCandidates::volume_corners), one of the fiducials
/// there (all its arm configurations) drawn at random with options.seed; registers those 8
/// (Eq. 2) and computes epsilon_j (Eq. 6) for all `fiducials` [m]. Throws InputError on fewer than
/// 8 fiducials, a fiducial without a robot position, or a degenerate volume.
Strategy3Registration register_volume_corners(const std::vector<Location>& fiducials,
                                              const Strategy3Options& options);

}  // namespace vrreg::planning
