// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/beyond_report.hpp"

#include <cmath>
#include <limits>

#include "text_table.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::experiments {
namespace {

using text::decimal_text;
using units::kMillimetresPerMetre;
constexpr double kMilliradiansPerRadian = 1e3;
constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

// "strategy 2" -> "strategy_2": a JSON pointer segment.
std::string method_key(std::string method) {
  for (char& ch : method) ch = ch == ' ' ? '_' : ch;
  return method;
}

std::string prefix(const BeyondTable& t) { return "/beyond/" + t.key + "/"; }

// Mean, or "mean ± sd" over several seeds; "-" when undefined (on some seed).
std::string shown(const CellTable& t, const std::string& pointer, int decimals, double scale = 1) {
  const CellSummary* c = t.find(pointer);
  if (c == nullptr || std::isnan(c->mean)) return "-";
  std::string out = decimal_text(scale * c->mean, decimals);
  if (t.n_seeds > 1 && c->kind == CellKind::kValue)
    out += " ± " + decimal_text(scale * c->sd, decimals);
  return out;
}

// What auto chooses between (pipeline/cross_validation.cpp).
const std::vector<InterpolationMethod>& auto_choices() {
  static const std::vector<InterpolationMethod> methods = {
      InterpolationMethod::kScattered, InterpolationMethod::kTrilinear, InterpolationMethod::kRbf,
      InterpolationMethod::kKriging, InterpolationMethod::kJoint};
  return methods;
}

// auto's choice: the method chosen on most seeds, with on how many when not all.
std::string auto_choice(const CellTable& t, const std::string& p) {
  std::string best;
  double best_fraction = 0.0;
  for (const InterpolationMethod m : auto_choices()) {
    const CellSummary* c = t.find(p + "chose_" + to_string(m));
    if (c != nullptr && !std::isnan(c->mean) && c->mean > best_fraction) {
      best_fraction = c->mean;
      best = to_string(m);
    }
  }
  if (best.empty()) return "";
  if (best_fraction < 1.0) {
    best += " " + std::to_string(static_cast<int>(std::lround(best_fraction * t.n_seeds))) + "/" +
            std::to_string(t.n_seeds);
  }
  return " (" + best + ")";
}

}  // namespace

void append_beyond_cells(const std::vector<BeyondTable>& tables, std::vector<Cell>& out) {
  const auto value = [&out](const std::string& p, double v) {
    out.push_back({p, CellKind::kValue, v});
  };
  const auto count = [&out](const std::string& p, double v) {
    out.push_back({p, CellKind::kCount, v});
  };
  for (const BeyondTable& t : tables) {
    const std::string p = prefix(t);
    count(p + "n_fiducials", t.n_fiducials);
    count(p + "n_targets", t.n_targets);
    value(p + "unc_rms_t_mm", kMillimetresPerMetre * t.unc_rms_t_m);
    value(p + "noise_floor_mm", kMillimetresPerMetre * t.noise_floor_m);
    for (const BeyondRow& r : t.rows) {
      const std::string q = p + method_key(r.method) + "/";
      const double cor = r.ok ? r.cor_rms_t_m : kNoValue;
      value(q + "cor_rms_t_mm", kMillimetresPerMetre * cor);
      value(q + "over_floor", t.noise_floor_m > 0.0 ? cor / t.noise_floor_m : kNoValue);
      value(q + "calibration_rms_ratio", r.ok ? r.calibration_rms_ratio : kNoValue);
      value(q + "within_2sigma_percent", r.ok ? 100.0 * r.within_2sigma : kNoValue);
      count(q + "n_flagged", r.ok ? r.n_flagged : kNoValue);
      if (r.method == to_string(InterpolationMethod::kAuto)) {
        for (const InterpolationMethod m : auto_choices()) {
          value(q + "chose_" + to_string(m), !r.ok                      ? kNoValue
                                             : r.chosen == to_string(m) ? 1.0
                                                                        : 0.0);
        }
      }
      if (std::isnan(t.unc_rms_angle_rad)) continue;  // positions only
      const double angle = r.ok ? r.cor_rms_angle_rad : kNoValue;
      value(q + "cor_rms_angle_mrad", kMilliradiansPerRadian * angle);
      value(q + "angle_over_floor",
            t.angle_noise_floor_rad > 0.0 ? angle / t.angle_noise_floor_rad : kNoValue);
      value(q + "angle_calibration_rms_ratio", r.ok ? r.angle_calibration_rms_ratio : kNoValue);
    }
    if (std::isnan(t.unc_rms_angle_rad)) continue;
    value(p + "unc_rms_angle_mrad", kMilliradiansPerRadian * t.unc_rms_angle_rad);
    value(p + "angle_noise_floor_mrad", kMilliradiansPerRadian * t.angle_noise_floor_rad);
  }
}

std::string format_beyond_orientation(const CellTable& cells,
                                      const std::vector<BeyondTable>& first_seed) {
  std::string out;
  for (const BeyondTable& t : first_seed) {
    const std::string p = prefix(t);
    if (cells.find(p + "unc_rms_angle_mrad") == nullptr) continue;
    out += "\n" + t.dataset + ": unc RMS angle " + shown(cells, p + "unc_rms_angle_mrad", 3) +
           ", noise floor " + shown(cells, p + "angle_noise_floor_mrad", 3) + "\n";
    text::TextTable table;
    table.add({"method", "cor RMS angle", "x floor", "angle/sd"});
    for (const BeyondRow& r : t.rows) {
      const std::string q = p + method_key(r.method) + "/";
      if (cells.find(q + "cor_rms_angle_mrad") == nullptr) continue;  // the paper's rows
      table.add({r.method, shown(cells, q + "cor_rms_angle_mrad", 3),
                 shown(cells, q + "angle_over_floor", 2),
                 shown(cells, q + "angle_calibration_rms_ratio", 2)});
    }
    out += table.str();
  }
  if (out.empty()) return out;
  return "Orientations beyond the paper (docs/orientation.md): the test beds' rigid-body marker,\n"
         "each method's field interpolating the fiducials' rotation residuals; angles in mrad.\n"
         "'x floor' = cor RMS angle / its noise floor (the targets' own orientation noise);\n"
         "angle/sd = RMS of angle error / predicted sd.\n" +
         out + "\n";
}

std::string format_beyond_tables(const CellTable& cells,
                                 const std::vector<BeyondTable>& first_seed) {
  if (first_seed.empty()) return "";
  std::string out =
      "Beyond the paper. The paper's RRBC beside the field models (docs/field-models.md), one\n"
      "registration of all the dataset's fiducials; lengths in mm. 'x floor' = cor RMS_T / the\n"
      "noise floor (what a perfect correction of the systematic error would leave: the targets'\n"
      "own noise, from a noise-free re-simulation of the seed). TRE/sd = RMS of TRE / predicted\n"
      "sd (1 = honest); '2 sd %' = targets with TRE <= 2 predicted sd. '-': not applicable or not\n"
      "built yet (the reason, on the first seed, under each table).\n";
  for (const BeyondTable& t : first_seed) {
    const std::string p = prefix(t);
    out += "\n" + t.dataset + ": " + shown(cells, p + "n_fiducials", 0) + " fiducials, " +
           shown(cells, p + "n_targets", 0) + " targets; unc RMS_T " +
           shown(cells, p + "unc_rms_t_mm", 3) + ", noise floor " +
           shown(cells, p + "noise_floor_mm", 3) + "\n";
    text::TextTable table;
    // Over several seeds the median of cor RMS_T too: one seed's cell can be a lucky or an unlucky robot.
    const bool seeds = cells.n_seeds > 1;
    if (seeds) {
      table.add({"method", "cor RMS_T", "median", "x floor", "TRE/sd", "2 sd %", "flagged"});
    } else {
      table.add({"method", "cor RMS_T", "x floor", "TRE/sd", "2 sd %", "flagged"});
    }
    std::string why;  // rows without numbers, with the reason (first seed), under the table
    for (const BeyondRow& r : t.rows) {
      const std::string q = p + method_key(r.method) + "/";
      const bool is_auto = r.method == to_string(InterpolationMethod::kAuto);
      const CellSummary* cor = cells.find(q + "cor_rms_t_mm");
      const bool none = cor == nullptr || std::isnan(cor->mean);
      std::vector<std::string> row = {r.method + (is_auto ? auto_choice(cells, q) : ""),
                                      shown(cells, q + "cor_rms_t_mm", 3)};
      if (seeds) row.push_back(none ? "-" : decimal_text(cor->median, 3));
      for (const std::string& cell :
           {shown(cells, q + "over_floor", 2), shown(cells, q + "calibration_rms_ratio", 2),
            shown(cells, q + "within_2sigma_percent", 0), shown(cells, q + "n_flagged", 0)})
        row.push_back(cell);
      table.add(row);
      if (none && !r.ok) why += "    " + r.method + ": " + r.note + "\n";
    }
    out += table.str();
    if (!why.empty()) out += "  -:\n" + why;
  }
  return out + "\n" + format_beyond_orientation(cells, first_seed);
}

std::string beyond_csv(const CellTable& cells, const std::vector<BeyondTable>& first_seed) {
  static const char* const kColumns[] = {"cor_rms_t_mm", "over_floor", "calibration_rms_ratio",
                                         "within_2sigma_percent", "n_flagged"};
  const auto num = [](const CellSummary* c, bool sd) {
    if (c == nullptr) return std::string();
    const double v = sd ? c->sd : c->mean;
    return std::isnan(v) ? std::string() : format_general(v, 10);
  };
  std::string out = "dataset,method,n_seeds,n_fiducials,n_targets,unc_rms_t_mm,noise_floor_mm";
  for (const char* c : kColumns) out += std::string(",") + c + "," + c + "_sd";
  out += ",cor_rms_t_mm_median";
  static const char* const kAngleColumns[] = {"cor_rms_angle_mrad", "angle_over_floor",
                                              "angle_calibration_rms_ratio"};
  out += ",unc_rms_angle_mrad,angle_noise_floor_mrad";
  for (const char* c : kAngleColumns) out += std::string(",") + c + "," + c + "_sd";
  out += "\n";
  for (const BeyondTable& t : first_seed) {
    const std::string p = prefix(t);
    for (const BeyondRow& r : t.rows) {
      const std::string q = p + method_key(r.method) + "/";
      out += t.key + "," + method_key(r.method) + "," + std::to_string(cells.n_seeds) + "," +
             num(cells.find(p + "n_fiducials"), false) + "," +
             num(cells.find(p + "n_targets"), false) + "," +
             num(cells.find(p + "unc_rms_t_mm"), false) + "," +
             num(cells.find(p + "noise_floor_mm"), false);
      for (const char* c : kColumns) {
        out += "," + num(cells.find(q + c), false) + "," + num(cells.find(q + c), true);
      }
      const CellSummary* cor = cells.find(q + "cor_rms_t_mm");
      out += "," + (cor == nullptr || std::isnan(cor->median) ? std::string()
                                                               : format_general(cor->median, 10));
      out += "," + num(cells.find(p + "unc_rms_angle_mrad"), false) + "," +
             num(cells.find(p + "angle_noise_floor_mrad"), false);
      for (const char* c : kAngleColumns) {
        out += "," + num(cells.find(q + c), false) + "," + num(cells.find(q + c), true);
      }
      out += "\n";
    }
  }
  return out;
}

}  // namespace vrreg::experiments
