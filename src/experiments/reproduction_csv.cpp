// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/reproduction_csv.hpp"

#include <cmath>
#include <cstdio>

#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/experiments/paper_numbers.hpp"

namespace vrreg::experiments {
namespace {

using units::kMillimetresPerMetre;

// Shortest round-trip-ish text of a number; empty for NaN.
std::string num(double v) {
  if (std::isnan(v)) return "";
  return format_general(v, 10);
}

std::string mean_of(const CellTable& t, const std::string& pointer) {
  const CellSummary* c = t.find(pointer);
  return c ? num(c->mean) : "";
}

std::string sd_of(const CellTable& t, const std::string& pointer) {
  const CellSummary* c = t.find(pointer);
  return c ? num(c->sd) : "";
}

void histogram_rows(const Histogram& h, const std::string& prefix, std::string& out) {
  for (std::size_t k = 0; k < h.counts.size(); ++k) {
    const double lo = h.lo_m + h.bin_width_m * static_cast<double>(k);
    out += prefix + num(kMillimetresPerMetre * lo) + "," +
           num(kMillimetresPerMetre * (lo + h.bin_width_m)) + "," + std::to_string(h.counts[k]) +
           "\n";
  }
}

}  // namespace

std::string table1_csv(const CellTable& t) {
  static const char* const kColumns[] = {"d_mm",  "sigma_opt_mm", "sigma_l_mm",   "sigma_noise_mm",
                                         "rho",   "unc_rms_t_mm", "cor_rms_t_mm", "gamma_percent",
                                         "n_bad", "n_targets",    "n_fiducials"};
  std::string out = "dataset,source";
  for (const char* c : kColumns) out += std::string(",") + c;
  out += "\n";
  for (const paper::Table1Row& p : paper::kTable1) {
    const std::string k = std::string("/table1/") + p.dataset + "/";
    if (t.find(k + "d_mm") == nullptr) continue;
    out += std::string(p.dataset) + ",vrreg";
    for (const char* c : kColumns) out += "," + mean_of(t, k + c);
    out += "\n" + std::string(p.dataset) + ",vrreg_sd";
    for (const char* c : kColumns) out += "," + sd_of(t, k + c);
    out += "\n" + std::string(p.dataset) + ",paper," + num(p.d_mm) + "," + num(p.sigma_opt_mm) +
           "," + num(p.sigma_l_mm) + "," + num(p.sigma_noise_mm) + "," + num(p.rho) + "," +
           num(p.unc_rms_t_mm) + "," + num(p.cor_rms_t_mm) + "," + num(p.gamma_percent) + ",," +
           std::to_string(p.targets) + "," + std::to_string(p.fiducials) + "\n";
  }
  return out;
}

std::string figure7_8_csv(const CellTable& t) {
  const paper::DatasetB& p = paper::kDatasetB;
  std::string out =
      "d_mm,cube_mm,cor_rms_t_mm,cor_rms_t_mm_sd,n_bad,n_bad_sd,gamma_percent,gamma_percent_sd,"
      "unc_rms_t_mm,paper_cor_rms_t_mm,paper_n_bad,paper_gamma_percent\n";
  for (int k = 0;; ++k) {
    const std::string s = "/figure7/" + std::to_string(k) + "/";
    const CellSummary* d = t.find(s + "d_mm");
    if (d == nullptr) break;
    const bool d_max = std::abs(d->mean - p.d_max_mm) < 0.05;
    const bool d_min = std::abs(d->mean - p.d_min_mm) < 0.05;
    out += num(d->mean) + "," + mean_of(t, s + "cube_mm") + "," + mean_of(t, s + "cor_rms_t_mm") +
           "," + sd_of(t, s + "cor_rms_t_mm") + "," + mean_of(t, s + "n_bad") + "," +
           sd_of(t, s + "n_bad") + "," + mean_of(t, s + "gamma_percent") + "," +
           sd_of(t, s + "gamma_percent") + "," + mean_of(t, "/dataset_b/unc_rms_t_mm") + "," +
           (d_min ? num(p.cor_rms_t_at_d_min_mm()) : "") + "," +
           (d_max   ? std::to_string(p.n_bad_at_d_max)
            : d_min ? std::to_string(p.n_bad_at_d_min)
                    : "") +
           "," + (d_min ? num(p.gamma_at_d_min_percent) : "") + "\n";
  }
  return out;
}

std::string table2_csv(const CellTable& t) {
  static const char* const kColumns[] = {"sigma_l_mm",   "rho",           "unc_rms_t_mm",
                                         "cor_rms_t_mm", "gamma_percent", "n_bad"};
  std::string out = "config,strategy";
  for (const char* c : kColumns) out += std::string(",") + c + "," + c + "_sd";
  out +=
      ",n_targets,n_switched_locations,paper_sigma_l_mm,paper_rho,paper_unc_rms_t_mm,"
      "paper_cor_rms_t_mm,paper_gamma_percent\n";
  for (int k = 0;; ++k) {
    const std::string s = "/table2/" + std::to_string(k) + "/";
    const CellSummary* config = t.find(s + "config");
    if (config == nullptr) break;
    const int m = static_cast<int>(config->mean);
    const int strategy = static_cast<int>(t.find(s + "strategy")->mean);
    out += std::to_string(m) + "," + std::to_string(strategy);
    for (const char* c : kColumns) out += "," + mean_of(t, s + c) + "," + sd_of(t, s + c);
    out += "," + mean_of(t, s + "n_targets") + "," + mean_of(t, s + "n_switched_locations");
    const paper::Table2Row* p = nullptr;
    for (const paper::Table2Row& row : paper::kTable2) {
      if (row.config == m) p = &row;
    }
    const auto i = static_cast<std::size_t>(strategy - 1);
    if (p != nullptr && i < 3) {
      out += "," + (i < 2 ? num(p->sigma_l_mm[i]) : "") + "," + (i < 2 ? num(p->rho[i]) : "") +
             "," + num(p->unc_rms_t_mm[i]) + "," + num(p->cor_rms_t_mm[i]) + "," +
             num(p->gamma_percent[i]);
    } else {
      out += ",,,,,";
    }
    out += "\n";
  }
  return out;
}

std::string histograms_l_csv(const Reproduction& r) {
  std::string out = "figure,dataset,strategy,config,bin_lo_mm,bin_hi_mm,count\n";
  for (const auto* e : {&r.a1, &r.a2}) {
    if (*e && (*e)->figures.l_histogram) {
      histogram_rows(*(*e)->figures.l_histogram, "4," + (*e)->dataset + ",,,", out);
    }
  }
  if (r.table2) {
    for (const Table2Entry& e : r.table2->entries) {
      if (e.strategy == 3 || !e.figures.l_histogram) continue;
      histogram_rows(*e.figures.l_histogram,
                     std::string(e.strategy == 1 ? "5" : "6") + ",kuka," +
                         std::to_string(e.strategy) + "," + std::to_string(e.config) + ",",
                     out);
    }
  }
  return out;
}

std::string figure10_targets_csv(const Reproduction& r) {
  std::string out =
      "n,point,robot_x_mm,robot_y_mm,robot_z_mm,unc_tre_mm,cor_tre_d_max_mm,cor_tre_d_min_mm,"
      "delta_tre_d_min_mm,failed_at_d_max,failed_at_d_min,n_failed,category\n";
  if (!r.b) return out;
  const DistanceSweep& b = *r.b;
  const SweepStep& hi = b.at_d_max();
  const SweepStep& lo = b.at_d_min();
  for (std::size_t n = 0; n < b.target_points.size(); ++n) {
    const auto i = static_cast<Eigen::Index>(n);
    int failed = 0;
    for (const SweepStep& s : b.steps) failed += s.cor_tre_m[i] > b.unc_tre_m[i] ? 1 : 0;
    const bool f_hi = hi.cor_tre_m[i] > b.unc_tre_m[i];
    const bool f_lo = lo.cor_tre_m[i] > b.unc_tre_m[i];
    const char* category = f_hi && f_lo ? "failed_at_both"
                           : f_hi       ? "failed_at_d_max"
                           : f_lo       ? "failed_at_d_min_only"
                           : failed > 0 ? "failed_at_other_d"
                                        : "succeeded_at_all_d";
    out += std::to_string(n + 1) + "," + b.target_points[n] + "," +
           num(kMillimetresPerMetre * b.target_robot_m(0, i)) + "," +
           num(kMillimetresPerMetre * b.target_robot_m(1, i)) + "," +
           num(kMillimetresPerMetre * b.target_robot_m(2, i)) + "," +
           num(kMillimetresPerMetre * b.unc_tre_m[i]) + "," +
           num(kMillimetresPerMetre * hi.cor_tre_m[i]) + "," +
           num(kMillimetresPerMetre * lo.cor_tre_m[i]) + "," +
           num(kMillimetresPerMetre * (lo.cor_tre_m[i] - b.unc_tre_m[i])) + "," +
           (f_hi ? "1" : "0") + "," + (f_lo ? "1" : "0") + "," + std::to_string(failed) + "," +
           category + "\n";
  }
  return out;
}

std::string figure11_delta_tre_csv(const Reproduction& r) {
  std::string out = "bin_lo_mm,bin_hi_mm,count\n";
  if (r.b) histogram_rows(r.b->delta_tre_histogram, "", out);
  return out;
}

std::string tre_per_target_csv(const Reproduction& r) {
  std::string out =
      "figure,strategy,config,n,point,robot_x_mm,robot_y_mm,robot_z_mm,unc_tre_mm,cor_tre_mm\n";
  if (!r.table2) return out;
  for (const Table2Entry& e : r.table2->entries) {
    const std::string figure = e.strategy == 1 ? "12" : e.strategy == 2 ? "13" : "";
    for (std::size_t n = 0; n < e.target_points.size(); ++n) {
      const auto i = static_cast<Eigen::Index>(n);
      out += figure + "," + std::to_string(e.strategy) + "," + std::to_string(e.config) + "," +
             std::to_string(n + 1) + "," + e.target_points[n] + "," +
             num(kMillimetresPerMetre * e.target_robot_m(0, i)) + "," +
             num(kMillimetresPerMetre * e.target_robot_m(1, i)) + "," +
             num(kMillimetresPerMetre * e.target_robot_m(2, i)) + "," +
             num(kMillimetresPerMetre * e.figures.unc_tre_m[i]) + "," +
             num(kMillimetresPerMetre * e.figures.cor_tre_m[i]) + "\n";
    }
  }
  return out;
}

}  // namespace vrreg::experiments
