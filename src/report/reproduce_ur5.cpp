// SPDX-License-Identifier: Apache-2.0
// UR5 figures of the reproduce report: Fig. 4 (L histogram, A2), Fig. 7-8 (corrected RMS_T and
// N_bad against d, dataset B), Fig. 10 (where RRBC failed), Fig. 11 (Delta TRE at d_min).
#include <algorithm>
#include <cmath>

#include "reproduce_parts.hpp"
#include "values.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/experiments/paper_numbers.hpp"
#include "vrreg/report/cell_report.hpp"
#include "charts.hpp"
#include "vrreg/metrics/improvement.hpp"

namespace vrreg::report::detail {

Histogram histogram_of(const nlohmann::json& entry, const std::string& where) {
  const auto lo = stat_at(entry, "lo_mm", where);
  const auto bin = stat_at(entry, "bin_mm", where);
  VRREG_THROW_UNLESS(lo && bin && bin->mean > 0.0 && entry.contains("counts"),
                     where << ": needs lo_mm, bin_mm > 0 and counts");
  Histogram h;
  h.lo_m = lo->mean * 1e-3;
  h.bin_width_m = bin->mean * 1e-3;
  for (double c : numbers_at(entry, "counts", where)) h.counts.push_back(std::llround(c));
  h.below = std::llround(stat_at(entry, "below", where).value_or(Stat{}).mean);
  h.above = std::llround(stat_at(entry, "above", where).value_or(Stat{}).mean);
  return h;
}

std::vector<nlohmann::json> entries_of(const nlohmann::json& doc, const std::string& key,
                                       const std::string& dataset) {
  std::vector<nlohmann::json> out;
  if (!doc.contains(key)) return out;
  VRREG_THROW_UNLESS(doc[key].is_array(), key << ": expected an array of objects");
  for (const nlohmann::json& e : doc[key]) {
    if (string_at(e, "dataset", key + "[]") == dataset) out.push_back(e);
  }
  return out;
}

namespace {

ReportFigure fig4(const nlohmann::json& entry, const std::string& dataset) {
  ReportFigure f;
  f.title = "Fig. 4: histogram of L for dataset " + dataset;
  const Histogram h = histogram_of(entry, "l_histograms[" + dataset + "]");
  f.data.push_back(charts::histogram_trace(h, 1e3, "fiducial pairs", charts::kCorrected));
  f.layout = charts::xy_layout("L = |X_i − X_j| − |Y_i − Y_j|  [mm]", "pairs [count]");
  f.caption =
      "Deviation from the rigid-body condition (Eq. 1) over all fiducial pairs; its "
      "standard deviation is Table 1's σ_L, here " +
      stat_text(stat_at(entry, "sigma_l_mm", "l_histograms"), 3) + " mm.";
  return f;
}

nlohmann::json line(const std::vector<double>& x, const std::vector<double>& y,
                    const std::vector<double>& sd, const std::string& name, const char* color) {
  nlohmann::json t = {{"type", "scatter"},
                      {"mode", "lines+markers"},
                      {"name", name},
                      {"x", charts::scaled(x, 1.0, 3)},
                      {"y", charts::scaled(y, 1.0, 4)},
                      {"line", {{"color", color}}},
                      {"marker", {{"size", 7}}}};
  if (std::any_of(sd.begin(), sd.end(), [](double s) { return s > 0.0; })) {
    t["error_y"] = {{"type", "data"}, {"array", charts::scaled(sd, 1.0, 4)}, {"visible", true}};
  }
  return t;
}

nlohmann::json paper_points(const std::vector<double>& x, const std::vector<double>& y,
                            const std::vector<std::string>& text, const std::string& name) {
  return {{"type", "scatter"},
          {"mode", "markers"},
          {"name", name},
          {"x", x},
          {"y", y},
          {"text", text},
          {"marker",
           {{"color", charts::kPaper},
            {"symbol", "diamond-open"},
            {"size", 11},
            {"line", {{"width", 2}}}}},
          {"hovertemplate", "%{text}: %{y}<extra>paper</extra>"}};
}

void add_fig7_fig8(const nlohmann::json& doc, ReportSection& b) {
  std::vector<double> d, cor, cor_sd, bad, bad_sd;
  for (const nlohmann::json& e : doc["figure7"]) {
    const auto dd = stat_at(e, "d_mm", "figure7[]");
    const auto c = stat_at(e, "cor_rms_t_mm", "figure7[]");
    const auto n = stat_at(e, "n_bad", "figure7[]");
    if (!dd || !c) continue;
    d.push_back(dd->mean);
    cor.push_back(c->mean);
    cor_sd.push_back(c->sd.value_or(0.0));
    bad.push_back(n ? n->mean : std::nan(""));
    bad_sd.push_back(n ? n->sd.value_or(0.0) : 0.0);
  }
  const experiments::paper::DatasetB pb = experiments::paper::kDatasetB;
  ReportFigure f7;
  f7.title = "Fig. 7: corrected RMS_T against the target–fiducial distance d (dataset B)";
  f7.data.push_back(line(d, cor, cor_sd, "corRMS_T (vrreg)", charts::kCorrected));
  if (const auto unc =
          stat_at(doc.value("dataset_b", nlohmann::json()), "unc_rms_t_mm", "dataset_b")) {
    f7.data.push_back({{"type", "scatter"},
                       {"mode", "lines"},
                       {"name", "uncRMS_T (vrreg)"},
                       {"x", {pb.d_min_mm, pb.d_max_mm}},
                       {"y", {unc->mean, unc->mean}},
                       {"line", {{"color", charts::kUncorrected}, {"dash", "dash"}}}});
  }
  f7.data.push_back(paper_points({pb.d_min_mm, experiments::paper::kTable1[0].d_mm, experiments::paper::kTable1[1].d_mm},
                                 {charts::round_to(pb.cor_rms_t_at_d_min_mm(), 3),
                                  experiments::paper::kTable1[0].cor_rms_t_mm, experiments::paper::kTable1[1].cor_rms_t_mm},
                                 {"B at d_min (γ = 84 %)", "Table 1, A1", "Table 1, A2"}, "paper"));
  f7.layout = charts::xy_layout("target–fiducial distance d = √3·a/2  [mm]", "RMS_T [mm]");
  f7.caption =
      "Read the slope: the closer the eight fiducials, the smaller the corrected error; "
      "the paper's values are orange diamonds.";
  ReportFigure f8;
  f8.title = "Fig. 8: N_bad, the targets RRBC made worse, against d (dataset B)";
  f8.data.push_back(line(d, bad, bad_sd, "N_bad (vrreg)", charts::kFailed));
  f8.data.push_back(
      paper_points({pb.d_min_mm, pb.d_max_mm},
                   {static_cast<double>(pb.n_bad_at_d_min), static_cast<double>(pb.n_bad_at_d_max)},
                   {"d_min", "d_max"}, "paper"));
  f8.layout = charts::xy_layout("target–fiducial distance d = √3·a/2  [mm]",
                                "N_bad [targets of " + std::to_string(pb.targets) + "]");
  f8.caption = "Failures should be few and fall with d (paper: 17 at d_max, 4 at d_min).";
  b.figures.push_back(f7);
  b.figures.push_back(f8);
}

}  // namespace

void add_ur5_figures(const nlohmann::json& doc, ReportSection& table1, ReportSection& b,
                     std::vector<std::string>& missing) {
  std::vector<nlohmann::json> h = entries_of(doc, "l_histograms", "A2");
  std::string dataset = "A2";
  if (h.empty()) {
    h = entries_of(doc, "l_histograms", "A1");
    dataset = "A1";
  }
  if (h.empty()) {
    missing.push_back("Fig. 4 (l_histograms with dataset A2)");
  } else {
    table1.figures.push_back(fig4(h.front(), dataset));
  }
  if (doc.contains("figure7") && doc["figure7"].is_array() && !doc["figure7"].empty()) {
    add_fig7_fig8(doc, b);
  } else {
    missing.push_back("Fig. 7-8 (figure7)");
  }
  add_dataset_b_targets(entries_of(doc, "target_errors", "B"), b, missing);
}

}  // namespace vrreg::report::detail
