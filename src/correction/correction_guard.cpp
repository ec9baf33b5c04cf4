// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/correction_guard.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace vrreg {

CorrectionGuard judge_correction(const CrossValidationRow& row, const CorrectorData& data,
                                 const std::vector<Eigen::Index>& unit_of) {
  CorrectionGuard out;
  out.judged_by = row.method;
  if (!row.applicable || row.squared_error_m2.size() != data.size()) {
    out.note = row.note.empty() ? "not cross-validated" : row.note;
    return out;
  }
  // Per fold unit: the mean squared error of its predicted fiducials, corrected and not.
  const Eigen::Index n_units =
      unit_of.empty() ? 0 : *std::max_element(unit_of.begin(), unit_of.end()) + 1;
  Eigen::VectorXd corrected_m2 = Eigen::VectorXd::Zero(n_units);
  Eigen::VectorXd uncorrected_m2 = Eigen::VectorXd::Zero(n_units);
  Eigen::VectorXi count = Eigen::VectorXi::Zero(n_units);
  for (Eigen::Index j = 0; j < data.size(); ++j) {
    if (std::isnan(row.squared_error_m2(j))) continue;
    const Eigen::Index u = unit_of[static_cast<std::size_t>(j)];
    corrected_m2(u) += row.squared_error_m2(j);
    uncorrected_m2(u) += data.corrections_sensor_m.col(j).squaredNorm();
    ++count(u);
    ++out.n_judged;
  }
  double sum_corrected = 0.0;
  double sum_uncorrected = 0.0;
  Eigen::Index units = 0;
  for (Eigen::Index u = 0; u < n_units; ++u) {
    if (count(u) == 0) continue;
    sum_corrected += corrected_m2(u) / count(u);
    sum_uncorrected += uncorrected_m2(u) / count(u);
    ++units;
  }
  if (units < kMinJudgedUnits) {
    out.note = "only " + std::to_string(units) +
               " held-out fiducials predicted, too few to judge the correction by";
    return out;
  }
  out.judged = true;
  out.cv_rms_m = std::sqrt(sum_corrected / static_cast<double>(units));
  out.uncorrected_rms_m = std::sqrt(sum_uncorrected / static_cast<double>(units));
  out.applied = out.cv_rms_m < out.uncorrected_rms_m || out.uncorrected_rms_m == 0.0;
  return out;
}

}  // namespace vrreg
