#pragma once
// The registration model that `register` writes and `evaluate` / `correct` read: the transform,
// the fiducials it came from, their RRBC corrections (Eq. 6) and how to interpolate them (Eq. 7).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/core/types.hpp"

namespace vrreg {

/// How fiducial corrections are carried to a target (paper Eq. 7).
enum class InterpolationMethod {
  kAuto,       ///< grid when the fiducials hold a complete regular grid, else scattered
  kOctuplet,   ///< 8 cube corners around the target's nominal position, weights 1/8
  kGrid,       ///< trilinear weights in the grid cell holding the registered target position
  kScattered,  ///< barycentric weights in the enclosing Delaunay tetrahedron
};

/// Interpolation settings stored with a model and overridable on the command line.
struct InterpolationSettings {
  InterpolationMethod method = InterpolationMethod::kAuto;
  double cube_edge_m = 0.0;           ///< octuplet cube edge; 0 = not set
  double match_tolerance_m = 1e-6;    ///< how close a fiducial must be to a cube corner / grid node
};

/// Procedure 2 (paper section 4.4): how a model treats arm configurations.
struct ConfigurationStrategy {
  int strategy = 0;               ///< 0: rows as in the file (no strategy); else 1, 2 or 3
  std::string joint_norm = "l2";  ///< Strategies 2 and 3: joint-space distance, "l2" or "linf"
  std::optional<std::uint64_t> seed;  ///< Strategy 3: seed of the random volume-corner choice
  std::vector<std::size_t> registration_fiducials;  ///< Strategy 3: fiducials registered (Eq. 2)
};

/// Everything needed to correct new targets: the registration and the fiducial corrections.
struct RegistrationModel {
  static constexpr int kFormatVersion = 1;
  RigidTransform T_robot_sensor;
  std::vector<Location> fiducials;   ///< nominal robot and averaged sensor positions, labels, joints
  Points3 corrections_sensor_m;      ///< epsilon_j (Eq. 6), one column per fiducial, sensor frame
  InterpolationSettings interpolation;
  std::optional<int> config;         ///< configuration label the model was built for, if any
  /// Strategy 2: `fiducials` carry Strategy 2 labels. Strategy 3: `fiducials` hold every arm
  /// configuration, corrected against the one registration from `registration_fiducials`.
  ConfigurationStrategy procedure2;
  double fre_m = 0.0;                ///< FRE of the registration (Eq. 2)
  double sigma_l_m = 0.0;            ///< sigma_L over fiducial pairs (Eq. 1)
  std::string source;                ///< the fiducial file it came from
};

/// Lower-case name of a method as used on the command line and in files.
const char* to_string(InterpolationMethod method);
/// Parses "auto", "octuplet", "grid" or "scattered"; throws InputError otherwise.
InterpolationMethod parse_interpolation_method(const std::string& name);

}  // namespace vrreg
