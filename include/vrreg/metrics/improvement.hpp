// SPDX-License-Identifier: Apache-2.0
#pragma once
// How much RRBC helped: uncorrected vs corrected RMS_T, gamma, N_bad, Delta TRE (section 5.1).
#include <Eigen/Core>
#include <vector>

namespace vrreg {

/// Summary of corrected against uncorrected target errors.
struct ImprovementSummary {
  int n_targets = 0;               ///< the targets summarised
  double unc_rms_t_m = 0.0;        ///< RMS_T of TRE(T_X) (Eq. 4)
  double cor_rms_t_m = 0.0;        ///< RMS_T of TRE(T^_X)
  double unc_max_tre_m = 0.0;      ///< largest TRE(T_X)
  double cor_max_tre_m = 0.0;      ///< largest TRE(T^_X)
  double gamma = 0.0;              ///< (unc - cor) / unc, a fraction (x100 for the paper's %)
  int n_bad = 0;                   ///< targets where TRE(T^_X) > TRE(T_X)
  std::vector<int> bad_targets{};  ///< their indices
  Eigen::VectorXd delta_tre_m{};   ///< TRE(T^_X) - TRE(T_X) where it improved (< 0), Fig. 11
};

/// Compares per-target uncorrected and corrected TRE [m] (same order, same length).
ImprovementSummary summarize_improvement(const Eigen::Ref<const Eigen::VectorXd>& unc_tre_m,
                                         const Eigen::Ref<const Eigen::VectorXd>& cor_tre_m);

}  // namespace vrreg
