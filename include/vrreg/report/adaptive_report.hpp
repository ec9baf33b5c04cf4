// SPDX-License-Identifier: Apache-2.0
#pragma once
// The adaptive-planning study's page (`vrreg adaptive-study --report FILE`, docs/report.md): the
// done-when table, every plan's fiducials, readings, robot time and RMS_T, and RMS_T against
// fiducials (the adaptive loop per seed, Procedure 1 per cube edge, the full grid).
#include "vrreg/experiments/adaptive_study.hpp"
#include "vrreg/report/page.hpp"

namespace vrreg::report {

/// The page for a study's result.
ReportPage adaptive_study_page(const experiments::AdaptiveStudyResult& result);

}  // namespace vrreg::report
