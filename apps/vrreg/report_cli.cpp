// SPDX-License-Identifier: Apache-2.0
#include "report_cli.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "vrreg/core/check.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/io/plan_csv.hpp"
#include "vrreg/report/reproduce_report.hpp"

#ifndef VRREG_PLOTLY_JS_DEFAULT
#define VRREG_PLOTLY_JS_DEFAULT "web/node_modules/plotly.js-dist-min/plotly.min.js"
#endif
#ifndef VRREG_PLOTLY_JS_FROM_BIN
#define VRREG_PLOTLY_JS_FROM_BIN "../share/vrreg/plotly.min.js"
#endif

namespace vrreg::cli {
namespace {

bool read_whole(const std::string& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  text = ss.str();
  return static_cast<bool>(in) || in.eof();
}

// The copy installed with the running command (cmake --install, the .deb), found from the
// executable's own path; empty when there is none, as for a command run from its build tree.
std::string installed_plotly_js() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const std::filesystem::path path = exe.parent_path() / VRREG_PLOTLY_JS_FROM_BIN;
  return std::filesystem::is_regular_file(path, ec) ? path.lexically_normal().string()
                                                    : std::string();
}

}  // namespace

std::string plotly_js_path() {
  const char* env = std::getenv("VRREG_PLOTLY_JS");
  if (env && *env) return env;
  const std::string installed = installed_plotly_js();
  return installed.empty() ? std::string(VRREG_PLOTLY_JS_DEFAULT) : installed;
}

std::string read_plotly_js() {
  const std::string path = plotly_js_path();
  std::string text;
  VRREG_THROW_UNLESS(std::filesystem::is_regular_file(path) && read_whole(path, text) &&
                         text.size() > 1000 && text.find("Plotly") != std::string::npos,
                     "the Plotly library is missing at "
                         << path
                         << ": run scripts/install-deps.sh (npm ci in web/), or set "
                            "VRREG_PLOTLY_JS to a plotly.min.js");
  return text;
}

std::size_t write_report_html(const report::ReportPage& page, const std::string& out) {
  const std::string html = report::render_report_html(page, read_plotly_js());
  io::write_file_atomically(out, html);
  return html.size();
}

report::ReportPage write_reproduce_report(const nlohmann::json& reproduce,
                                          const std::string& source, const std::string& plan_csv,
                                          const std::string& out) {
  std::optional<io::PlanFile> plan;
  if (!plan_csv.empty()) plan = io::read_plan_csv(plan_csv);
  report::ReportPage page = report::reproduce_report_page(reproduce, source, plan, plan_csv);
  write_report_html(page, out);
  return page;
}

report::ReportPage write_reproduce_report(const std::string& dir, const std::string& plan_csv,
                                          const std::string& out) {
  const std::string path = (std::filesystem::path(dir) / "reproduce.json").string();
  std::string text;
  if (!std::filesystem::is_regular_file(path) || !read_whole(path, text)) {
    throw io::FileError(path, 0, "cannot read it: run 'vrreg reproduce --out " + dir + "' first");
  }
  return write_reproduce_report(report::parse_reproduce_json(text, path), path, plan_csv, out);
}

}  // namespace vrreg::cli
