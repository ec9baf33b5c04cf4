// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/reproduction_json.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::experiments {
namespace {

using units::kMillimetresPerMetre;

nlohmann::json number(double v, bool integral) {
  if (std::isnan(v)) return nullptr;
  if (integral && v == std::round(v) && std::abs(v) < 1e15) return static_cast<long long>(v);
  return v;
}

nlohmann::json mm_list(const Eigen::VectorXd& v) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(kMillimetresPerMetre * v[i]);
  return out;
}

nlohmann::json positions_mm(const Points3& p) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index i = 0; i < p.cols(); ++i) {
    out.push_back({kMillimetresPerMetre * p(0, i), kMillimetresPerMetre * p(1, i),
                   kMillimetresPerMetre * p(2, i)});
  }
  return out;
}

nlohmann::json histogram_json(const Histogram& h) {
  return {{"lo_mm", kMillimetresPerMetre * h.lo_m},
          {"bin_mm", kMillimetresPerMetre * h.bin_width_m},
          {"counts", h.counts},
          {"below", h.below},
          {"above", h.above}};
}

nlohmann::json finding_json(const Finding& f) {
  return {{"id", f.id},         {"statement", f.statement}, {"value", number(f.value, false)},
          {"detail", f.detail}, {"evaluated", f.evaluated}, {"met", f.met}};
}

nlohmann::json rate_json(const FindingRate& r) {
  nlohmann::json values = nlohmann::json::array();
  for (const double v : r.values) values.push_back(number(v, false));
  return {{"id", r.id},       {"statement", r.statement},
          {"n_met", r.n_met}, {"n_seeds", r.n_evaluated},
          {"rate", r.rate()}, {"met", r.accepted()},
          {"values", values}, {"met_per_seed", r.met}};
}

}  // namespace

nlohmann::json cells_json(const CellTable& cells) {
  nlohmann::json out = nlohmann::json::object();
  for (const CellSummary& c : cells.cells) {
    const nlohmann::json::json_pointer pointer(c.pointer);
    const bool integral = c.kind != CellKind::kValue;
    if (cells.n_seeds <= 1 || c.kind == CellKind::kKey) {
      out[pointer] = number(c.mean, integral);
    } else {
      out[pointer] = {{"mean", number(c.mean, false)}, {"sd", number(c.sd, false)}};
    }
  }
  return out;
}

nlohmann::json figure_data_json(const Reproduction& r) {
  nlohmann::json hist = nlohmann::json::array();
  nlohmann::json tre = nlohmann::json::array();
  for (const auto* e : {&r.a1, &r.a2}) {
    if (!*e || !(*e)->figures.l_histogram) continue;
    nlohmann::json h = histogram_json(*(*e)->figures.l_histogram);
    h["dataset"] = (*e)->dataset;
    h["sigma_l_mm"] = kMillimetresPerMetre * (*e)->figures.sigma_l_m;
    hist.push_back(h);
  }
  if (r.b) {
    for (const SweepStep& s : r.b->steps) {
      tre.push_back({{"dataset", "B"},
                     {"d_mm", kMillimetresPerMetre * s.d_m},
                     {"cube_mm", kMillimetresPerMetre * s.cube_edge_m},
                     {"point", r.b->target_points},
                     {"robot_mm", positions_mm(r.b->target_robot_m)},
                     {"unc_tre_mm", mm_list(r.b->unc_tre_m)},
                     {"cor_tre_mm", mm_list(s.cor_tre_m)}});
    }
  }
  if (r.table2) {
    for (const Table2Entry& e : r.table2->entries) {
      if (e.figures.l_histogram) {
        nlohmann::json h = histogram_json(*e.figures.l_histogram);
        h["dataset"] = "lwr4";
        h["strategy"] = e.strategy;
        h["config"] = e.config;
        h["sigma_l_mm"] = kMillimetresPerMetre * e.figures.sigma_l_m;
        hist.push_back(h);
      }
      tre.push_back({{"dataset", "lwr4"},
                     {"strategy", e.strategy},
                     {"config", e.config},
                     {"point", e.target_points},
                     {"robot_mm", positions_mm(e.target_robot_m)},
                     {"unc_tre_mm", mm_list(e.figures.unc_tre_m)},
                     {"cor_tre_mm", mm_list(e.figures.cor_tre_m)}});
    }
  }
  return {{"l_histograms", hist}, {"target_errors", tre}};
}

nlohmann::json reproduction_json(const std::vector<Reproduction>& runs) {
  VRREG_THROW_UNLESS(!runs.empty(), "reproduce: no seeds to report");
  std::vector<std::vector<Cell>> cells;
  std::vector<std::vector<Finding>> findings;
  nlohmann::json seeds = nlohmann::json::array();
  for (const Reproduction& r : runs) {
    cells.push_back(reproduction_cells(r));
    findings.push_back(evaluate_findings(r));
    seeds.push_back(r.seed);
  }
  const CellTable table = summarize_cells(cells);
  nlohmann::json j = cells_json(table);
  j["format"] = kReproductionJsonFormat;
  j["version"] = kReproductionJsonVersion;
  j["seed"] = runs.front().seed;
  j["seeds"] = seeds;
  j["n_seeds"] = runs.size();
  if (j.contains("kuka")) j["switched_fraction"] = j["kuka"]["switched_points_fraction"];
  nlohmann::json f = nlohmann::json::array();
  if (runs.size() == 1) {
    for (const Finding& x : findings.front()) f.push_back(finding_json(x));
  } else {
    for (const FindingRate& x : finding_rates(findings)) f.push_back(rate_json(x));
  }
  j["findings"] = f;
  j["figures_seed"] = runs.front().seed;
  const nlohmann::json figures = figure_data_json(runs.front());
  j["l_histograms"] = figures["l_histograms"];
  j["target_errors"] = figures["target_errors"];
  return j;
}

}  // namespace vrreg::experiments
