// SPDX-License-Identifier: Apache-2.0
// Renders a ReportPage as one HTML document: header, verdict, contents, sections with tables and
// figure placeholders, the figures' JSON, the inlined Plotly library and the page script.
#include <sstream>

#include "assets.hpp"
#include "escape.hpp"
#include "vrreg/report/page.hpp"

namespace vrreg::report {

int ReportPage::figure_count() const {
  int n = 0;
  for (const ReportSection& s : sections) n += static_cast<int>(s.figures.size());
  return n;
}

namespace {

const char* tone_class(Tone tone) {
  switch (tone) {
    case Tone::kGood:
      return "good";
    case Tone::kWarn:
      return "warn";
    case Tone::kBad:
      return "bad";
    case Tone::kInfo:
      break;
  }
  return "info";
}

bool is_scene(const ReportFigure& f) { return f.layout.contains("scene"); }

void render_table(std::ostream& out, const ReportTable& t) {
  out << "<div class=\"table-wrap\">";
  if (!t.title.empty()) out << "<h3>" << html_escape(t.title) << "</h3>";
  out << "<table><thead><tr>";
  const auto muted_column = [&](std::size_t c) {
    return c < t.muted_columns.size() && t.muted_columns[c];
  };
  for (std::size_t c = 0; c < t.header.size(); ++c) {
    out << (muted_column(c) ? "<th class=\"muted\">" : "<th>") << html_escape(t.header[c])
        << "</th>";
  }
  out << "</tr></thead><tbody>\n";
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const bool muted = r < t.muted.size() && t.muted[r];
    const bool group = t.group_size > 0 && r > 0 && r % t.group_size == 0;
    out << "<tr" << (muted || group ? " class=\"" : "") << (muted ? "muted" : "")
        << (muted && group ? " " : "") << (group ? "group-start" : "")
        << (muted || group ? "\"" : "") << ">";
    for (std::size_t c = 0; c < t.rows[r].size(); ++c) {
      out << (muted_column(c) ? "<td class=\"muted\">" : "<td>") << html_escape(t.rows[r][c])
          << "</td>";
    }
    out << "</tr>\n";
  }
  out << "</tbody></table>";
  if (!t.caption.empty()) out << "<p class=\"caption\">" << html_escape(t.caption) << "</p>";
  out << "</div>\n";
}

}  // namespace

std::string render_report_html(const ReportPage& page, const std::string& plotly_js) {
  std::ostringstream out;
  nlohmann::json specs = nlohmann::json::array();
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<meta name=\"generator\" content=\"vrreg report\">\n"
      << "<title>" << html_escape(page.title) << "</title>\n<style>" << detail::kReportCss
      << "</style>\n</head>\n<body data-charts-expected=\"" << page.figure_count() << "\">\n"
      << "<header class=\"top\"><h1>" << html_escape(page.title) << "</h1>";
  if (!page.subtitle.empty()) out << "<p>" << html_escape(page.subtitle) << "</p>";
  out << "</header>\n<main>\n";
  if (!page.verdict.empty()) {
    out << "<div class=\"verdict\" id=\"verdict\"><h2>Verdict</h2><ul>\n";
    for (const ReportVerdict& v : page.verdict) {
      out << "<li class=\"" << tone_class(v.tone) << "\">" << html_escape(v.text) << "</li>\n";
    }
    out << "</ul></div>\n";
  }
  out << "<nav class=\"toc\">";
  for (std::size_t s = 0; s < page.sections.size(); ++s) {
    out << "<a href=\"#sec-" << s + 1 << "\">" << html_escape(page.sections[s].heading) << "</a>";
  }
  out << "</nav>\n";
  int figure_number = 0;
  for (std::size_t s = 0; s < page.sections.size(); ++s) {
    const ReportSection& section = page.sections[s];
    out << "<section class=\"part\" id=\"sec-" << s + 1 << "\">\n<h2>"
        << html_escape(section.heading) << "</h2>\n";
    for (const std::string& p : section.paragraphs) out << "<p>" << html_escape(p) << "</p>\n";
    for (const ReportTable& t : section.tables) render_table(out, t);
    if (!section.figures.empty()) out << "<div class=\"grid\">\n";
    for (const ReportFigure& f : section.figures) {
      const std::string id = "chart-" + std::to_string(++figure_number);
      out << "<figure class=\"chart" << (f.wide || is_scene(f) ? " wide" : "")
          << (is_scene(f) ? " scene" : "") << "\" id=\"fig-" << figure_number << "\"><h3>"
          << html_escape(f.title) << "</h3><div class=\"plot\" id=\"" << id
          << "\"></div><figcaption>" << html_escape(f.caption) << "</figcaption></figure>\n";
      specs.push_back({{"id", id}, {"data", f.data}, {"layout", f.layout}});
    }
    if (!section.figures.empty()) out << "</div>\n";
    out << "</section>\n";
  }
  out << "<footer>";
  for (const std::string& n : page.notes) out << "<p>" << html_escape(n) << "</p>";
  out << "</footer>\n</main>\n"
      << "<script type=\"application/json\" id=\"vrreg-figures\">" << json_for_script(specs)
      << "</script>\n<script>" << js_for_script(plotly_js) << "\n</script>\n<script>"
      << detail::kReportScript << "</script>\n</body>\n</html>\n";
  return out.str();
}

}  // namespace vrreg::report
