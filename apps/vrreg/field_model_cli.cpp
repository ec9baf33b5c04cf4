// SPDX-License-Identifier: Apache-2.0
#include "field_model_cli.hpp"

#include <cstdio>

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
      std::printf("    %-10s   not applicable: %s\n", to_string(row.method), row.note.c_str());
      continue;
    }
    std::printf("    %-10s   %8s mm  %8s mm (%5lld)   %s mm   %7.2f s%s\n",
                to_string(row.method), format_mm(row.rms_common_m).c_str(),
                format_mm(row.rms_m).c_str(), static_cast<long long>(row.n_predicted),
                format_mm3(row.rms_axis_m).c_str(), row.seconds,
                row.method == cv.chosen ? "   <- chosen" : "");
  }
}

nlohmann::json cross_validation_json(const CrossValidation& cv) {
  nlohmann::json j;
  j["folds"] = cv.folds;
  j["seed"] = cv.seed;
  j["chosen"] = to_string(cv.chosen);
  j["n_common"] = cv.n_common;
  nlohmann::json rows = nlohmann::json::array();
  for (const CrossValidationRow& row : cv.rows) {
    nlohmann::json r;
    r["method"] = to_string(row.method);
    r["applicable"] = row.applicable;
    if (row.applicable) {
      r["rms_common_mm"] = units::m_to_mm(row.rms_common_m);
      r["rms_mm"] = units::m_to_mm(row.rms_m);
      r["rms_axis_mm"] = {units::m_to_mm(row.rms_axis_m.x()), units::m_to_mm(row.rms_axis_m.y()),
                          units::m_to_mm(row.rms_axis_m.z())};
      r["n_predicted"] = row.n_predicted;
    } else {
      r["note"] = row.note;
    }
    rows.push_back(r);
  }
  j["rows"] = rows;
  return j;
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

void add_predicted_sd_json(const TargetCorrection& c,
                           const std::optional<UncertaintyCalibration>& calibration,
                           nlohmann::json& j) {
  const PredictedSdSummary sd = summarize_predicted_sd(c.predicted_sd_m);
  if (sd.n == 0) return;
  j["predicted_sd_median_mm"] = units::m_to_mm(sd.median_m);
  j["predicted_sd_max_mm"] = units::m_to_mm(sd.max_m);
  if (calibration && calibration->n > 0) {
    j["calibration"] = {{"n", calibration->n},
                        {"rms_tre_over_sd", calibration->rms_ratio},
                        {"within_2sd", calibration->within_2sigma}};
  }
}

const char* why_not_correctable(const TargetCorrection& c) {
  const bool none = !c.stencils.empty() && c.stencils.front().status == StencilStatus::kTooFewFiducials;
  return none ? "too few fiducials" : "outside the fiducials";
}

}  // namespace vrreg::cli
