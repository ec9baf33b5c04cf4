// SPDX-License-Identifier: Apache-2.0
#pragma once
// The adaptive loop's stop judged by the correction it will correct with: plan_next predicts
// with kriging (its posterior variance chooses where to measure), but a loop that corrects with
// the joint-space model (or auto) should stop when that model's own predicted sd at the parts
// reaches the goal (docs/adaptive.md).
#include "vrreg/core/measurement.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"
#include "vrreg/planning/plan_next.hpp"

namespace vrreg {

/// PlanNextOptions::correction_sd for fiducials `measured` corrected as `options` registers them
/// (interpolation method, robot for the joint-space model): registers them once when called and
/// returns each part's predicted sd, the part's joints given (CorrectResult's predicted_sd_m).
/// No sd, with the reason, when the registration refuses the fiducials (too few, no joints) or
/// a part is not corrected (outside the method's support). Both are copied in. Throws InputError
/// at once for the joint-space model without a robot, or on measurements without its joints
/// (none, or another count): no number of fiducials mends that.
planning::CorrectionSdAtParts correction_sd_at_parts(MeasurementSet measured,
                                                     RegisterOptions options);

}  // namespace vrreg
