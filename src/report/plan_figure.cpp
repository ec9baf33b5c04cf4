// SPDX-License-Identifier: Apache-2.0
// Fig. 16 (paper section 6, Procedure 1): a plan's part points, the fiducial grid around each and
// the visiting order, in the robot frame.
#include <map>

#include "reproduce_parts.hpp"
#include "values.hpp"
#include "charts.hpp"

namespace vrreg::report::detail {

ReportFigure plan_layout_figure(const io::PlanFile& plan, const std::string& plan_name) {
  ReportFigure f;
  f.title = "Fig. 16: fiducial layout of the plan " + plan_name;
  Points3 path(3, static_cast<Eigen::Index>(plan.rows.size()));
  std::map<std::string, std::vector<std::size_t>> fiducials_by_part;
  std::vector<std::size_t> targets;
  for (std::size_t i = 0; i < plan.rows.size(); ++i) {
    path.col(static_cast<Eigen::Index>(i)) = plan.rows[i].robot_m;
    if (plan.rows[i].role == Role::kTarget) {
      targets.push_back(i);
    } else {
      fiducials_by_part[plan.rows[i].part].push_back(i);
    }
  }
  nlohmann::json order =
      charts::scatter3d_trace(path, {}, "visiting order", nlohmann::json::object());
  order["mode"] = "lines";
  order["line"] = {{"color", "#c5cad3"}, {"width", 2}};
  order["hoverinfo"] = "skip";
  f.data.push_back(order);
  const auto pick = [&](const std::vector<std::size_t>& rows, bool with_config) {
    Points3 p(3, static_cast<Eigen::Index>(rows.size()));
    std::vector<std::string> labels;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      p.col(static_cast<Eigen::Index>(i)) = plan.rows[rows[i]].robot_m;
      const io::PlanRow& r = plan.rows[rows[i]];
      labels.push_back(
          r.point + (r.config && with_config ? " (config " + std::to_string(*r.config) + ")" : ""));
    }
    return std::make_pair(p, labels);
  };
  for (const auto& [part, rows] : fiducials_by_part) {
    const auto [p, labels] = pick(rows, true);
    f.data.push_back(charts::scatter3d_trace(
        p, labels, "fiducials" + (part.empty() ? std::string() : " of " + part),
        {{"size", 3}, {"symbol", "cross"}}));
  }
  const auto [tp, tl] = pick(targets, false);
  nlohmann::json t = charts::scatter3d_trace(tp, tl, "part points (targets)",
                                             {{"size", 8}, {"color", charts::kPaper}});
  t["mode"] = "markers+text";
  t["textposition"] = "top center";
  f.data.push_back(t);
  f.layout = charts::scene_layout("x robot [mm]", "y robot [mm]", "z robot [mm]");
  f.caption = std::to_string(targets.size()) + " part points, each inside a cube of " +
              "fiducials (crosses, one colour per part), " + std::to_string(plan.rows.size()) +
              " locations in all; the grey line is the order the robot visits them.";
  return f;
}

}  // namespace vrreg::report::detail
