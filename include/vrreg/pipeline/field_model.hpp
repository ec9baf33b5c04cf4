#pragma once
// Beyond the paper (docs/field-models.md): models of the whole correction field — trilinear on
// the filled lattice, kriging, radial basis functions, the joint-space error model — compared by
// K-fold cross-validation on the fiducials, each with a predicted uncertainty per target.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/correction/interpolation.hpp"
#include "vrreg/metrics/uncertainty_calibration.hpp"

namespace vrreg {

/// One method's K-fold cross-validation on the fiducials: each fold's corrections predicted by
/// the model fitted on the other folds, at the fold's registered positions.
struct CrossValidationRow {
  InterpolationMethod method = InterpolationMethod::kTrilinear;
  bool applicable = false;  ///< false: `note` says why (e.g. no joints, not a lattice)
  std::string note;
  double rms_m = 0.0;  ///< RMS over the predicted fiducials of |predicted - measured| (3D) [m]
  Eigen::Vector3d rms_axis_m = Eigen::Vector3d::Zero();  ///< the same per sensor axis [m]
  Eigen::Index n_predicted = 0;  ///< fiducials the held-out models could predict
  /// RMS (3D) over the fiducials every compared method predicted: what `auto` compares [m].
  double rms_common_m = 0.0;
  /// |predicted - measured|^2 per fiducial [m^2]; NaN where not predicted.
  Eigen::VectorXd squared_error_m2;
  double seconds = 0.0;          ///< fit and predict over all folds (wall time)
};

/// The table `--interpolation auto` prints, and its choice: the lowest RMS over the fiducials
/// every compared method predicted (lattice and Delaunay methods cannot predict at the layout's
/// edge; comparing each over its own subset would favour them).
struct CrossValidation {
  int folds = 5;
  Eigen::Index n_common = 0;  ///< fiducials in the common comparison
  std::uint64_t seed = 1;  ///< of the shuffle that assigns fiducials to folds
  std::vector<CrossValidationRow> rows;
  InterpolationMethod chosen = InterpolationMethod::kTrilinear;
};

}  // namespace vrreg
