// SPDX-License-Identifier: Apache-2.0
// The reproduce report: reads reproduce.json (docs/report.md) and lays out the paper's tables and
// figures, section by section, with the findings on top.
#include "reproduce_parts.hpp"
#include "values.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/file_error.hpp"
#include "vrreg/io/json_text.hpp"
#include "vrreg/report/reproduce_report.hpp"

namespace vrreg::report {

nlohmann::json parse_reproduce_json(const std::string& text, const std::string& source) {
  nlohmann::json doc = io::parse_json_document(text, source, "reproduce.json");
  VRREG_THROW_UNLESS(doc.is_object(), source << ": expected a JSON object at the top level");
  const auto format = doc.find("format");
  VRREG_THROW_UNLESS(format == doc.end() || *format == kReproduceFormat,
                     source << ": format is " << io::quote_value(*format) << ", expected \""
                            << kReproduceFormat << "\"");
  const auto version = doc.find("version");
  VRREG_THROW_UNLESS(version == doc.end() ||
                         (version->is_number_integer() && version->get<int>() <= kReproduceVersion),
                     source << ": version " << io::quote_value(*version)
                            << " is newer than this vrreg reads (" << kReproduceVersion << ")");
  return doc;
}

ReportSection plan_section(const io::PlanFile& plan, const std::string& plan_name) {
  return {"Procedure 1: where to measure (Fig. 16)",
          {"A plan from vrreg plan: a dense fiducial grid in a cube of edge 2S around each part "
           "point, so that every target has fiducials at distance d_min."},
          {},
          {detail::plan_layout_figure(plan, plan_name)}};
}

namespace {

ReportPage page_of(const nlohmann::json& doc, const std::string& source,
                   const std::optional<io::PlanFile>& plan, const std::string& plan_name) {
  ReportPage page;
  page.title = "vrreg — the paper's experiments, reproduced";
  page.subtitle =
      "Simulated UR5 and KUKA LWR 4+ test beds processed as in the NIST paper "
      "\"Improving 3D Vision-Robot Registration for Assembly Tasks\". Lengths in mm.";
  if (const auto seeds = detail::numbers_at(doc, "seeds", "reproduce"); !seeds.empty()) {
    page.subtitle += seeds.size() == 1
                         ? " Seed " + detail::fixed(seeds.front(), 0) + "."
                         : " Mean ± sd over " + std::to_string(seeds.size()) + " seeds.";
    if (const auto fs = detail::stat_at(doc, "figures_seed", "reproduce"); fs && seeds.size() > 1) {
      page.subtitle +=
          " Histograms and per-target figures are of seed " + detail::fixed(fs->mean, 0) + ".";
    }
  }
  page.verdict = detail::reproduce_findings(doc);
  std::vector<std::string> missing;

  ReportSection t1{"UR5: distance to the fiducials (Table 1, Fig. 4)",
                   {"Datasets A1 and A2: targets on a grid, each corrected from the eight "
                    "fiducials at the corners of a cube around it (a = 50 and 25 mm, so d = 43.3 "
                    "and 21.6 mm)."},
                   {detail::table1_beside_paper(doc)},
                   {}};
  ReportSection b{"UR5: error against d (dataset B, Fig. 7, 8, 10, 11)",
                  {"Dataset B: the same 120 targets corrected from octuplets of ten cube sizes, "
                   "a = 50 mm down to 5 mm."},
                  {},
                  {}};
  detail::add_ur5_figures(doc, t1, b, missing);
  ReportSection kuka{"KUKA LWR 4+: arm configurations (Table 2, Fig. 5, 6, 12-15)",
                     {"Four arm configurations per point. Strategy 1 keeps the IK's order, "
                      "Strategy 2 relabels configurations along the path, Strategy 3 uses one "
                      "registration and, per target, the fiducials in the nearest configuration."},
                     {detail::table2_beside_paper(doc)},
                     {}};
  if (const auto sf = detail::stat_at(doc, "switched_fraction", "reproduce")) {
    kuka.paragraphs.push_back(
        "Strategy 2 switched " +
        detail::stat_text(detail::Stat{100 * sf->mean, sf->sd ? std::optional<double>(100 * *sf->sd)
                                                              : std::nullopt},
                          0) +
        " % of the points (paper: about 14 %).");
  }
  detail::add_kuka_figures(doc, kuka, missing);
  page.sections = {t1, b, kuka};
  if (plan) page.sections.push_back(plan_section(*plan, plan_name));
  if (!missing.empty()) {
    std::string text = "Not in " + source + ", so not drawn:";
    for (const std::string& m : missing) text += " " + m + ";";
    text.back() = '.';
    page.verdict.push_back({Tone::kWarn, text});
  }
  page.notes = {"Made by vrreg report from " + source + (plan ? " and " + plan_name : "") + ".",
                "The paper's numbers (grey rows, orange diamonds, hatched bars) are the project's "
                "copy of Tables 1-2 and section 5.1."};
  return page;
}

}  // namespace

ReportPage reproduce_report_page(const nlohmann::json& doc, const std::string& source,
                                 const std::optional<io::PlanFile>& plan,
                                 const std::string& plan_name) {
  try {
    return page_of(doc, source, plan, plan_name);
  } catch (const FileError&) {
    throw;  // the plan file's, named already
  } catch (const InputError& e) {
    throw FileError(source, 0, e.what());  // a key of the wrong type, named by its path
  }
}

}  // namespace vrreg::report
