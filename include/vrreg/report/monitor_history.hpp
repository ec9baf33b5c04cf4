// SPDX-License-Identifier: Apache-2.0
#pragma once
// A cell's monitor history on its report page: one point per check (`vrreg check --history`),
// the change at the monitor points against time, coloured by the verdict.
#include <string>
#include <vector>

#include "vrreg/io/monitor_json.hpp"
#include "vrreg/report/page.hpp"

namespace vrreg::report {

/// The section: a chart of change_rms_mm per check in file order (time on the axis as written)
/// and a table of the checks that were not valid. Throws InputError on an empty history.
ReportSection monitor_history_section(const std::vector<io::CheckHistoryRow>& history,
                                      const std::string& history_name);

}  // namespace vrreg::report
