// SPDX-License-Identifier: Apache-2.0
#pragma once
// One pass of the paper's pipeline on measured locations (sections 4.3, 4.4): register the
// fiducials (Eq. 2), rigid-body condition (Eq. 1), noise (Eq. 9), RRBC-correct the targets
// (Eq. 6-8) and compare uncorrected with corrected target errors (Eq. 3, 4, gamma, N_bad).
#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "vrreg/core/measurement.hpp"
#include "vrreg/correction/interpolation.hpp"
#include "vrreg/metrics/rigid_body.hpp"

namespace vrreg::experiments {

/// How to run the pipeline.
struct RrbcRunOptions {
  InterpolationSettings interpolation{};  ///< e.g. octuplet with a cube edge
  double sigma_rep_m = 0.0;               ///< robot repeatability for sigma_noise (Eq. 9) [m]
  /// sigma_opt to use instead of the fiducials' repeat readings (e.g. K = 1) [m].
  std::optional<double> sigma_opt_m{};
  bool rigid_body_statistics = true;  ///< compute sigma_L (all pairs; the slow part)
  /// > 0: also the histogram of L_ij (Eq. 1, Fig. 4-6) in bins of this width [m], spanning the
  /// observed range (edges at multiples of the width). Needs rigid_body_statistics.
  double l_histogram_bin_m = 0.0;
};

/// The figures of one run (paper Tables 1 and 2); lengths in m, gamma a fraction.
struct RrbcRunFigures {
  int n_fiducials = 0;
  int n_targets = 0;
  double sigma_opt_m = 0.0;  ///< from repeat readings (or the option); 0 when unknown
  double sigma_l_m = 0.0;    ///< 0 when not computed
  double sigma_noise_m = 0.0;
  double rho = 0.0;
  double unc_rms_t_m = 0.0;
  double cor_rms_t_m = 0.0;
  double gamma = 0.0;
  int n_bad = 0;
  int n_flagged = 0;          ///< targets the interpolation could not correct
  Eigen::VectorXd unc_tre_m{};  ///< TRE(T_X) per target, in the order given (Eq. 3; Fig. 12-13)
  Eigen::VectorXd cor_tre_m{};  ///< TRE(T^_X) per target
  std::optional<Histogram> l_histogram{};  ///< when RrbcRunOptions::l_histogram_bin_m > 0
};

/// Histogram of L_ij (Eq. 1; Fig. 4-6) over all pairs in bins of `bin_m` [m] whose edges are
/// multiples of `bin_m`, from the bin holding `range.min_m` to the one holding `range.max_m`
/// (`range`: rigid_body_statistics of the same points).
Histogram l_histogram(const ConstPoints3Ref& sensor_m, const ConstPoints3Ref& robot_m, double bin_m,
                      const RigidBodyStatistics& range);

/// Runs the pipeline with fiducials `fiducials` and targets `targets` (indices into `set`).
RrbcRunFigures run_rrbc(const MeasurementSet& set, const std::vector<std::size_t>& fiducials,
                        const std::vector<std::size_t>& targets, const RrbcRunOptions& options);

}  // namespace vrreg::experiments
