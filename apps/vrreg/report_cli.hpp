// SPDX-License-Identifier: Apache-2.0
#pragma once
// `vrreg report` glue (cmd_report.cpp), also for `vrreg reproduce`, which writes the report of
// its --out DIR: finding the Plotly library, reading the inputs, writing the page atomically.
//
// The Plotly library (web/node_modules/plotly.js-dist-min/plotly.min.js, installed by
// scripts/install-deps.sh with `npm ci` in web/) is found at $VRREG_PLOTLY_JS when set, else
// installed with the command (<bin>/../share/vrreg/plotly.min.js), else at the path compiled in
// (VRREG_PLOTLY_JS_DEFAULT, the repository's copy).
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "vrreg/report/page.hpp"

namespace vrreg::cli {

/// Where the Plotly library is read from.
std::string plotly_js_path();

/// The Plotly library's source; throws InputError naming the path and the setup command when it
/// is missing or empty.
std::string read_plotly_js();

/// Writes `page` with the Plotly library inlined to `out`, whole or not at all; returns its size
/// in bytes.
std::size_t write_report_html(const report::ReportPage& page, const std::string& out);

/// The report of `vrreg reproduce --out DIR`: reads DIR/reproduce.json (docs/report.md) and, when
/// `plan_csv` is not empty, a plan for Fig. 16. Returns the page written to `out`.
report::ReportPage write_reproduce_report(const std::string& dir, const std::string& plan_csv,
                                          const std::string& out);

/// The same from a reproduce.json already in memory (`source` names it on the page).
report::ReportPage write_reproduce_report(const nlohmann::json& reproduce,
                                          const std::string& source, const std::string& plan_csv,
                                          const std::string& out);

}  // namespace vrreg::cli
