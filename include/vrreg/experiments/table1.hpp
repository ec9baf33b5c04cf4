// SPDX-License-Identifier: Apache-2.0
#pragma once
// Table 1 (paper sections 4.3, 5.1): one UR5 grid dataset (A1 or A2) through the pipeline with
// octuplet corrections of edge a, so that every target sits at d = sqrt(3)/2 a from its
// fiducials; the L histogram of Fig. 4 on request.
#include <string>

#include "vrreg/core/measurement.hpp"
#include "vrreg/experiments/rrbc_run.hpp"

namespace vrreg::experiments {

/// How to process one Table 1 dataset.
struct Table1Options {
  double cube_edge_m = 0.050;      ///< octuplet edge a [m]: 50 mm for A1, 25 mm for A2
  double sigma_rep_m = 0.1e-3;     ///< robot repeatability for sigma_noise (Eq. 9) [m]
  double l_histogram_bin_m = 0.0;  ///< > 0: also the L histogram (Fig. 4) in these bins [m]
  /// Throws InputError on a cube edge that is not > 0 or a negative repeatability or bin.
  void validate() const;
};

/// One row of Table 1.
struct Table1Entry {
  std::string dataset{};     ///< e.g. "A1"
  double cube_edge_m = 0.0;  ///< a [m]
  double d_m = 0.0;          ///< target-fiducial distance sqrt(3)/2 a [m]
  RrbcRunFigures figures{};  ///< sigma_opt, sigma_L, sigma_noise, rho, RMS_T, gamma, N_bad
};

/// Target-fiducial distance of an octuplet of edge a: d = sqrt(3)/2 a (section 4.1) [m].
double octuplet_distance_m(double cube_edge_m);

/// Table 1 (section 4.3): registers all fiducials of `set`, corrects all its targets with
/// octuplets of options.cube_edge_m and compares uncorrected with corrected errors.
Table1Entry run_table1_entry(const MeasurementSet& set, const std::string& dataset,
                             const Table1Options& options);

}  // namespace vrreg::experiments
