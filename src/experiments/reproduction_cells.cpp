// SPDX-License-Identifier: Apache-2.0
#include <algorithm>
#include "vrreg/experiments/reproduction_cells.hpp"

#include <cmath>
#include <limits>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/experiments/beyond_report.hpp"
#include "vrreg/experiments/findings.hpp"
#include "vrreg/experiments/statistics.hpp"

namespace vrreg::experiments {
namespace {

using units::kMillimetresPerMetre;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

class Cells {
 public:
  explicit Cells(std::vector<Cell>& out) : out_(out) {}
  void value(const std::string& p, double v) { out_.push_back({p, CellKind::kValue, v}); }
  void count(const std::string& p, double v) { out_.push_back({p, CellKind::kCount, v}); }
  void key(const std::string& p, double v) { out_.push_back({p, CellKind::kKey, v}); }

 private:
  std::vector<Cell>& out_;
};

void table1(const Table1Entry& e, Cells& c) {
  const std::string p = "/table1/" + e.dataset + "/";
  const RrbcRunFigures& f = e.figures;
  c.key(p + "d_mm", kMillimetresPerMetre * e.d_m);
  c.key(p + "cube_mm", kMillimetresPerMetre * e.cube_edge_m);
  c.value(p + "sigma_opt_mm", kMillimetresPerMetre * f.sigma_opt_m);
  c.value(p + "sigma_l_mm", kMillimetresPerMetre * f.sigma_l_m);
  c.value(p + "sigma_noise_mm", kMillimetresPerMetre * f.sigma_noise_m);
  c.value(p + "rho", f.rho);
  c.value(p + "unc_rms_t_mm", kMillimetresPerMetre * f.unc_rms_t_m);
  c.value(p + "cor_rms_t_mm", kMillimetresPerMetre * f.cor_rms_t_m);
  c.value(p + "gamma_percent", 100.0 * f.gamma);
  c.count(p + "n_bad", f.n_bad);
  c.count(p + "n_targets", f.n_targets);
  c.count(p + "n_fiducials", f.n_fiducials);
}

void dataset_b(const DistanceSweep& b, Cells& c) {
  const SweepStep& lo = b.at_d_min();
  c.value("/dataset_b/unc_rms_t_mm", kMillimetresPerMetre * b.unc_rms_t_m);
  c.value("/dataset_b/cor_rms_t_at_d_min_mm", kMillimetresPerMetre * lo.cor_rms_t_m);
  c.value("/dataset_b/gamma_at_d_min_percent", 100.0 * lo.gamma);
  c.count("/dataset_b/n_bad_at_d_min", lo.n_bad);
  c.count("/dataset_b/n_bad_at_d_max", b.at_d_max().n_bad);
  c.count("/dataset_b/n_targets", static_cast<double>(b.target_points.size()));
  c.count("/dataset_b/n_fiducials", b.n_fiducials);
  for (std::size_t k = 0; k < b.steps.size(); ++k) {
    const SweepStep& s = b.steps[k];
    const std::string p = "/figure7/" + std::to_string(k) + "/";
    c.key(p + "d_mm", kMillimetresPerMetre * s.d_m);
    c.key(p + "cube_mm", kMillimetresPerMetre * s.cube_edge_m);
    c.value(p + "cor_rms_t_mm", kMillimetresPerMetre * s.cor_rms_t_m);
    c.count(p + "n_bad", s.n_bad);
    c.value(p + "gamma_percent", 100.0 * s.gamma);
  }
}

void table2(const Table2& t, Cells& c) {
  c.value("/kuka/sigma_noise_mm", kMillimetresPerMetre * t.sigma_noise_m);
  c.value("/kuka/switched_points_fraction", t.strategy2.switched_points_fraction());
  c.value("/kuka/switched_locations_fraction", t.strategy2.switched_locations_fraction());
  c.count("/kuka/n_points", t.strategy2.n_points);
  c.count("/kuka/n_locations", t.strategy2.n_locations);
  for (int s = 1; s <= 3; ++s) {
    c.value("/kuka/cor_rms_t_spread_percent/" + std::to_string(s - 1),
            t.configs.size() < 2 ? kNaN : 100.0 * cor_rms_t_relative_spread(t, s));
  }
  for (std::size_t k = 0; k < t.entries.size(); ++k) {
    const Table2Entry& e = t.entries[k];
    const RrbcRunFigures& f = e.figures;
    const std::string p = "/table2/" + std::to_string(k) + "/";
    const bool per_label = e.strategy != 3;
    c.key(p + "config", e.config);
    c.key(p + "strategy", e.strategy);
    c.value(p + "sigma_l_mm", per_label ? kMillimetresPerMetre * f.sigma_l_m : kNaN);
    c.value(p + "rho", per_label ? f.rho : kNaN);
    c.value(p + "unc_rms_t_mm", kMillimetresPerMetre * f.unc_rms_t_m);
    c.value(p + "cor_rms_t_mm", kMillimetresPerMetre * f.cor_rms_t_m);
    c.value(p + "gamma_percent", 100.0 * f.gamma);
    c.count(p + "n_bad", f.n_bad);
    c.count(p + "n_targets", f.n_targets);
    c.count(p + "n_fiducials", f.n_fiducials);
    const auto it = t.strategy2.switched_by_file_label.find(e.config);
    c.count(p + "n_switched_locations",
            it == t.strategy2.switched_by_file_label.end() ? 0 : it->second);
  }
}

}  // namespace

std::vector<Cell> reproduction_cells(const Reproduction& r) {
  std::vector<Cell> out;
  Cells c(out);
  if (r.a1) table1(*r.a1, c);
  if (r.a2) table1(*r.a2, c);
  if (r.b) dataset_b(*r.b, c);
  if (r.table2) table2(*r.table2, c);
  append_beyond_cells(r.beyond, out);
  return out;
}

const CellSummary* CellTable::find(std::string_view pointer) const {
  for (const CellSummary& c : cells) {
    if (c.pointer == pointer) return &c;
  }
  return nullptr;
}

CellTable summarize_cells(const std::vector<std::vector<Cell>>& per_seed) {
  CellTable out;
  out.n_seeds = static_cast<int>(per_seed.size());
  if (per_seed.empty()) return out;
  const std::vector<Cell>& first = per_seed.front();
  for (std::size_t k = 0; k < first.size(); ++k) {
    std::vector<double> values;
    bool defined = true;
    for (const std::vector<Cell>& seed : per_seed) {
      VRREG_THROW_UNLESS(
          seed.size() == first.size() && seed[k].pointer == first[k].pointer,
          "reproduction cells of different seeds do not line up at '" << first[k].pointer << "'");
      VRREG_THROW_UNLESS(first[k].kind != CellKind::kKey || seed[k].value == first[k].value,
                         "'" << first[k].pointer << "' differs between seeds");
      defined = defined && !std::isnan(seed[k].value);
      values.push_back(seed[k].value);
    }
    if (first[k].kind == CellKind::kKey) {  // the same on every seed: exactly that value
      out.cells.push_back(
          {first[k].pointer, CellKind::kKey, first[k].value, 0.0, first[k].value, out.n_seeds});
      continue;
    }
    const MeanSd m = mean_sd(values);
    double median = kNaN;
    if (defined) {
      std::sort(values.begin(), values.end());
      const std::size_t n = values.size();
      median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    }
    out.cells.push_back({first[k].pointer, first[k].kind, defined ? m.mean : kNaN,
                         defined ? m.sd : kNaN, median, m.n});
  }
  return out;
}

}  // namespace vrreg::experiments
