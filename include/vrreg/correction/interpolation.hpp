#pragma once
// How RRBC carries fiducial corrections to a target (paper Eq. 7): the method and its settings.
#include <string>

namespace vrreg {

/// How fiducial corrections are carried to a target (paper Eq. 7).
enum class InterpolationMethod {
  kAuto,       ///< grid when the fiducials hold a complete regular grid, else scattered
  kOctuplet,   ///< 8 cube corners around the target's nominal position, weights 1/8
  kGrid,       ///< trilinear weights in the grid cell holding the registered target position
  kScattered,  ///< barycentric weights in the enclosing Delaunay tetrahedron
};

/// Interpolation settings, stored with a model as the default of evaluate and correct.
struct InterpolationSettings {
  InterpolationMethod method = InterpolationMethod::kAuto;
  double cube_edge_m = 0.0;         ///< octuplet cube edge [m]; 0 = not set
  double match_tolerance_m = 1e-6;  ///< how close a fiducial must be to a cube corner / grid node
  /// Throws InputError on octuplet without a cube edge, or a tolerance or edge that is not finite
  /// and positive.
  void validate() const;
};

/// Lower-case name of a method as used on the command line and in files.
const char* to_string(InterpolationMethod method);
/// Parses "auto", "octuplet", "grid" or "scattered"; throws InputError otherwise.
InterpolationMethod parse_interpolation_method(const std::string& name);

}  // namespace vrreg
