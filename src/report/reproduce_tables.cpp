// SPDX-License-Identifier: Apache-2.0
// Tables 1 and 2 beside the paper's numbers, and the paper's findings checked on ours.
#include <algorithm>
#include <cmath>
#include <map>

#include "reproduce_parts.hpp"
#include "values.hpp"
#include "vrreg/experiments/paper_numbers.hpp"

namespace vrreg::report::detail {
namespace {

const nlohmann::json* table2_row(const nlohmann::json& doc, int config, int strategy) {
  if (!doc.contains("table2") || !doc["table2"].is_array()) return nullptr;
  for (const nlohmann::json& row : doc["table2"]) {
    if (int_at(row, "config", "table2[]") == config &&
        int_at(row, "strategy", "table2[]") == strategy) {
      return &row;
    }
  }
  return nullptr;
}

std::optional<Stat> t2(const nlohmann::json& doc, int config, int strategy, const char* key) {
  const nlohmann::json* row = table2_row(doc, config, strategy);
  return row ? stat_at(*row, key,
                       "table2[config " + std::to_string(config) + ", strategy " +
                           std::to_string(strategy) + "]")
             : std::nullopt;
}

}  // namespace

ReportTable table1_beside_paper(const nlohmann::json& doc) {
  ReportTable t;
  t.title = "Table 1 — UR5, datasets A1 and A2: vrreg (simulated test bed) and the paper";
  t.header = {"dataset", "d [mm]",        "σ_opt [mm]",    "σ_L [mm]", "σ_noise [mm]",
              "ρ",       "uncRMS_T [mm]", "corRMS_T [mm]", "γ [%]",    "N_bad"};
  for (const experiments::paper::Table1Row& p : experiments::paper::kTable1) {
    const std::string name = p.dataset;
    if (doc.contains("table1") && doc["table1"].contains(name)) {
      const nlohmann::json& r = doc["table1"][name];
      const std::string w = "table1." + name;
      t.rows.push_back(
          {name + " — vrreg", stat_text(stat_at(r, "d_mm", w), 1),
           stat_text(stat_at(r, "sigma_opt_mm", w), 3), stat_text(stat_at(r, "sigma_l_mm", w), 3),
           stat_text(stat_at(r, "sigma_noise_mm", w), 3), stat_text(stat_at(r, "rho", w), 1),
           stat_text(stat_at(r, "unc_rms_t_mm", w), 3), stat_text(stat_at(r, "cor_rms_t_mm", w), 3),
           stat_text(stat_at(r, "gamma_percent", w), 0), stat_text(stat_at(r, "n_bad", w), 0)});
      t.muted.push_back(false);
    }
    t.rows.push_back({name + " — paper", fixed(p.d_mm, 1), fixed(p.sigma_opt_mm, 3),
                      fixed(p.sigma_l_mm, 3), fixed(p.sigma_noise_mm, 3), fixed(p.rho, 1),
                      fixed(p.unc_rms_t_mm, 3), fixed(p.cor_rms_t_mm, 3), fixed(p.gamma_percent, 0),
                      "—"});
    t.muted.push_back(true);
  }
  t.caption =
      "Read across: ρ > 2.5 in both, and the closer fiducials of A2 (smaller d) give the "
      "smaller corRMS_T and larger γ. Grey rows are the paper's.";
  return t;
}

ReportTable table2_beside_paper(const nlohmann::json& doc) {
  ReportTable t;
  t.title = "Table 2 — KUKA LWR 4+, 4 arm configurations × 3 strategies: vrreg and the paper";
  t.header = {"m",     "strategy",      "σ_L [mm]", "paper", "ρ",    "paper", "uncRMS_T [mm]",
              "paper", "corRMS_T [mm]", "paper",    "γ [%]", "paper"};
  t.muted_columns = {false, false, false, true, false, true, false, true, false, true, false, true};
  t.group_size = 3;
  for (const experiments::paper::Table2Row& p : experiments::paper::kTable2) {
    for (int s = 1; s <= 3; ++s) {
      const auto i = static_cast<std::size_t>(s - 1);
      const int m = p.config;
      t.rows.push_back(
          {std::to_string(m), std::to_string(s), stat_text(t2(doc, m, s, "sigma_l_mm"), 3),
           s < 3 ? fixed(p.sigma_l_mm[i], 3) : "—", stat_text(t2(doc, m, s, "rho"), 1),
           s < 3 ? fixed(p.rho[i], 1) : "—", stat_text(t2(doc, m, s, "unc_rms_t_mm"), 3),
           fixed(p.unc_rms_t_mm[i], 3), stat_text(t2(doc, m, s, "cor_rms_t_mm"), 3),
           fixed(p.cor_rms_t_mm[i], 3), stat_text(t2(doc, m, s, "gamma_percent"), 0),
           fixed(p.gamma_percent[i], 0)});
    }
  }
  t.caption =
      "Read down each configuration: Strategy 2 (ordered) should give a smaller σ_L and "
      "corRMS_T than Strategy 1, and Strategy 3 the largest γ. Grey columns are the "
      "paper's; Strategy 3 has one registration, so no σ_L or ρ per configuration.";
  return t;
}

namespace {

// The findings `vrreg reproduce` evaluated itself: {statement, detail, evaluated, met} for one
// seed, {statement, n_met, n_seeds, met} over several.
std::vector<ReportVerdict> written_findings(const nlohmann::json& list) {
  std::vector<ReportVerdict> v;
  for (const nlohmann::json& f : list) {
    const std::string statement = string_at(f, "statement", "findings[]").value_or("?");
    const bool met = f.value("met", false);
    if (f.contains("n_seeds")) {
      const auto n_met = int_at(f, "n_met", "findings[]").value_or(0);
      const auto n = int_at(f, "n_seeds", "findings[]").value_or(0);
      v.push_back({met ? Tone::kGood : Tone::kBad, statement + ": held on " +
                                                       std::to_string(n_met) + " of " +
                                                       std::to_string(n) + " seeds (needs 80 %)."});
    } else if (!f.value("evaluated", true)) {
      v.push_back({Tone::kInfo, statement + ": not evaluated (its datasets were not run)."});
    } else {
      v.push_back({met ? Tone::kGood : Tone::kBad,
                   statement + ": " + (met ? "holds" : "does NOT hold") + " — " +
                       string_at(f, "detail", "findings[]").value_or("") + "."});
    }
  }
  return v;
}

}  // namespace

std::vector<ReportVerdict> reproduce_findings(const nlohmann::json& doc) {
  if (doc.contains("findings") && doc["findings"].is_array() && !doc["findings"].empty()) {
    return written_findings(doc["findings"]);
  }
  std::vector<ReportVerdict> v;
  const auto tone = [](bool ok) { return ok ? Tone::kGood : Tone::kBad; };
  if (doc.contains("table1")) {
    const auto g1 =
        stat_at(doc["table1"].value("A1", nlohmann::json()), "gamma_percent", "table1.A1");
    const auto g2 =
        stat_at(doc["table1"].value("A2", nlohmann::json()), "gamma_percent", "table1.A2");
    if (g1 && g2) {
      v.push_back({tone(g2->mean > g1->mean),
                   "Table 1: γ(A2) = " + fixed(g2->mean, 0) + " % " +
                       (g2->mean > g1->mean ? ">" : "≤") + " γ(A1) = " + fixed(g1->mean, 0) +
                       " % (paper: 72 > 64): fiducials closer to the targets correct better."});
    }
  }
  std::vector<double> d, cor, bad;
  if (doc.contains("figure7") && doc["figure7"].is_array()) {
    for (const nlohmann::json& e : doc["figure7"]) {
      const auto dd = stat_at(e, "d_mm", "figure7[]");
      const auto cc = stat_at(e, "cor_rms_t_mm", "figure7[]");
      const auto nb = stat_at(e, "n_bad", "figure7[]");
      if (!dd || !cc) continue;
      d.push_back(dd->mean);
      cor.push_back(cc->mean);
      bad.push_back(nb ? nb->mean : std::nan(""));
    }
  }
  if (d.size() >= 2) {
    const double rs = spearman(d, cor);
    v.push_back({tone(rs >= 0.9), "Fig. 7: corrected RMS_T falls as d falls — Spearman " +
                                      fixed(rs, 2) + " over " + std::to_string(d.size()) +
                                      " cube sizes (the paper's finding needs ≥ 0.9)."});
    const auto imax = static_cast<std::size_t>(std::max_element(d.begin(), d.end()) - d.begin());
    const auto imin = static_cast<std::size_t>(std::min_element(d.begin(), d.end()) - d.begin());
    if (!std::isnan(bad[imax]) && !std::isnan(bad[imin])) {
      v.push_back({tone(bad[imin] < bad[imax]), "Fig. 8: N_bad = " + fixed(bad[imin], 1) +
                                                    " at d_min against " + fixed(bad[imax], 1) +
                                                    " at d_max (paper: 4 against 17 of 120)."});
    }
  }
  int s3_best = 0, s2_below = 0, configs = 0;
  std::map<int, std::vector<double>> cor_by_strategy;
  for (int m = 1; m <= 4; ++m) {
    const auto g1 = t2(doc, m, 1, "gamma_percent"), g2 = t2(doc, m, 2, "gamma_percent"),
               g3 = t2(doc, m, 3, "gamma_percent");
    const auto c1 = t2(doc, m, 1, "cor_rms_t_mm"), c2 = t2(doc, m, 2, "cor_rms_t_mm");
    for (int s = 1; s <= 3; ++s) {
      if (const auto c = t2(doc, m, s, "cor_rms_t_mm")) cor_by_strategy[s].push_back(c->mean);
    }
    if (!g1 || !g2 || !g3 || !c1 || !c2) continue;
    ++configs;
    s3_best += g3->mean >= std::max(g1->mean, g2->mean) ? 1 : 0;
    s2_below += c2->mean <= c1->mean ? 1 : 0;
  }
  if (configs > 0) {
    const std::string n = " of " + std::to_string(configs) + " configurations";
    v.push_back({tone(s3_best == configs),
                 "Table 2: Strategy 3 has the largest γ in " + std::to_string(s3_best) + n + "."});
    v.push_back({tone(s2_below == configs),
                 "Table 2: Strategy 2's corRMS_T is at or below "
                 "Strategy 1's in " +
                     std::to_string(s2_below) + n + "."});
  }
  if (cor_by_strategy[1].size() >= 2) {
    std::string spread = "Spread of corRMS_T over the configurations (max − min, % of mean):";
    for (auto& [s, c] : cor_by_strategy) {
      double mean = 0.0;
      for (double x : c) mean += x / static_cast<double>(c.size());
      const double range =
          *std::max_element(c.begin(), c.end()) - *std::min_element(c.begin(), c.end());
      spread += " Strategy " + std::to_string(s) + " " +
                fixed(mean > 0 ? 100 * range / mean : 0, 0) + " %;";
    }
    spread.back() = '.';
    v.push_back({Tone::kInfo, spread + " The paper finds Strategies 2 and 3 uniform, 1 not."});
  }
  return v;
}

}  // namespace vrreg::report::detail
