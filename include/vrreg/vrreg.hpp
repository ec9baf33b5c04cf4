// SPDX-License-Identifier: Apache-2.0
#pragma once
// vrreg's front door: register fiducials, evaluate on targets and correct points, each one call
// (docs/library.md). The modules below it stay available under vrreg/<module>/.
//
//   vrreg::MeasuredPoints fiducials;  // sensor_m and robot_m: 3 x N [m]
//   const vrreg::RegisterResult r = vrreg::register_fiducials(fiducials);
//   const vrreg::CorrectResult c = vrreg::correct(r.model, points);
#include "vrreg/config.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/file_error.hpp"
#include "vrreg/core/types.hpp"
#include "vrreg/pipeline/check.hpp"
#include "vrreg/pipeline/correct.hpp"
#include "vrreg/pipeline/evaluate.hpp"
#include "vrreg/pipeline/interpolation_choice.hpp"
#include "vrreg/pipeline/marker_offset.hpp"
#include "vrreg/pipeline/model.hpp"
#include "vrreg/pipeline/plan_next_correction.hpp"
#include "vrreg/pipeline/points.hpp"
#include "vrreg/pipeline/prepared_corrector.hpp"
#include "vrreg/pipeline/register_fiducials.hpp"
#include "vrreg/pipeline/update.hpp"
