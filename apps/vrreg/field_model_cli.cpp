// SPDX-License-Identifier: Apache-2.0
#include "field_model_cli.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "option_flags.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::cli {

void print_cross_validation(const CrossValidation& cv) {
  if (cv.folds == 1) {
    std::printf("  cross-validation              one held-out sample (a large cell: more than %lld "
                "fiducials; fold shuffle seed %llu); ranked on the %lld fiducials any "
                "method predicted, its misses at their uncorrected error\n",
                static_cast<long long>(kLargeCellFiducials),
                static_cast<unsigned long long>(cv.seed), static_cast<long long>(cv.n_ranked));
  } else {
    std::printf("  cross-validation              %d folds over the fiducials (fold shuffle seed "
                "%llu); ranked on the %lld fiducials any method predicted, its misses at their "
                "uncorrected error\n",
                cv.folds, static_cast<unsigned long long>(cv.seed),
                static_cast<long long>(cv.n_ranked));
  }
  std::printf("    method         ranked     own (predicted)             x / y / z                     "
              "time\n");
  for (const CrossValidationRow& row : cv.rows) {
    if (!row.applicable) {
      std::printf("    %-10s   not applicable: %s\n", to_string(row.method),
                  with_flags(row.note).c_str());
      continue;
    }
    std::printf("    %-10s   %8s mm  %8s mm (%5lld)   %s mm   %7.2f s%s\n",
                to_string(row.method), format_mm(row.rms_ranked_m).c_str(),
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
  if (c.guard && !c.guard->applied) return to_string(StencilStatus::kNotBetterThanNone);
  const StencilStatus first = c.stencils.empty() ? StencilStatus::kOk : c.stencils.front().status;
  if (first == StencilStatus::kTooFewFiducials || first == StencilStatus::kFlatLayout)
    return to_string(first);
  return "outside the fiducials";
}

void print_guard(const CorrectionGuard& guard) {
  if (!guard.judged) {
    std::printf("  correction guard              not judged (%s): applied\n",
                with_flags(guard.note).c_str());
    return;
  }
  std::printf("  correction guard              %s: cross-validated %s mm %s uncorrected %s mm "
              "(%s, %lld held-out fiducials)%s\n",
              guard.applied ? "applied" : "NOT APPLIED", format_mm(guard.cv_rms_m).c_str(),
              guard.applied ? "<" : ">=", format_mm(guard.uncorrected_rms_m).c_str(),
              to_string(guard.judged_by), static_cast<long long>(guard.n_judged),
              guard.applied ? ""
                            : "; every target is answered uncorrected (correction not better "
                              "than none)");
}

void print_lost_motion(const LostMotionTerm& term) {
  constexpr double kArcminPerRad = 180.0 * 60.0 / M_PI;
  std::printf("  lost motion                   %s: %s\n", term.applied ? "applied" : "not applied",
              term.reason.c_str());
  for (Eigen::Index j = 0; j < term.play_rad.size(); ++j) {
    std::printf("    joint %-3lld                   %.3f arcmin (sd %.3f)\n",
                static_cast<long long>(j + 1), kArcminPerRad * term.play_rad(j),
                kArcminPerRad * std::sqrt(std::max(term.covariance_rad2(j, j), 0.0)));
  }
}

void print_orientation_field(const OrientationCorrector& field) {
  constexpr double kMrad = 1e3;
  std::printf("  orientation field             %s: %s\n", to_string(field.method()),
              field.describe().c_str());
  const double cv = kMrad * field.cv_rms_rad();
  const double unc = kMrad * field.uncorrected_rms_rad();
  if (field.cv_rms_rad() > 0.0) {
    std::printf("  orientation RMS angle         %.3f mrad cross-validated, %.3f mrad uncorrected%s\n",
                cv, unc,
                field.applied() ? ""
                                : ": NOT APPLIED (correction not better than none; orientations "
                                  "are answered uncorrected)");
  } else {
    std::printf("  orientation RMS angle         %.3f mrad uncorrected (not cross-validated)\n",
                unc);
  }
  if (field.cross_validation().size() > 1) {
    std::printf("  orientation cross-validation  RMS angle over every fiducial (those a method "
                "cannot predict at their uncorrected angle)\n");
    for (const OrientationCvRow& row : field.cross_validation()) {
      if (!row.applicable) {
        std::printf("    %-10s   not applicable: %s\n", to_string(row.method), row.note.c_str());
        continue;
      }
      std::printf("    %-10s   %8.3f mrad  (%lld predicted)%s\n", to_string(row.method),
                  kMrad * row.rms_rad, static_cast<long long>(row.n_predicted),
                  row.method == field.method() ? "   <- chosen" : "");
    }
  }
}

void print_orientation_correction(const OrientationCorrection& o) {
  constexpr double kMrad = 1e3;
  const auto n = static_cast<long long>(o.status.size());
  long long not_better = 0;
  for (const StencilStatus s : o.status) not_better += s == StencilStatus::kNotBetterThanNone;
  if (not_better > 0 && not_better == o.n_flagged) {
    std::printf("  orientation                   not corrected: %s (the model's orientation "
                "field); robot_q* hold the uncorrected orientation\n",
                to_string(StencilStatus::kNotBetterThanNone));
    return;
  }
  std::printf("  orientation                   %s: %lld of %lld points corrected (orientation_status "
              "says why not)\n",
              to_string(o.method_used), n - o.n_flagged, n);
  const PredictedSdSummary sd = summarize_predicted_sd(o.predicted_sd_rad);
  if (sd.n == 0) return;
  std::size_t over = 0;
  for (std::size_t t = 0; t < o.status.size(); ++t) over += o.sd_over_limit(t) ? 1 : 0;
  std::printf("  predicted angle sd            median %.3f mrad, max %.3f mrad; %zu above the limit "
              "%.3f mrad (angle_sd_over_limit)\n",
              kMrad * sd.median_m, kMrad * sd.max_m, over, kMrad * o.sd_limit_rad);
}

}  // namespace vrreg::cli
