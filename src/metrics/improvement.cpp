// SPDX-License-Identifier: Apache-2.0
#include "vrreg/metrics/improvement.hpp"

#include "vrreg/core/check.hpp"
#include "vrreg/metrics/errors.hpp"

namespace vrreg {

ImprovementSummary summarize_improvement(const Eigen::Ref<const Eigen::VectorXd>& unc_tre_m,
                                         const Eigen::Ref<const Eigen::VectorXd>& cor_tre_m) {
  VRREG_THROW_UNLESS(unc_tre_m.size() == cor_tre_m.size(),
                     "improvement needs one corrected TRE per uncorrected TRE: "
                         << unc_tre_m.size() << " vs " << cor_tre_m.size());
  ImprovementSummary s;
  s.n_targets = static_cast<int>(unc_tre_m.size());
  s.unc_rms_t_m = root_mean_square(unc_tre_m);
  s.cor_rms_t_m = root_mean_square(cor_tre_m);
  s.unc_max_tre_m = unc_tre_m.size() > 0 ? unc_tre_m.maxCoeff() : 0.0;
  s.cor_max_tre_m = cor_tre_m.size() > 0 ? cor_tre_m.maxCoeff() : 0.0;
  s.gamma = s.unc_rms_t_m > 0.0 ? (s.unc_rms_t_m - s.cor_rms_t_m) / s.unc_rms_t_m : 0.0;
  std::vector<double> improved;
  for (Eigen::Index n = 0; n < unc_tre_m.size(); ++n) {
    const double delta = cor_tre_m[n] - unc_tre_m[n];
    if (delta > 0.0) {
      ++s.n_bad;
      s.bad_targets.push_back(static_cast<int>(n));
    } else if (delta < 0.0) {
      improved.push_back(delta);
    }
  }
  s.delta_tre_m = Eigen::Map<const Eigen::VectorXd>(improved.data(),
                                                    static_cast<Eigen::Index>(improved.size()));
  return s;
}

}  // namespace vrreg
