// SPDX-License-Identifier: Apache-2.0
// The report page and its words: the page counts and places every chart, escapes its text,
// gives the same bytes for the same input; where RRBC's failures lie is said by layer; the
// reproduce page draws what reproduce.json holds and lists what it lacks.
#include "vrreg/report/page.hpp"

#include <gtest/gtest.h>

#include <string>

#include "vrreg/core/check.hpp"
#include "vrreg/report/cell_report.hpp"
#include "vrreg/report/reproduce_report.hpp"

namespace vrreg::report {
namespace {

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

ReportPage two_chart_page() {
  ReportPage page;
  page.title = "cell <b>";
  page.verdict = {{Tone::kGood, "ρ = 5.5 > 2.5"}};
  ReportFigure f;
  f.title = "Fig. A";
  f.caption = "read <this>";
  f.data = nlohmann::json::array(
      {{{"type", "bar"}, {"x", {1, 2}}, {"y", {3, 4}}, {"text", {"</script><b>", "T2"}}}});
  f.layout = {{"xaxis", {{"title", {{"text", "x [mm]"}}}}}};
  page.sections.push_back({"Errors", {"a & b"}, {}, {f, f}});
  return page;
}

TEST(ReportPage, RendersOneDocumentWithEveryChartAndTheLibraryInlined) {
  const ReportPage page = two_chart_page();
  EXPECT_EQ(page.figure_count(), 2);
  const std::string html = render_report_html(page, "window.Plotly = {}; // </script> here");
  EXPECT_TRUE(html.starts_with("<!DOCTYPE html>"));
  EXPECT_NE(html.find("data-charts-expected=\"2\""), std::string::npos);
  EXPECT_NE(html.find("id=\"chart-1\""), std::string::npos);
  EXPECT_NE(html.find("id=\"chart-2\""), std::string::npos);
  EXPECT_NE(html.find("<title>cell &lt;b&gt;</title>"), std::string::npos);
  EXPECT_NE(html.find("read &lt;this&gt;"), std::string::npos);
  EXPECT_NE(html.find("window.Plotly = {}; // <\\/script> here"), std::string::npos);
  // Three scripts (figures, library, page) and nothing loaded from elsewhere.
  EXPECT_EQ(count(html, "</script>"), 3);
  EXPECT_EQ(count(html, "<script"), 3);
  EXPECT_EQ(html.find(" src="), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html, render_report_html(page, "window.Plotly = {}; // </script> here"));
}

TEST(ReportWhere, CountsFailuresByLayerAndBoundary) {
  // A 3 x 3 x 4 grid of targets, 50 mm apart; z layers at 100, 150, 200, 250 mm.
  Points3 p(3, 36);
  int k = 0;
  for (int iz = 0; iz < 4; ++iz)
    for (int iy = 0; iy < 3; ++iy)
      for (int ix = 0; ix < 3; ++ix) p.col(k++) = Eigen::Vector3d(ix, iy, 2 + iz) * 0.05;
  // Three on the lowest layer (two at its centre row's ends, one in the middle), one on top.
  const std::vector<int> bad = {0, 4, 8, 31};
  const std::string text = describe_locations(p, bad);
  EXPECT_TRUE(
      text.starts_with("3 of 4 on the lowest layer (z = 100.0 mm), 1 on the top layer "
                       "(z = 250.0 mm)"))
      << text;
  EXPECT_NE(text.find("4 of 4 on the boundary of the targets' volume (which holds 94 %"),
            std::string::npos)
      << text;
  EXPECT_EQ(describe_locations(p, {}), "");
}

TEST(ReportWhere, UsesThirdsOfTheHeightForScatteredTargets) {
  Points3 p(3, 9);
  for (int k = 0; k < 9; ++k) p.col(k) = Eigen::Vector3d(0.01 * k, 0.02 * (k % 3), 0.1 + 0.011 * k);
  const std::string text = describe_locations(p, {0, 1});
  EXPECT_TRUE(text.starts_with("2 of 2 in the lowest third (z < ")) << text;
}

nlohmann::json small_reproduce() {
  return nlohmann::json::parse(R"({
    "format": "vrreg-reproduce", "version": 1, "seeds": [7],
    "table1": {"A1": {"d_mm": 43.3, "sigma_l_mm": 0.6, "rho": 5.2, "unc_rms_t_mm": 0.66,
                      "cor_rms_t_mm": 0.25, "gamma_percent": 62, "n_bad": 15},
               "A2": {"d_mm": 21.6, "sigma_l_mm": {"mean": 0.5, "sd": 0.02}, "rho": 4.4,
                      "unc_rms_t_mm": 0.6, "cor_rms_t_mm": 0.17, "gamma_percent": 71}},
    "figure7": [{"d_mm": 43.3, "cor_rms_t_mm": 0.25, "n_bad": 17},
                {"d_mm": 21.6, "cor_rms_t_mm": 0.17, "n_bad": 9},
                {"d_mm": 4.33, "cor_rms_t_mm": 0.11, "n_bad": 4}],
    "table2": [{"config": 1, "strategy": 1, "sigma_l_mm": 0.9, "rho": 12, "unc_rms_t_mm": 1.1,
                "cor_rms_t_mm": 0.4, "gamma_percent": 64},
               {"config": 1, "strategy": 3, "sigma_l_mm": null, "unc_rms_t_mm": 2.9,
                "cor_rms_t_mm": 0.17, "gamma_percent": 94}]
  })");
}

TEST(ReportReproduce, DrawsWhatTheFileHoldsAndNamesWhatItLacks) {
  const nlohmann::json doc = small_reproduce();
  const ReportPage page = reproduce_report_page(doc, "out/reproduce.json");
  // Fig. 7, 8 and RMS_T per configuration for Strategies 1 and 3; no histograms, no targets.
  EXPECT_EQ(page.figure_count(), 4);
  const std::string& last = page.verdict.back().text;
  EXPECT_NE(last.find("Not in out/reproduce.json"), std::string::npos) << last;
  EXPECT_NE(last.find("Fig. 4"), std::string::npos) << last;
  EXPECT_NE(last.find("Fig. 10-11"), std::string::npos) << last;
  // Without written findings, the page checks them itself.
  EXPECT_NE(page.verdict.front().text.find("γ(A2) = 71 %"), std::string::npos)
      << page.verdict.front().text;
  const std::string html = render_report_html(page, "window.Plotly = {};");
  EXPECT_NE(html.find("0.500 ± 0.020"), std::string::npos);  // mean ± sd over seeds
  EXPECT_NE(html.find("0.626"), std::string::npos);          // the paper's sigma_L of A1
}

TEST(ReportReproduce, RejectsAnotherFormatAndBadValuesNamingTheKey) {
  EXPECT_THROW(parse_reproduce_json("{\"format\": \"vrreg-model\"}", "x.json"), InputError);
  EXPECT_THROW(parse_reproduce_json("{\"version\": 99}", "x.json"), InputError);
  EXPECT_THROW(parse_reproduce_json("[1, 2]", "x.json"), InputError);
  EXPECT_THROW(parse_reproduce_json("{", "x.json"), InputError);
  nlohmann::json doc = small_reproduce();
  doc["table1"]["A1"]["rho"] = "high";
  try {
    (void)reproduce_report_page(doc, "x.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("table1.A1.rho"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vrreg::report
