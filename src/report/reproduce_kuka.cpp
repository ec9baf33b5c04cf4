// SPDX-License-Identifier: Apache-2.0
// KUKA figures of the reproduce report (paper section 5.2): Fig. 5-6 (L histograms per
// configuration, Strategies 1 and 2), Fig. 12-13 (TRE per target), Fig. 14-15 (RMS_T per
// configuration, with Strategy 3's from Table 2 beside them).
#include <map>

#include "reproduce_parts.hpp"
#include "values.hpp"
#include "vrreg/experiments/paper_numbers.hpp"
#include "charts.hpp"

namespace vrreg::report::detail {
namespace {

const char* kStrategyName[4] = {"", "Strategy 1 (unordered)", "Strategy 2 (ordered)",
                                "Strategy 3 (one registration, nearest configurations)"};

// entries of `list` for `strategy`, by configuration label.
std::map<int, nlohmann::json> by_config(const std::vector<nlohmann::json>& list, int strategy,
                                        const std::string& where) {
  std::map<int, nlohmann::json> out;
  for (const nlohmann::json& e : list) {
    if (int_at(e, "strategy", where) == strategy) out[int_at(e, "config", where).value_or(0)] = e;
  }
  return out;
}

ReportFigure l_histograms(const std::map<int, nlohmann::json>& entries, int strategy) {
  ReportFigure f;
  f.title = "Fig. " + std::to_string(4 + strategy) + ": histograms of L per configuration, " +
            kStrategyName[strategy];
  std::string sigmas;
  for (const auto& [m, e] : entries) {
    const std::string where = "l_histograms[lwr4, strategy " + std::to_string(strategy) + "]";
    f.data.push_back(charts::histogram_step_trace(histogram_of(e, where), 1e3,
                                                  "configuration " + std::to_string(m)));
    sigmas += (sigmas.empty() ? "" : ", ") + stat_text(stat_at(e, "sigma_l_mm", where), 3);
  }
  f.layout = charts::xy_layout("L = |X_i − X_j| − |Y_i − Y_j|  [mm]", "pairs [count]");
  f.caption = (strategy == 1 ? "Unordered labels mix arm configurations, which widens L"
                             : "Ordered labels keep similar arms together, which narrows L") +
              std::string(" (σ_L by configuration: ") + sigmas + " mm).";
  return f;
}

ReportFigure tre_per_target(const std::map<int, nlohmann::json>& entries, int strategy) {
  ReportFigure f;
  f.title =
      "Fig. " + std::to_string(11 + strategy) + ": TRE per target, " + kStrategyName[strategy];
  f.wide = true;
  bool first = true;
  for (const auto& [m, e] : entries) {
    const std::string where = "target_errors[lwr4, strategy " + std::to_string(strategy) + "]";
    const std::vector<std::string> labels = strings_at(e, "point", where);
    const std::string cfg = "m = " + std::to_string(m);
    nlohmann::json unc = charts::per_target_trace(numbers_at(e, "unc_tre_mm", where), labels,
                                                  "uncorrected, " + cfg, charts::kUncorrected);
    nlohmann::json cor = charts::per_target_trace(numbers_at(e, "cor_tre_mm", where), labels,
                                                  "corrected (RRBC), " + cfg, charts::kCorrected);
    if (!first) {
      unc["visible"] = "legendonly";
      cor["visible"] = "legendonly";
    }
    first = false;
    f.data.push_back(unc);
    f.data.push_back(cor);
  }
  f.layout = charts::xy_layout("target n", "TRE [mm]");
  f.layout["barmode"] = "group";
  f.caption =
      std::string(strategy == 1 ? "Spikes in grey are targets measured in another arm than their "
                                  "fiducials; RRBC removes most error but not all of the spikes."
                                : "Ordered data: no spikes, and RRBC brings every target down.") +
      " The first configuration is shown; click the legend for the others.";
  return f;
}

ReportFigure rms_per_config(const nlohmann::json& doc, int strategy) {
  nlohmann::json x = nlohmann::json::array(), unc = nlohmann::json::array(),
                 cor = nlohmann::json::array(), punc = nlohmann::json::array(),
                 pcor = nlohmann::json::array();
  for (const nlohmann::json& row : doc["table2"]) {
    if (int_at(row, "strategy", "table2[]") != strategy) continue;
    const int m = int_at(row, "config", "table2[]").value_or(0);
    x.push_back("m = " + std::to_string(m));
    unc.push_back(stat_at(row, "unc_rms_t_mm", "table2[]").value_or(Stat{}).mean);
    cor.push_back(stat_at(row, "cor_rms_t_mm", "table2[]").value_or(Stat{}).mean);
    const auto i = static_cast<std::size_t>(strategy - 1);
    if (m >= 1 && m <= 4) {
      punc.push_back(experiments::paper::kTable2[static_cast<std::size_t>(m - 1)].unc_rms_t_mm[i]);
      pcor.push_back(experiments::paper::kTable2[static_cast<std::size_t>(m - 1)].cor_rms_t_mm[i]);
    } else {
      punc.push_back(nullptr);
      pcor.push_back(nullptr);
    }
  }
  const auto bar = [&](const std::string& name, const nlohmann::json& y, const char* color,
                       bool paper) {
    nlohmann::json t = {
        {"type", "bar"}, {"name", name}, {"x", x}, {"y", y}, {"marker", {{"color", color}}}};
    if (paper) t["marker"]["pattern"] = {{"shape", "/"}, {"fillmode", "overlay"}};
    if (paper) t["opacity"] = 0.55;
    return t;
  };
  ReportFigure f;
  f.title = (strategy < 3 ? "Fig. " + std::to_string(13 + strategy) + ": " : std::string()) +
            "RMS_T per configuration, " + kStrategyName[strategy];
  f.data = {bar("uncRMS_T (vrreg)", unc, charts::kUncorrected, false),
            bar("uncRMS_T (paper)", punc, charts::kUncorrected, true),
            bar("corRMS_T (vrreg)", cor, charts::kCorrected, false),
            bar("corRMS_T (paper)", pcor, charts::kCorrected, true)};
  f.layout = charts::xy_layout("arm configuration m", "RMS_T [mm]");
  f.layout["barmode"] = "group";
  f.caption = "Solid bars are vrreg's, hatched the paper's Table 2; " +
              std::string(strategy == 1 ? "the corrected error depends on the configuration."
                                        : "the corrected error is about the same in every "
                                          "configuration.");
  return f;
}

}  // namespace

void add_kuka_figures(const nlohmann::json& doc, ReportSection& kuka,
                      std::vector<std::string>& missing) {
  const std::vector<nlohmann::json> hist = entries_of(doc, "l_histograms", "lwr4");
  const std::vector<nlohmann::json> tre = entries_of(doc, "target_errors", "lwr4");
  for (int s = 1; s <= 2; ++s) {
    const auto h = by_config(hist, s, "l_histograms[lwr4]");
    if (h.empty()) {
      missing.push_back("Fig. " + std::to_string(4 + s) + " (l_histograms, lwr4, strategy " +
                        std::to_string(s) + ")");
    } else {
      kuka.figures.push_back(l_histograms(h, s));
    }
  }
  for (int s = 1; s <= 2; ++s) {
    const auto t = by_config(tre, s, "target_errors[lwr4]");
    if (t.empty()) {
      missing.push_back("Fig. " + std::to_string(11 + s) + " (target_errors, lwr4, strategy " +
                        std::to_string(s) + ")");
    } else {
      kuka.figures.push_back(tre_per_target(t, s));
    }
  }
  if (!doc.contains("table2") || !doc["table2"].is_array() || doc["table2"].empty()) {
    missing.push_back("Fig. 14-15 (table2)");
    return;
  }
  for (int s = 1; s <= 3; ++s) {
    for (const nlohmann::json& row : doc["table2"]) {
      if (int_at(row, "strategy", "table2[]") == s) {
        kuka.figures.push_back(rms_per_config(doc, s));
        break;
      }
    }
  }
}

}  // namespace vrreg::report::detail
