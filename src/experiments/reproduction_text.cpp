// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/reproduction_text.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "text_table.hpp"
#include "vrreg/experiments/paper_numbers.hpp"

namespace vrreg::experiments {
namespace {

using text::decimal_text;
using text::TextTable;

// A cell as "0.239", or "0.239 ± 0.012" over several seeds; counts of one seed without decimals.
std::string cell(const CellTable& t, const std::string& pointer, int decimals) {
  const CellSummary* c = t.find(pointer);
  if (c == nullptr) return "-";
  if (c->kind == CellKind::kKey) return decimal_text(c->mean, decimals);
  if (t.n_seeds <= 1) return decimal_text(c->mean, c->kind == CellKind::kCount ? 0 : decimals);
  if (std::isnan(c->mean)) return "-";
  if (c->kind == CellKind::kCount && c->sd == 0.0) return decimal_text(c->mean, 0);
  const int d = c->kind == CellKind::kCount ? 1 : decimals;
  return decimal_text(c->mean, d) + " ± " + decimal_text(c->sd, d);
}

// A fraction cell in percent: "16.8 %" or "16.8 ± 0.0 %".
std::string percent(const CellTable& t, const std::string& pointer) {
  const CellSummary* c = t.find(pointer);
  if (c == nullptr || std::isnan(c->mean)) return "-";
  std::string out = decimal_text(100.0 * c->mean, 1);
  if (t.n_seeds > 1 && c->sd > 0.0) out += " ± " + decimal_text(100.0 * c->sd, 1);
  return out + " %";
}

std::string beside(const std::string& ours, double paper, int decimals) {
  return ours + " (" + decimal_text(paper, decimals) + ")";
}

std::string seeds_note(const CellTable& t) {
  return t.n_seeds > 1 ? "vrreg: mean ± sd over " + std::to_string(t.n_seeds) + " seeds" : "vrreg";
}

void table1(const CellTable& t, std::string& out) {
  if (t.find("/table1/A1/d_mm") == nullptr && t.find("/table1/A2/d_mm") == nullptr) return;
  out +=
      "Table 1. UR5, datasets A1 and A2: all fiducials registered, each target corrected from\n"
      "the octuplet around it (a = 50 mm for A1, 25 mm for A2; d = sqrt(3)/2 a). Lengths in mm.\n";
  TextTable table;
  table.add({"data", "", "d", "sigma_opt", "sigma_L", "sigma_noise", "rho", "unc RMS_T",
             "cor RMS_T", "gamma %", "N_bad", "targets", "fiducials"});
  for (const paper::Table1Row& p : paper::kTable1) {
    const std::string k = std::string("/table1/") + p.dataset + "/";
    if (t.find(k + "d_mm") == nullptr) continue;
    table.add({p.dataset, seeds_note(t), cell(t, k + "d_mm", 1), cell(t, k + "sigma_opt_mm", 3),
               cell(t, k + "sigma_l_mm", 3), cell(t, k + "sigma_noise_mm", 3),
               cell(t, k + "rho", 1), cell(t, k + "unc_rms_t_mm", 3),
               cell(t, k + "cor_rms_t_mm", 3), cell(t, k + "gamma_percent", 0),
               cell(t, k + "n_bad", 0), cell(t, k + "n_targets", 0),
               cell(t, k + "n_fiducials", 0)});
    table.add({"", "paper", decimal_text(p.d_mm, 1), decimal_text(p.sigma_opt_mm, 3),
               decimal_text(p.sigma_l_mm, 3), decimal_text(p.sigma_noise_mm, 3),
               decimal_text(p.rho, 1), decimal_text(p.unc_rms_t_mm, 3),
               decimal_text(p.cor_rms_t_mm, 3), decimal_text(p.gamma_percent, 0), "-",
               std::to_string(p.targets), std::to_string(p.fiducials)});
  }
  out += table.str() + "\n";
}

void figures7_8(const CellTable& t, std::string& out) {
  if (t.find("/dataset_b/unc_rms_t_mm") == nullptr) return;
  const paper::DatasetB& p = paper::kDatasetB;
  out += "Figures 7 and 8. UR5 dataset B: one registration from all " +
         cell(t, "/dataset_b/n_fiducials", 0) + " fiducials; each of the " +
         cell(t, "/dataset_b/n_targets", 0) +
         " targets\ncorrected from the octuplet of each cube size a in turn (weights 1/8), d = "
         "sqrt(3)/2 a. Lengths in mm;\npaper values in brackets where the paper gives them.\n";
  out += "  uncorrected RMS_T " + beside(cell(t, "/dataset_b/unc_rms_t_mm", 3), p.unc_rms_t_mm, 3) +
         "\n";
  TextTable table;
  table.add({"a", "d", "cor RMS_T (Fig. 7)", "N_bad (Fig. 8)", "gamma %"});
  for (int k = 0;; ++k) {
    const std::string s = "/figure7/" + std::to_string(k) + "/";
    const CellSummary* d = t.find(s + "d_mm");
    if (d == nullptr) break;
    std::string cor = cell(t, s + "cor_rms_t_mm", 3);
    std::string bad = cell(t, s + "n_bad", 0);
    std::string gamma = cell(t, s + "gamma_percent", 0);
    if (std::abs(d->mean - p.d_max_mm) < 0.05) bad = beside(bad, p.n_bad_at_d_max, 0);
    if (std::abs(d->mean - p.d_min_mm) < 0.05) {
      cor = beside(cor, p.cor_rms_t_at_d_min_mm(), 3) + "*";
      bad = beside(bad, p.n_bad_at_d_min, 0);
      gamma = beside(gamma, p.gamma_at_d_min_percent, 0);
    }
    table.add({cell(t, s + "cube_mm", 0), decimal_text(d->mean, 2), cor, bad, gamma});
  }
  out += table.str();
  out += "  * the paper's 0.650 mm x (1 - 84 %): it gives gamma at d_min, not cor RMS_T.\n\n";
}

void table2(const CellTable& t, std::string& out) {
  if (t.find("/kuka/sigma_noise_mm") == nullptr) return;
  out += "Table 2. KUKA LWR 4+: " + cell(t, "/table2/0/n_targets", 0) +
         " targets in every arm configuration, octuplets of 40 mm; Strategy 1 = labels as the\n"
         "IK listed them, 2 = labels along the visiting path, 3 = one registration from the "
         "volume corners.\n";
  out += "  sigma_noise " +
         beside(cell(t, "/kuka/sigma_noise_mm", 3), paper::kKukaSigmaNoiseMm, 3) +
         " mm. Strategy 2 switched " + percent(t, "/kuka/switched_points_fraction") +
         " of the nominal points (paper ~" +
         decimal_text(100.0 * paper::kKukaSwitchedPointsFraction, 0) + " %),\n  " +
         percent(t, "/kuka/switched_locations_fraction") + " of the (point, config) locations.\n";
  TextTable table;
  table.add({"config", "strategy", "sigma_L mm", "rho", "unc RMS_T mm", "cor RMS_T mm", "gamma %",
             "N_bad", "switched"});
  for (int k = 0;; ++k) {
    const std::string s = "/table2/" + std::to_string(k) + "/";
    const CellSummary* config = t.find(s + "config");
    if (config == nullptr) break;
    const int m = static_cast<int>(config->mean);
    const int strategy = static_cast<int>(t.find(s + "strategy")->mean);
    const paper::Table2Row* p = nullptr;
    for (const paper::Table2Row& row : paper::kTable2) {
      if (row.config == m) p = &row;
    }
    const auto with_paper = [&](const std::string& ours, const double* values, int n, int dec) {
      return p != nullptr && strategy <= n ? beside(ours, values[strategy - 1], dec) : ours;
    };
    table.add(
        {std::to_string(m), std::to_string(strategy),
         with_paper(cell(t, s + "sigma_l_mm", 3), p ? p->sigma_l_mm.data() : nullptr, 2, 3),
         with_paper(cell(t, s + "rho", 1), p ? p->rho.data() : nullptr, 2, 1),
         with_paper(cell(t, s + "unc_rms_t_mm", 3), p ? p->unc_rms_t_mm.data() : nullptr, 3, 3),
         with_paper(cell(t, s + "cor_rms_t_mm", 3), p ? p->cor_rms_t_mm.data() : nullptr, 3, 3),
         with_paper(cell(t, s + "gamma_percent", 0), p ? p->gamma_percent.data() : nullptr, 3, 0),
         cell(t, s + "n_bad", 0), strategy == 1 ? cell(t, s + "n_switched_locations", 0) : ""});
  }
  out += table.str();
  out +=
      "  (paper in brackets; 'switched': locations the IK listed as this configuration that "
      "Strategy 2 relabelled)\n";
  std::array<double, 3> paper_spread{};
  for (std::size_t s = 0; s < 3; ++s) {
    double lo = 1e9, hi = 0.0, sum = 0.0;
    for (const paper::Table2Row& row : paper::kTable2) {
      lo = std::min(lo, row.cor_rms_t_mm[s]);
      hi = std::max(hi, row.cor_rms_t_mm[s]);
      sum += row.cor_rms_t_mm[s];
    }
    paper_spread[s] = 100.0 * (hi - lo) / (sum / 4.0);
  }
  out += "  spread (max - min) of cor RMS_T over the configurations, % of its mean: Strategy 1 " +
         beside(cell(t, "/kuka/cor_rms_t_spread_percent/0", 0), paper_spread[0], 0) + ", 2 " +
         beside(cell(t, "/kuka/cor_rms_t_spread_percent/1", 0), paper_spread[1], 0) + ", 3 " +
         beside(cell(t, "/kuka/cor_rms_t_spread_percent/2", 0), paper_spread[2], 0) + "\n\n";
}

}  // namespace

std::string format_reproduction_tables(const CellTable& cells) {
  std::string out;
  table1(cells, out);
  figures7_8(cells, out);
  table2(cells, out);
  return out;
}

std::string format_findings(const std::vector<Finding>& findings) {
  std::string out = "Findings of the paper (sections 5.1, 5.2) on this seed:\n";
  for (const Finding& f : findings) {
    out += std::string("  [") +
           (!f.evaluated ? "not run"
            : f.met      ? "met"
                         : "NOT MET") +
           "] " + f.statement + "\n";
    if (f.evaluated) out += "      " + f.detail + "\n";
  }
  return out;
}

std::string format_finding_rates(const std::vector<FindingRate>& rates,
                                 const std::vector<Finding>& first_seed) {
  std::string out =
      "Findings of the paper (sections 5.1, 5.2) over the seeds (accepted when met "
      "on >= 80 % of them):\n";
  for (std::size_t k = 0; k < rates.size(); ++k) {
    const FindingRate& r = rates[k];
    out += std::string("  [") +
           (r.n_evaluated == 0 ? "not run"
            : r.accepted()     ? "met"
                               : "NOT MET") +
           "] " + r.statement + "\n";
    if (r.n_evaluated == 0) continue;
    out += "      met on " + std::to_string(r.n_met) + " of " + std::to_string(r.n_evaluated) +
           " seeds (" + decimal_text(100.0 * r.rate(), 0) + " %)";
    if (k < first_seed.size() && first_seed[k].evaluated) {
      out += "; first seed: " + first_seed[k].detail;
    }
    out += "\n";
  }
  return out;
}

}  // namespace vrreg::experiments
