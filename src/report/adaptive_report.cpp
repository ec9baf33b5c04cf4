// SPDX-License-Identifier: Apache-2.0
#include "vrreg/report/adaptive_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "charts.hpp"

namespace vrreg::report {
// Unity builds share one translation unit per module: the helpers live in their own namespace.
namespace adaptive_page {
namespace {

namespace ex = experiments;

std::string mm(double value_m) {
  return std::isfinite(value_m) ? fmt::format("{:.3f}", 1e3 * value_m) : "n/a";
}

nlohmann::json mm_or_null(double value_m) {
  return std::isfinite(value_m) ? nlohmann::json(charts::round_to(1e3 * value_m, 4))
                                : nlohmann::json();
}

const char* robot_colour(const std::string& robot) {
  return robot == "ur5" ? charts::kCorrected : charts::kPaper;
}

ReportTable verdict_table(const ex::AdaptiveStudyResult& r) {
  ReportTable t;
  t.title = "Done when: the adaptive loop at STOP against Procedure 1 at d_min";
  t.caption =
      "reaches: adaptive RMS_T <= 1.1 x Procedure 1's at d_min; quarter: at most a quarter of its "
      "fiducials; honest: measured / predicted RMS_T within 0.8-1.2";
  t.header = {"robot", "seed", "Procedure 1 RMS_T [mm]", "Procedure 1 fiducials",
              "adaptive RMS_T [mm]", "adaptive fiducials", "measured / predicted", "reaches",
              "quarter", "honest"};
  for (const ex::AdaptiveVerdict& v : r.verdicts) {
    t.rows.push_back({v.robot, std::to_string(v.seed), mm(v.procedure1_dmin_rms_t_m),
                      std::to_string(v.procedure1_dmin_fiducials), mm(v.adaptive_rms_t_m),
                      std::to_string(v.adaptive_fiducials),
                      fmt::format("{:.2f}", v.measured_over_predicted), v.reaches ? "yes" : "no",
                      v.quarter ? "yes" : "no", v.honest ? "yes" : "no"});
  }
  return t;
}

ReportTable runs_table(const ex::AdaptiveStudyResult& r) {
  ReportTable t;
  t.title = "Fiducials, readings, robot time and RMS_T per plan";
  t.caption = fmt::format(
      "robot time at {:g} s per move and {:g} s per reading (the targets' own measurement not "
      "counted); adaptive: the state at STOP",
      r.options.seconds_per_move, r.options.seconds_per_reading);
  t.header = {"robot", "seed", "plan", "fiducials", "readings", "robot time [min]",
              "RMS_T [mm]", "predicted [mm]"};
  std::size_t k = 0;
  for (const ex::AdaptiveRun& a : r.adaptive) {
    if (!a.batches.empty()) {
      const ex::AdaptiveBatch& b = a.batches.back();
      t.rows.push_back({a.robot, std::to_string(a.seed),
                        fmt::format("adaptive ({} batches)", b.batch),
                        std::to_string(b.n_fiducials), std::to_string(b.n_readings),
                        fmt::format("{:.1f}", b.robot_time_s / 60.0), mm(b.measured_rms_t_m),
                        mm(b.predicted_rms_t_m)});
    }
    for (; k < r.fixed.size() && r.fixed[k].robot == a.robot && r.fixed[k].seed == a.seed; ++k) {
      const ex::FixedPlanRun& f = r.fixed[k];
      t.rows.push_back(
          {f.robot, std::to_string(f.seed),
           f.plan == "grid" ? fmt::format("grid {:g} mm, {}", 1e3 * f.cube_edge_m, f.interpolation)
                            : fmt::format("Procedure 1, d = {:.2f} mm", 1e3 * f.d_m),
           std::to_string(f.n_fiducials), std::to_string(f.n_readings),
           fmt::format("{:.1f}", f.robot_time_s / 60.0), mm(f.rms_t_m), ""});
    }
  }
  return t;
}

ReportFigure rms_against_fiducials(const ex::AdaptiveStudyResult& r) {
  ReportFigure f;
  f.title = "RMS_T against fiducials measured";
  const std::string method = to_string(r.options.interpolation);
  f.caption = fmt::format(
      "lines: the adaptive loop per seed, batch by batch (measured, {0}); circles: Procedure "
      "1's octuplets per cube edge; squares: the full grid with {0}",
      method);
  f.wide = true;
  for (const ex::AdaptiveRun& a : r.adaptive) {
    std::vector<double> x;
    std::vector<double> y;
    for (const ex::AdaptiveBatch& b : a.batches) {
      if (!std::isfinite(b.measured_rms_t_m)) continue;
      x.push_back(b.n_fiducials);
      y.push_back(b.measured_rms_t_m);
    }
    f.data.push_back({{"type", "scatter"},
                      {"mode", "lines+markers"},
                      {"name", fmt::format("{} adaptive, seed {}", a.robot, a.seed)},
                      {"x", x},
                      {"y", charts::scaled(y, 1e3, 4)},
                      {"line", {{"color", robot_colour(a.robot)}, {"width", 1.5}}},
                      {"marker", {{"size", 4}}}});
  }
  std::set<std::string> robots;
  for (const ex::FixedPlanRun& p : r.fixed) robots.insert(p.robot);
  for (const std::string& robot : robots) {
    for (const bool grid : {false, true}) {
      std::vector<double> x;
      nlohmann::json y = nlohmann::json::array();
      std::vector<std::string> text;
      for (const ex::FixedPlanRun& p : r.fixed) {
        if (p.robot != robot || (p.plan == "grid") != grid) continue;
        x.push_back(p.n_fiducials);
        y.push_back(mm_or_null(p.rms_t_m));
        text.push_back(grid ? fmt::format("grid, seed {}", p.seed)
                            : fmt::format("d = {:.2f} mm, seed {}", 1e3 * p.d_m, p.seed));
      }
      if (x.empty()) continue;
      f.data.push_back(
          {{"type", "scatter"},
           {"mode", "markers"},
           {"name", grid ? fmt::format("{} grid ({})", robot, method)
                         : fmt::format("{} Procedure 1", robot)},
           {"x", x},
           {"y", y},
           {"text", text},
           {"marker",
            {{"color", robot_colour(robot)}, {"symbol", grid ? "square" : "circle-open"},
             {"size", 8}}}});
    }
  }
  f.layout = charts::xy_layout("fiducials measured", "RMS_T at the targets [mm]");
  f.layout["xaxis"]["type"] = "log";
  return f;
}

}  // namespace
}  // namespace adaptive_page

ReportPage adaptive_study_page(const experiments::AdaptiveStudyResult& result) {
  using namespace adaptive_page;
  ReportPage page;
  page.title = "Adaptive planning study";
  page.subtitle = fmt::format(
      "plan-next -> simulate -> register ({}) -> plan-next until STOP, against Procedure 1 "
      "and the full grid, on the simulated test beds",
      to_string(result.options.interpolation));
  for (const ex::AdaptiveVerdict& v : result.verdicts) {
    const bool all = v.reaches && v.quarter && v.honest;
    page.verdict.push_back(
        {all ? Tone::kGood : Tone::kWarn,
         fmt::format("{} seed {}: {} fiducials reach {} mm (Procedure 1 at d_min: {} fiducials, "
                     "{} mm); measured / predicted {:.2f}",
                     v.robot, v.seed, v.adaptive_fiducials, mm(v.adaptive_rms_t_m),
                     v.procedure1_dmin_fiducials, mm(v.procedure1_dmin_rms_t_m),
                     v.measured_over_predicted)});
  }
  ReportSection s;
  s.heading = "Fiducials needed";
  s.paragraphs.push_back(
      "Targets: the UR5's 120 of dataset B and the LWR 4+'s 150 of its grid (one arm "
      "configuration, the one nearest the test bed's home joints). Procedure 1: the octuplet "
      "around every target at cube edge a (d = sqrt(3)/2 a), the paper's Eq. 7. Each plan is "
      "measured with noise of its own and evaluated at the same target readings.");
  s.tables.push_back(verdict_table(result));
  s.tables.push_back(runs_table(result));
  s.figures.push_back(rms_against_fiducials(result));
  page.sections.push_back(std::move(s));
  page.notes.push_back("made by vrreg adaptive-study (docs/adaptive.md)");
  return page;
}

}  // namespace vrreg::report
