// SPDX-License-Identifier: Apache-2.0
// Dataset B per target (paper section 5.1): Fig. 10, the targets where RRBC failed at d_max and
// d_min in the volume, and Fig. 11, the Delta TRE histogram where it succeeded at d_min.
#include <algorithm>

#include "reproduce_parts.hpp"
#include "values.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/report/cell_report.hpp"
#include "charts.hpp"
#include "vrreg/metrics/improvement.hpp"

namespace vrreg::report::detail {
namespace {

struct Step {
  double d_mm = 0.0;
  Eigen::VectorXd unc_m, cor_m;
  std::vector<int> bad;
};

Eigen::VectorXd metres(const std::vector<double>& mm) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(mm.size()));
  for (std::size_t i = 0; i < mm.size(); ++i) v[static_cast<Eigen::Index>(i)] = mm[i] * 1e-3;
  return v;
}

Points3 positions(const nlohmann::json& entry, std::size_t n, const std::string& where) {
  VRREG_THROW_UNLESS(
      entry.contains("robot_mm") && entry["robot_mm"].is_array() && entry["robot_mm"].size() == n,
      where << ".robot_mm: expected " << n << " [x, y, z] positions");
  Points3 p(3, static_cast<Eigen::Index>(n));
  for (std::size_t k = 0; k < n; ++k) {
    const nlohmann::json& xyz = entry["robot_mm"][k];
    VRREG_THROW_UNLESS(xyz.is_array() && xyz.size() == 3 && xyz[0].is_number() &&
                           xyz[1].is_number() && xyz[2].is_number(),
                       where << ".robot_mm[" << k << "]: expected [x, y, z]");
    for (int a = 0; a < 3; ++a) p(a, static_cast<Eigen::Index>(k)) = xyz[a].get<double>() * 1e-3;
  }
  return p;
}

}  // namespace

void add_dataset_b_targets(const std::vector<nlohmann::json>& entries, ReportSection& b,
                           std::vector<std::string>& missing) {
  if (entries.empty()) {
    missing.push_back("Fig. 10-11 (target_errors with dataset B)");
    return;
  }
  std::vector<Step> steps;
  std::size_t n = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::string where = "target_errors[B, " + std::to_string(i) + "]";
    Step s;
    s.d_mm = stat_at(entries[i], "d_mm", where).value_or(Stat{}).mean;
    s.unc_m = metres(numbers_at(entries[i], "unc_tre_mm", where));
    s.cor_m = metres(numbers_at(entries[i], "cor_tre_mm", where));
    VRREG_THROW_UNLESS(
        s.unc_m.size() == s.cor_m.size() &&
            (i == 0 || static_cast<std::size_t>(s.unc_m.size()) == n),
        where << ": unc_tre_mm and cor_tre_mm must list the same targets in every entry");
    n = static_cast<std::size_t>(s.unc_m.size());
    s.bad = summarize_improvement(s.unc_m, s.cor_m).bad_targets;
    steps.push_back(std::move(s));
  }
  const auto by_d = [](const Step& a, const Step& c) { return a.d_mm < c.d_mm; };
  const std::size_t imin =
      static_cast<std::size_t>(std::min_element(steps.begin(), steps.end(), by_d) - steps.begin());
  const std::size_t imax =
      static_cast<std::size_t>(std::max_element(steps.begin(), steps.end(), by_d) - steps.begin());
  const Step& dmin = steps[imin];
  const Step& dmax = steps[imax];
  std::vector<std::string> labels = strings_at(entries[imin], "point", "target_errors[B]");
  if (labels.size() != n) {
    labels.clear();
    for (std::size_t k = 0; k < n; ++k) labels.push_back("n = " + std::to_string(k + 1));
  }

  if (entries[imin].contains("robot_mm")) {
    const Points3 p = positions(entries[imin], n, "target_errors[B, d_min]");
    // Classes as in the paper's Fig. 10: success at every d, failure at d_max, failure at d_min
    // (which wins), and failure only at some d between.
    std::vector<int> cls(n, 0);
    for (const Step& s : steps)
      for (int k : s.bad)
        cls[static_cast<std::size_t>(k)] = std::max(cls[static_cast<std::size_t>(k)], 1);
    for (int k : dmax.bad) cls[static_cast<std::size_t>(k)] = 2;
    for (int k : dmin.bad) cls[static_cast<std::size_t>(k)] = 3;
    const char* names[4] = {"RRBC succeeded at every d", "failed at some d between",
                            "failed at d_max", "failed at d_min"};
    const nlohmann::json markers[4] = {
        {{"size", 4}, {"color", "#c5cad3"}},
        {{"size", 5}, {"color", charts::kUncorrected}},
        {{"size", 6}, {"color", charts::kPaper}},
        {{"size", 8}, {"color", charts::kFailed}, {"symbol", "diamond"}}};
    ReportFigure f;
    f.title = "Fig. 10: where RRBC failed in dataset B (d_max = " + fixed(dmax.d_mm, 1) +
              " mm, d_min = " + fixed(dmin.d_mm, 2) + " mm)";
    for (int c = 0; c < 4; ++c) {
      std::vector<int> idx;
      for (std::size_t k = 0; k < n; ++k)
        if (cls[k] == c) idx.push_back(static_cast<int>(k));
      Points3 q(3, static_cast<Eigen::Index>(idx.size()));
      std::vector<std::string> l;
      for (std::size_t i = 0; i < idx.size(); ++i) {
        q.col(static_cast<Eigen::Index>(i)) = p.col(idx[i]);
        const auto k = static_cast<std::size_t>(idx[i]);
        l.push_back(labels[k] + ": TRE " + fixed(dmin.unc_m[idx[i]] * 1e3, 3) + " → " +
                    fixed(dmin.cor_m[idx[i]] * 1e3, 3) + " mm at d_min");
      }
      f.data.push_back(charts::scatter3d_trace(q, l, names[c], markers[c]));
    }
    f.layout = charts::scene_layout("x robot [mm]", "y robot [mm]", "z robot [mm]");
    const std::string where = describe_locations(p, dmin.bad);
    f.caption = "Red diamonds failed at the smallest d" +
                (where.empty() ? std::string(" (none)") : ": " + where) +
                ". The paper found 3 of its 4 on the lowest layer: failures cluster at the "
                "volume's boundary, where the error is most nonlinear.";
    b.figures.push_back(f);
  } else {
    missing.push_back("Fig. 10 (robot_mm of dataset B's target_errors)");
  }

  const ImprovementSummary s = summarize_improvement(dmin.unc_m, dmin.cor_m);
  ReportFigure f11;
  f11.title =
      "Fig. 11: histogram of ΔTRE where RRBC succeeded, d_min = " + fixed(dmin.d_mm, 2) + " mm";
  const Histogram h = charts::auto_histogram(s.delta_tre_m, 30);
  f11.data.push_back(charts::histogram_trace(h, 1e3, "targets", charts::kCorrected));
  f11.layout = charts::xy_layout("ΔTRE = TRE(T̂_X) − TRE(T_X)  [mm]", "targets [count]");
  charts::whole_count_ticks(f11.layout, h);
  f11.caption = std::to_string(s.delta_tre_m.size()) + " of " + std::to_string(n) +
                " targets improved at d_min; the further left, the larger the gain.";
  b.figures.push_back(f11);
}

}  // namespace vrreg::report::detail
