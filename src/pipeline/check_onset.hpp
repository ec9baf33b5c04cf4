// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal to pipeline: a change found today, told from the checks before it (CheckOptions::
// earlier): at once (a step: a bump) or grown over them (a ramp: a drift).
#include <Eigen/Core>

#include "vrreg/pipeline/check.hpp"

namespace vrreg::pipeline_detail {

/// Fills out.onset and out.onset_times from options.earlier (the points matched to today's by
/// point and config) and says it in out.statistics.message; a rigid change that grew over the
/// earlier checks becomes a smooth change (a drift, rigid at the monitor points so far).
/// `baseline_mean_sd_m`: the sd of the registration's mean per axis, per point read today.
void classify_onset(const CheckOptions& options, const Eigen::VectorXd& baseline_mean_sd_m,
                    CheckResult& out);

}  // namespace vrreg::pipeline_detail
