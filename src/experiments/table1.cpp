// SPDX-License-Identifier: Apache-2.0
#include "vrreg/experiments/table1.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg::experiments {

void Table1Options::validate() const {
  VRREG_THROW_UNLESS(std::isfinite(cube_edge_m) && cube_edge_m > 0.0,
                     "Table 1: the octuplet cube edge must be > 0, got " << cube_edge_m << " m");
  VRREG_THROW_UNLESS(std::isfinite(sigma_rep_m) && sigma_rep_m >= 0.0,
                     "Table 1: the repeatability must be >= 0, got " << sigma_rep_m << " m");
  VRREG_THROW_UNLESS(
      std::isfinite(l_histogram_bin_m) && l_histogram_bin_m >= 0.0,
      "Table 1: the L histogram bin must be >= 0, got " << l_histogram_bin_m << " m");
}

double octuplet_distance_m(double cube_edge_m) { return 0.5 * std::sqrt(3.0) * cube_edge_m; }

Table1Entry run_table1_entry(const MeasurementSet& set, const std::string& dataset,
                             const Table1Options& options) {
  options.validate();
  RrbcRunOptions run;
  run.interpolation.method = InterpolationMethod::kOctuplet;
  run.interpolation.cube_edge_m = options.cube_edge_m;
  run.sigma_rep_m = options.sigma_rep_m;
  run.l_histogram_bin_m = options.l_histogram_bin_m;
  Table1Entry out;
  out.dataset = dataset;
  out.cube_edge_m = options.cube_edge_m;
  out.d_m = octuplet_distance_m(options.cube_edge_m);
  out.figures = run_rrbc(set, set.select(Role::kFiducial), set.select(Role::kTarget), run);
  return out;
}

}  // namespace vrreg::experiments
