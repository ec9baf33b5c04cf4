// SPDX-License-Identifier: Apache-2.0
#pragma once
// Whether predicted uncertainties are honest: measured errors against their predicted sd.
#include <Eigen/Core>

namespace vrreg {

/// How well the predicted uncertainty matched the measured TRE over the corrected targets.
struct UncertaintyCalibration {
  Eigen::Index n = 0;          ///< targets with a finite prediction and a measured TRE
  double rms_ratio = 0.0;      ///< RMS of TRE / sigma_pred (1 when calibrated)
  double within_2sigma = 0.0;  ///< fraction of targets with TRE <= 2 sigma_pred
};

/// The finite predicted sd values of a set of points [m]: how many, their median and max.
struct PredictedSdSummary {
  Eigen::Index n = 0;
  double median_m = 0.0;
  double max_m = 0.0;
};
PredictedSdSummary summarize_predicted_sd(const Eigen::Ref<const Eigen::VectorXd>& sd_m);

/// Over the targets whose sigma_pred (3D, sqrt of the per-axis variances) [m] is finite and > 0;
/// n = 0 when sd_m is empty. For an isotropic Gaussian error, rms_ratio -> 1 and within_2sigma
/// -> P(chi^2_3 <= 12) = 0.993.
UncertaintyCalibration uncertainty_calibration(const Eigen::Ref<const Eigen::VectorXd>& tre_m,
                                               const Eigen::Ref<const Eigen::VectorXd>& sd_m);

}  // namespace vrreg
