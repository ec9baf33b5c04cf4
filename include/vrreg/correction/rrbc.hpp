// SPDX-License-Identifier: Apache-2.0
#pragma once
// RRBC (paper section 3.2): corrections to the fiducials (Eq. 6) and their interpolation (Eq. 7).
#include <Eigen/Core>
#include <array>

#include "vrreg/core/types.hpp"

namespace vrreg {

/// epsilon_j = R' Y_j - R' tau - X_j (Eq. 6, divided by the scale when there is one): the shift
/// that puts each measured fiducial X_j [m, sensor] where the registration says its robot
/// position Y_j [m, robot] is. Returns one column per fiducial, sensor frame [m].
Points3 fiducial_corrections(const SimilarityTransform& T_robot_sensor,
                             const ConstPoints3Ref& fiducials_sensor_m,
                             const ConstPoints3Ref& fiducials_robot_m);

/// Why a target has no interpolated correction.
enum class StencilStatus {
  kOk,             ///< weights found
  kOutsideGrid,    ///< grid: registered position outside the grid
  kOutsideHull,    ///< scattered: outside the convex hull of the fiducials
  kMissingCorner,  ///< octuplet: a cube corner has no fiducial
  /// A model of the whole field (kriging, rbf, joint): outside the fiducials' box (and, for the
  /// joint model, the joint ranges they were measured at, or in a gap between the values of a
  /// joint that nothing measured).
  kOutsideSupport,
  /// Outside the support (any of the statuses above but a hole inside the layout), corrected
  /// anyway because the caller asked (extrapolate): the correction at the nearest point of the
  /// support, its sd widened for the distance (docs/uncertainty.md).
  kExtrapolated,
  /// Fewer fiducials than any correction method needs (scattered's 4): uncorrected.
  kTooFewFiducials,
  /// The method's cross-validated error on the fiducials is not below the uncorrected one:
  /// applying it would make the point worse on average, so it is answered uncorrected.
  kNotBetterThanNone,
  /// The fiducials lie in a plane or on a line (scattered, linear): no tetrahedron holds any
  /// point, so every point is answered uncorrected (the registration itself needs only three
  /// points off a line).
  kFlatLayout,
};

/// Whether a target with this status was corrected (ok, or extrapolated on request).
[[nodiscard]] inline bool is_corrected(StencilStatus status) {
  return status == StencilStatus::kOk || status == StencilStatus::kExtrapolated;
}

/// The fiducials and weights that carry corrections to one target (Eq. 7): sum of weights = 1.
struct Stencil {
  std::array<Eigen::Index, 8> fiducial{};  ///< column indices into the fiducial set
  std::array<double, 8> weight{};
  int size = 0;  ///< entries in use (8 grid/octuplet, 4 scattered)
  StencilStatus status = StencilStatus::kOk;
};

/// epsilon(T_X) = sum_n w_n epsilon_n (Eq. 7) for a stencil whose status is kOk.
inline Eigen::Vector3d interpolate_correction(const Stencil& stencil,
                                              const ConstPoints3Ref& corrections_sensor_m) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < stencil.size; ++k) {
    sum += stencil.weight[static_cast<std::size_t>(k)] *
           corrections_sensor_m.col(stencil.fiducial[static_cast<std::size_t>(k)]);
  }
  return sum;
}

const char* to_string(StencilStatus status);

}  // namespace vrreg
