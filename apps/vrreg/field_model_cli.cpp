// SPDX-License-Identifier: Apache-2.0
#include "field_model_cli.hpp"

#include <cstdio>

#include "option_flags.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::cli {

void print_cross_validation(const CrossValidation& cv) {
  if (cv.folds == 1) {
    std::printf("  cross-validation              one held-out sample (a large cell: more than %lld "
                "fiducials; fold shuffle seed %llu); compared on the %lld fiducials every "
                "method predicted\n",
                static_cast<long long>(kLargeCellFiducials),
                static_cast<unsigned long long>(cv.seed), static_cast<long long>(cv.n_common));
  } else {
    std::printf("  cross-validation              %d folds over the fiducials (fold shuffle seed "
                "%llu); compared on the %lld fiducials every method predicted\n",
                cv.folds, static_cast<unsigned long long>(cv.seed),
                static_cast<long long>(cv.n_common));
  }
  std::printf("    method       compared     own (predicted)             x / y / z                     "
              "time\n");
  for (const CrossValidationRow& row : cv.rows) {
    if (!row.applicable) {
      std::printf("    %-10s   not applicable: %s\n", to_string(row.method),
                  with_flags(row.note).c_str());
      continue;
    }
    std::printf("    %-10s   %8s mm  %8s mm (%5lld)   %s mm   %7.2f s%s\n",
                to_string(row.method), format_mm(row.rms_common_m).c_str(),
                format_mm(row.rms_m).c_str(), static_cast<long long>(row.n_predicted),
                format_mm3(row.rms_axis_m).c_str(), row.seconds,
                row.method == cv.chosen ? "   <- chosen" : "");
  }
}

void print_predicted_sd(const TargetCorrection& c,
                        const std::optional<UncertaintyCalibration>& calibration) {
  const PredictedSdSummary sd = summarize_predicted_sd(c.predicted_sd_m);
  if (sd.n == 0) return;
  std::printf("  predicted sd (1 sigma, 3D)    median %s mm, max %s mm\n",
              format_mm(sd.median_m).c_str(), format_mm(sd.max_m).c_str());
  if (calibration && calibration->n > 0) {
    std::printf("  calibration of sigma_pred     RMS of TRE / sigma_pred %.2f (1 = calibrated), "
                "%.0f %% within 2 sigma\n",
                calibration->rms_ratio, 100.0 * calibration->within_2sigma);
  }
}

const char* why_not_correctable(const TargetCorrection& c) {
  const bool none =
      !c.stencils.empty() && c.stencils.front().status == StencilStatus::kTooFewFiducials;
  return none ? "too few fiducials" : "outside the fiducials";
}

}  // namespace vrreg::cli
