// SPDX-License-Identifier: Apache-2.0
#pragma once
// The report page: sections of text, tables and Plotly charts, rendered to ONE
// self-contained HTML document with the charting library inlined, so that it opens offline and no
// request leaves the machine. Plain data: the experiments build pages, the CLI writes them.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace vrreg::report {

/// How a verdict line reads: drawn with a coloured mark.
enum class Tone { kInfo, kGood, kWarn, kBad };

/// One sentence of the verdict at the top of the page.
struct ReportVerdict {
  Tone tone = Tone::kInfo;
  std::string text{};
};

/// A table of plain-text cells (escaped when rendered).
struct ReportTable {
  std::string title{};
  std::string caption{};  ///< one line under the table: what to read from it
  std::vector<std::string> header{};
  std::vector<std::vector<std::string>> rows{};
  std::vector<bool> muted{};          ///< rows drawn grey, e.g. the paper's (may be shorter)
  std::vector<bool> muted_columns{};  ///< columns drawn grey (may be shorter than the header)
  std::size_t group_size = 0;       ///< > 0: a rule above every group_size-th row
};

/// One chart: a Plotly figure {data, layout}, a title and a one-line caption.
struct ReportFigure {
  std::string title{};                               ///< e.g. "Fig. 7: corrected RMS_T against d"
  std::string caption{};                             ///< one line: what to read from it
  nlohmann::json data = nlohmann::json::array();     ///< Plotly traces
  nlohmann::json layout = nlohmann::json::object();  ///< axis titles carry units
  bool wide = false;                                 ///< spans the page (e.g. TRE per target)
};

/// A section: heading, paragraphs, tables, then figures.
struct ReportSection {
  std::string heading{};
  std::vector<std::string> paragraphs{};
  std::vector<ReportTable> tables{};
  std::vector<ReportFigure> figures{};
};

/// A whole page.
struct ReportPage {
  std::string title{};
  std::string subtitle{};
  std::vector<ReportVerdict> verdict{};  ///< shown first, in a box
  std::vector<ReportSection> sections{};
  std::vector<std::string> notes{};  ///< footer lines: inputs, how it was made
  /// Number of charts on the page.
  [[nodiscard]] int figure_count() const;
};

/// The page as one HTML document with `plotly_js` (the Plotly library's source) inlined.
/// Charts are drawn by the page's script, which sets data-charts-expected on <body> and, once
/// every chart is drawn, data-charts-rendered and data-report-ready="1" (read by the browser
/// test). Deterministic: the same page and library give the same bytes.
std::string render_report_html(const ReportPage& page, const std::string& plotly_js);

}  // namespace vrreg::report
