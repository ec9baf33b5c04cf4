// SPDX-License-Identifier: Apache-2.0
#pragma once
// The report page's own style sheet and script (report_assets.cpp), inlined into every page.

namespace vrreg::report::detail {

/// CSS of the report page: system fonts only (no web font is fetched).
extern const char* const kReportCss;

/// The page script: reads the figures from <script id="vrreg-figures" type="application/json">,
/// draws each with Plotly.newPlot into its <div>, and marks <body> with data-charts-rendered,
/// data-report-ready and (on failure) data-report-errors.
extern const char* const kReportScript;

}  // namespace vrreg::report::detail
