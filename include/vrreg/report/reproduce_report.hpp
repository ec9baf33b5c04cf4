// SPDX-License-Identifier: Apache-2.0
#pragma once
// The report of the paper's experiments (`vrreg report --reproduce DIR`): Tables 1-2
// beside the paper's numbers and Figures 4-8, 10-16 from what `vrreg reproduce --out DIR` wrote
// into DIR/reproduce.json (the contract is docs/report.md). Sections whose data is absent are
// listed as missing instead of drawn.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "vrreg/report/page.hpp"
#include "vrreg/io/plan_csv.hpp"

namespace vrreg::report {

/// The reproduce.json format this reader understands.
inline constexpr const char* kReproduceFormat = "vrreg-reproduce";
inline constexpr int kReproduceVersion = 1;

/// Parses reproduce.json text; throws InputError naming `source` on invalid JSON, a top level
/// that is not an object, another "format" or a newer "version".
nlohmann::json parse_reproduce_json(const std::string& text, const std::string& source);

/// The page for a parsed reproduce.json; `plan` (with its file name) adds Fig. 16. Throws
/// FileError naming `source` and the key on a value of the wrong type.
ReportPage reproduce_report_page(const nlohmann::json& doc, const std::string& source,
                                 const std::optional<io::PlanFile>& plan = std::nullopt,
                                 const std::string& plan_name = "");

/// The section with a plan's fiducial layout (Fig. 16, Procedure 1), for either report.
ReportSection plan_section(const io::PlanFile& plan, const std::string& plan_name);

}  // namespace vrreg::report
