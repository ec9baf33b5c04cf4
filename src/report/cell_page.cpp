// SPDX-License-Identifier: Apache-2.0
// The cell report's page: summary table, L histogram (as Fig. 4), TRE per target (as Fig. 12-13),
// RMS_T per configuration (as Fig. 14-15), Delta TRE histogram (as Fig. 11), 3D volume (Fig. 10).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "charts.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/metrics/errors.hpp"
#include "vrreg/metrics/uncertainty_calibration.hpp"
#include "vrreg/report/cell_report.hpp"

namespace vrreg::report {
namespace {

std::string num(double value, int decimals) { return format_fixed(value, decimals); }
std::string mm(double metres) { return format_mm(metres) + " mm"; }
std::string opt_mm(const std::optional<double>& m) { return m ? mm(*m) : "—"; }

std::string pairs_text(const CellAnalysis& a) {
  const SigmaLSampling& s = a.sigma_l_sampling;
  if (!s.sampled) return std::to_string(a.rigid_body.pairs);
  return std::to_string(s.pairs_total) + " (σ_L and its histogram from " +
         std::to_string(s.pairs_sampled) + " pairs sampled with seed " + std::to_string(s.seed) +
         ")";
}

std::string sigma_l_text(const CellAnalysis& a) {
  const SigmaLSampling& s = a.sigma_l_sampling;
  if (!s.sampled) return mm(a.rigid_body.sigma_l_m);
  return mm(a.rigid_body.sigma_l_m) + " (sampled; 95 % interval " + format_mm(s.sigma_l_low_m, 5) +
         " to " + format_mm(s.sigma_l_high_m, 5) + " mm)";
}

ReportTable summary_table(const CellReportInput& in, const CellAnalysis& a) {
  const ImprovementSummary& s = a.summary;
  ReportTable t;
  t.title = "Summary";
  t.header = {"quantity", "value"};
  t.rows = {
      {"fiducials in the model (J)", std::to_string(a.n_fiducials)},
      {"fiducial pairs (L_ij, Eq. 1)", pairs_text(a)},
      {"σ_L (Eq. 1)", sigma_l_text(a)},
      {"σ_opt (repeat readings)", opt_mm(a.noise.sigma_opt_m)},
      {"σ_rep (robot repeatability)", opt_mm(a.noise.sigma_rep_m)},
      {"σ_noise (Eq. 9)", opt_mm(a.noise.sigma_noise_m)},
      {"ρ = σ_L / σ_noise", a.noise.rho ? num(*a.noise.rho, 2) : "—"},
      {"targets evaluated (N)", std::to_string(in.evaluation.n_targets())},
      {"interpolation", std::string(to_string(in.evaluation.correction.method_used)) + ": " +
                            in.evaluation.correction.layout},
      {"targets corrected (the figures below are theirs)", std::to_string(s.n_targets)},
      {"uncorrected RMS_T (Eq. 4)", s.n_targets > 0 ? mm(s.unc_rms_t_m) : "—"},
      {"corrected RMS_T (RRBC, Eq. 7-8)", s.n_targets > 0 ? mm(s.cor_rms_t_m) : "—"},
      {"γ = (unc − cor) / unc", s.n_targets > 0 ? num(100.0 * s.gamma, 1) + " %" : "—"},
      {"N_bad (TRE got worse)", std::to_string(s.n_bad) + " of " + std::to_string(s.n_targets)},
      {"not correctable (left uncorrected)",
       std::to_string(in.evaluation.correction.n_flagged) +
           (in.evaluation.correction.n_flagged > 0
                ? ", RMS_T " + mm(in.evaluation.flagged_rms_t_m) + " as registered"
                : "")},
  };
  const EvaluateResult& e = in.evaluation;
  if (e.calibration.n > 0) {  // a field model: its predicted uncertainty, and how honest it was
    const PredictedSdSummary sd = summarize_predicted_sd(e.correction.predicted_sd_m);
    t.rows.push_back({"predicted σ of a corrected target (median)", mm(sd.median_m)});
    t.rows.push_back({"calibration: RMS of TRE / σ_pred (1 = honest)",
                      num(e.calibration.rms_ratio, 2) + ", " +
                          num(100.0 * e.calibration.within_2sigma, 0) + " % within 2σ"});
  }
  if (!a.method.empty()) t.rows.insert(t.rows.begin() + 8, {"Procedure 2", a.method});
  t.caption =
      "ρ > 2.5 means the rigid-body deviation is systematic and RRBC should help; γ is the "
      "share of RMS_T it removed; N_bad counts the targets it made worse.";
  return t;
}

ReportFigure l_histogram_figure(const CellAnalysis& a) {
  ReportFigure f;
  f.title = "Histogram of L_ij over fiducial pairs (as paper Fig. 4)";
  f.data.push_back(
      charts::histogram_trace(a.l_histogram, 1e3, "fiducial pairs", charts::kCorrected));
  f.layout = charts::xy_layout("L = |X_i − X_j| − |Y_i − Y_j|  [mm]", "pairs [count]");
  const long long out = static_cast<long long>(a.l_histogram.below + a.l_histogram.above);
  f.caption = std::string(a.sigma_l_sampling.sampled ? "Over a uniform sample of pairs (see the "
                                                       "summary). "
                                                     : "") +
              "The width of this distribution is σ_L = " + mm(a.rigid_body.sigma_l_m) +
              ": the wider it is against the noise, the more systematic error RRBC can remove" +
              (out > 0 ? " (" + std::to_string(out) + " pairs beyond ±5 σ_L not drawn)." : ".");
  return f;
}

std::vector<double> to_mm(const Eigen::VectorXd& v) {
  std::vector<double> out(static_cast<std::size_t>(v.size()));
  for (Eigen::Index i = 0; i < v.size(); ++i) out[static_cast<std::size_t>(i)] = v[i] * 1e3;
  return out;
}

ReportFigure tre_figure(const CellReportInput& in, const CellAnalysis& a) {
  ReportFigure f;
  f.title = "TRE per target, uncorrected and corrected (as paper Fig. 12-13)";
  f.wide = true;
  f.data.push_back(charts::per_target_trace(to_mm(a.unc_tre_m), a.labels, "uncorrected TRE(T_X)",
                                            charts::kUncorrected));
  f.data.push_back(charts::per_target_trace(to_mm(a.cor_tre_m), a.labels,
                                            "corrected TRE(T̂_X) (RRBC)", charts::kCorrected));
  const Eigen::VectorXd& sd_m = in.evaluation.correction.predicted_sd_m;
  if (sd_m.size() == a.cor_tre_m.size()) {  // field models: what each target was predicted to be
    f.data.push_back(
        charts::per_target_trace(to_mm(sd_m), a.labels, "predicted σ (1σ)", charts::kUncorrected));
    f.data.back()["type"] = "scatter";
    f.data.back()["mode"] = "lines";
    f.data.back()["line"] = {{"dash", "dot"}, {"color", charts::kCorrected}};
  }
  nlohmann::json bx = nlohmann::json::array(), by = nlohmann::json::array(),
                 bt = nlohmann::json::array();
  for (int k : a.summary.bad_targets) {
    bx.push_back(k + 1);
    by.push_back(charts::round_to(a.cor_tre_m[k] * 1e3, 4));
    bt.push_back(a.labels[static_cast<std::size_t>(k)]);
  }
  f.data.push_back({{"type", "scatter"},
                    {"mode", "markers"},
                    {"name", "RRBC failed (N_bad)"},
                    {"x", bx},
                    {"y", by},
                    {"text", bt},
                    {"marker", {{"color", charts::kFailed}, {"symbol", "x"}, {"size", 9}}},
                    {"hovertemplate", "n = %{x} (%{text}): %{y} mm<extra>worse</extra>"}});
  f.layout = charts::xy_layout("target n (file order)", "TRE [mm]");
  f.layout["barmode"] = "group";
  f.caption =
      "Blue below grey is a gain from RRBC; red crosses mark the N_bad targets it made "
      "worse. Spikes in grey show where the registration alone is poor.";
  return f;
}

ReportFigure config_figure(const CellAnalysis& a) {
  std::map<int, std::vector<Eigen::Index>> groups;
  for (std::size_t k = 0; k < a.configs.size(); ++k) {
    if (a.configs[k]) groups[*a.configs[k]].push_back(static_cast<Eigen::Index>(k));
  }
  nlohmann::json x = nlohmann::json::array(), unc = nlohmann::json::array(),
                 cor = nlohmann::json::array();
  for (const auto& [config, rows] : groups) {
    x.push_back("config " + std::to_string(config));
    Eigen::VectorXd u(static_cast<Eigen::Index>(rows.size())), c(u.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
      u[static_cast<Eigen::Index>(i)] = a.unc_tre_m[rows[i]];
      c[static_cast<Eigen::Index>(i)] = a.cor_tre_m[rows[i]];
    }
    unc.push_back(charts::round_to(root_mean_square(u) * 1e3, 4));
    cor.push_back(charts::round_to(root_mean_square(c) * 1e3, 4));
  }
  ReportFigure f;
  f.title = "RMS_T per arm configuration (as paper Fig. 14-15)";
  f.data.push_back({{"type", "bar"},
                    {"name", "uncorrected RMS_T"},
                    {"x", x},
                    {"y", unc},
                    {"marker", {{"color", charts::kUncorrected}}}});
  f.data.push_back({{"type", "bar"},
                    {"name", "corrected RMS_T (RRBC)"},
                    {"x", x},
                    {"y", cor},
                    {"marker", {{"color", charts::kCorrected}}}});
  f.layout = charts::xy_layout("arm configuration (label in the file)", "RMS_T [mm]");
  f.layout["barmode"] = "group";
  f.caption =
      "A configuration with much larger errors is one to avoid, or to register on its own "
      "(Procedure 2, Strategy 2).";
  return f;
}

ReportFigure delta_figure(const CellAnalysis& a) {
  ReportFigure f;
  f.title = "Histogram of ΔTRE where RRBC helped (as paper Fig. 11)";
  const Histogram h = charts::auto_histogram(a.summary.delta_tre_m, 40);
  f.data.push_back(charts::histogram_trace(h, 1e3, "targets", charts::kCorrected));
  f.layout = charts::xy_layout("ΔTRE = TRE(T̂_X) − TRE(T_X)  [mm]", "targets [count]");
  charts::whole_count_ticks(f.layout, h);
  f.caption = std::to_string(a.summary.delta_tre_m.size()) + " of " +
              std::to_string(a.summary.n_targets) +
              " targets improved; the further left, the larger the gain.";
  return f;
}

// Targets coloured by corrected TRE; RRBC's failures and the uncorrectable marked; fiducials
// hidden until clicked in the legend.
nlohmann::json cell_volume_traces(const CellReportInput& in, const CellAnalysis& a) {
  nlohmann::json traces = nlohmann::json::array();
  Points3 fid(3, static_cast<Eigen::Index>(in.model.fiducials.size()));
  for (std::size_t j = 0; j < in.model.fiducials.size(); ++j) {
    fid.col(static_cast<Eigen::Index>(j)) = in.model.fiducials[j].robot_m;
  }
  nlohmann::json fm = {{"size", 2}, {"color", charts::kNeutral}, {"opacity", 0.5}};
  nlohmann::json ft = charts::scatter3d_trace(fid, {}, "fiducials", fm);
  ft["visible"] = "legendonly";
  ft["hoverinfo"] = "skip";
  traces.push_back(ft);
  std::vector<std::string> hover;
  for (std::size_t k = 0; k < a.labels.size(); ++k) {
    const auto n = static_cast<Eigen::Index>(k);
    hover.push_back(a.labels[k] + ": TRE " + num(a.unc_tre_m[n] * 1e3, 3) + " → " +
                    num(a.cor_tre_m[n] * 1e3, 3) + " mm");
  }
  nlohmann::json tm = {{"size", 4},
                       {"color", charts::scaled(a.cor_tre_m, 1e3, 4)},
                       {"colorscale", "Viridis"},
                       {"cmin", 0},
                       {"colorbar", {{"title", {{"text", "corrected TRE [mm]"}}}, {"len", 0.7}}}};
  traces.push_back(charts::scatter3d_trace(a.targets_robot_m, hover, "targets", tm));
  const auto subset = [&](const std::vector<int>& idx, const std::string& name,
                          const nlohmann::json& marker) {
    Points3 p(3, static_cast<Eigen::Index>(idx.size()));
    std::vector<std::string> labels;
    for (std::size_t i = 0; i < idx.size(); ++i) {
      p.col(static_cast<Eigen::Index>(i)) = a.targets_robot_m.col(idx[i]);
      labels.push_back(hover[static_cast<std::size_t>(idx[i])]);
    }
    traces.push_back(charts::scatter3d_trace(p, labels, name, marker));
  };
  subset(a.summary.bad_targets, "RRBC failed (N_bad)",
         {{"size", 8}, {"color", charts::kFailed}, {"symbol", "diamond-open"}});
  std::vector<int> flagged;
  for (std::size_t k = 0; k < in.evaluation.correction.stencils.size(); ++k) {
    if (in.evaluation.correction.stencils[k].status != StencilStatus::kOk)
      flagged.push_back(static_cast<int>(k));
  }
  if (!flagged.empty()) {
    subset(flagged, "not correctable", {{"size", 6}, {"color", "#444"}, {"symbol", "square-open"}});
  }
  return traces;
}

}  // namespace

ReportPage cell_report_page(const CellReportInput& in, const CellAnalysis& a) {
  ReportPage page;
  page.title = "vrreg report — " + in.targets_name;
  page.subtitle =
      "Registration model " + in.model_name + ", targets " + in.targets_name +
      (in.evaluation.config ? " (configuration " + std::to_string(*in.evaluation.config) + ")"
                            : "") +
      ". Lengths in mm; equations as numbered in the NIST paper.";
  page.verdict = cell_verdict(in, a);

  ReportSection summary{"Summary", {}, {summary_table(in, a)}, {}};
  ReportSection rigid{"Rigid-body condition",
                      {"Eq. 1: L_ij = |X_i − X_j| − |Y_i − Y_j| over every pair of the model's "
                       "fiducials, X measured by the sensor and Y commanded to the robot. A rigid "
                       "body would give L = 0 up to noise."},
                      {},
                      {}};
  if (a.rigid_body.pairs > 0) rigid.figures.push_back(l_histogram_figure(a));
  ReportSection errors{"Target registration error", {}, {}, {tre_figure(in, a)}};
  std::map<int, int> configs;
  for (const auto& c : a.configs)
    if (c) ++configs[*c];
  if (configs.size() >= 2) errors.figures.push_back(config_figure(a));
  if (a.summary.delta_tre_m.size() > 0) errors.figures.push_back(delta_figure(a));

  ReportSection volume{"Where RRBC failed", {}, {}, {}};
  ReportFigure f3;
  f3.title = "Targets in the work volume, coloured by corrected TRE (as paper Fig. 10)";
  f3.data = cell_volume_traces(in, a);
  f3.layout = charts::scene_layout("x robot [mm]", "y robot [mm]", "z robot [mm]");
  f3.caption = "Red open diamonds: targets RRBC made worse (N_bad)" +
               (a.where_bad.empty() ? std::string(" — none.") : ": " + a.where_bad + ".") +
               " Drag to turn; failures at the volume's edges point to strong local nonlinearity.";
  volume.figures.push_back(f3);

  page.sections = {summary, rigid, errors, volume};
  page.notes = {"Made by vrreg report from " + in.model_name + " and " + in.targets_name + ".",
                "TRE: distance between the registered (and corrected) target and its robot "
                "position (Eq. 3); RMS_T its root mean square (Eq. 4)."};
  return page;
}

}  // namespace vrreg::report
