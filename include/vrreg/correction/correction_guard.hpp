// SPDX-License-Identifier: Apache-2.0
#pragma once
// Whether a fitted correction is applied at all: a correction whose cross-validated error is not
// below the error of no correction, on the same held-out fiducials, would move targets further
// from where they are. Such a corrector is kept (its figures are printed and saved) but answers
// every target uncorrected, status StencilStatus::kNotBetterThanNone.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "vrreg/correction/corrector_data.hpp"
#include "vrreg/correction/cross_validation.hpp"
#include "vrreg/correction/interpolation.hpp"

namespace vrreg {

/// Fewer held-out fold units than this leave a correction unjudged (applied): the two RMS of a
/// handful of fiducials differ by chance as much as by the method (the field models' minimum).
inline constexpr Eigen::Index kMinJudgedUnits = 12;

struct CorrectionGuard {
  /// False: no cross-validation could judge the method (too few fiducials for folds); it is
  /// applied, and `note` says why it was not judged.
  bool judged = false;
  bool applied = true;
  /// Whose cross-validation judged: the method itself, or for a stencil no fold can carry (a
  /// complete grid, the octuplet) the trilinear stencil on the same fiducials.
  InterpolationMethod judged_by = InterpolationMethod::kTrilinear;
  double cv_rms_m = 0.0;           ///< held-out RMS (3D) of the correction [m]
  double uncorrected_rms_m = 0.0;  ///< RMS (3D) of no correction on the same fiducials [m]
  Eigen::Index n_judged = 0;       ///< held-out fiducials both RMS are over
  std::string note{};
};

/// The guard from one method's cross-validation row: its RMS against the RMS of the measured
/// corrections (Eq. 6's epsilon_j, what an uncorrected target is off by) over the fiducials the
/// row predicted, each fold unit (`unit_of`) weighing as one fiducial. Applied when the CV RMS is
/// below the uncorrected one (or both are 0); a row that is not applicable, or that predicted
/// fewer than kMinJudgedUnits fold units, leaves it unjudged.
[[nodiscard]] CorrectionGuard judge_correction(const CrossValidationRow& row,
                                               const CorrectorData& data,
                                               const std::vector<Eigen::Index>& unit_of);

}  // namespace vrreg
