// SPDX-License-Identifier: Apache-2.0
#pragma once
// How RRBC carries fiducial corrections to a target (paper Eq. 7): the method and its settings.
#include <string>

namespace vrreg {

/// How fiducial corrections are carried to a target (paper Eq. 7).
enum class InterpolationMethod {
  kLinear,     ///< RRBC's linear weights: grid on a complete regular grid, else scattered
  kOctuplet,   ///< 8 cube corners around the target's nominal position, weights 1/8
  kGrid,       ///< trilinear weights in the grid cell holding the registered target position
  kScattered,  ///< barycentric weights in the enclosing Delaunay tetrahedron
  // Beyond the paper (docs/field-models.md): models of the whole correction field.
  kTrilinear,  ///< trilinear on the finest lattice, its empty nodes filled from their neighbours
  kKriging,    ///< universal kriging (Gaussian process) with a quadratic trend, per axis
  kRbf,        ///< polyharmonic radial basis functions, smoothing by cross-validation
  kJoint,      ///< joint-space error model through the robot's Jacobian (needs joints, robot)
  kAuto,       ///< the applicable method with the lowest K-fold cross-validated error
};

/// Interpolation settings, stored with a model as the default of evaluate and correct.
struct InterpolationSettings {
  InterpolationMethod method = InterpolationMethod::kLinear;
  double cube_edge_m = 0.0;         ///< octuplet cube edge [m]; 0 = not set
  double match_tolerance_m = 1e-6;  ///< how close a fiducial must be to a cube corner / grid node
  /// Throws InputError on octuplet without a cube edge, or a tolerance or edge that is not finite
  /// and positive.
  void validate() const;
};

/// Lower-case name of a method as used on the command line and in files.
const char* to_string(InterpolationMethod method);
/// Parses a method's name (to_string); throws InputError otherwise. `legacy_auto`: a model file
/// written before the field models, whose "auto" meant what "linear" means now.
InterpolationMethod parse_interpolation_method(const std::string& name, bool legacy_auto = false);
/// Whether the method models the whole field (kriging, rbf, joint, trilinear, auto) rather than
/// the paper's stencils of Eq. 7.
bool is_field_model(InterpolationMethod method);

}  // namespace vrreg
