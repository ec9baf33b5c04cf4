// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal: leave-one-out residuals of an exact universal-kriging model in closed form, and the
// latent-sd scale that makes them calibrated (docs/field-models.md, "Predicted sd").
#include <Eigen/Core>

#include "kriging_posterior.hpp"

namespace vrreg::detail {

/// Fiducial i left out: residual y_i - mean_{-i}(x_i), and the predictive variance of y_i given
/// the others (latent posterior variance + nugget^2, the trend re-estimated without i).
struct KrigingLeaveOneOut {
  Eigen::VectorXd residual_m;
  Eigen::VectorXd variance_m2;
};

/// Dubrule's (1983) closed form for universal kriging: with P = K^-1 - K^-1 F A^-1 F' K^-1,
/// residual_i = (P y)_i / P_ii = alpha_i / P_ii and variance_i = 1 / P_ii. O(J^3 / 3) for the
/// inverse of the Cholesky factor. A non-positive P_ii (rounding; a fiducial the others fix
/// exactly) gives NaN for that fiducial.
[[nodiscard]] KrigingLeaveOneOut leave_one_out(const KrigingPosterior& posterior);

/// The factor c on the latent posterior sd with mean_i residual_i^2 / (c^2 (variance_i - nugget^2)
/// + nugget^2) = 1 over the finite fiducials: the leave-one-out z-scores get unit mean square, the
/// nugget (the fiducials' own noise) kept. 1 when the mean square at c = 1 is within
/// kLooSignificance standard errors (sqrt(2 / N)) of 1, or no fiducial has latent variance left;
/// clamped to [kMinLatentSdScale, kMaxLatentSdScale].
[[nodiscard]] double loo_latent_sd_scale(const KrigingLeaveOneOut& loo, double nugget_sd_m);

inline constexpr double kLooSignificance = 3.0;

inline constexpr double kMinLatentSdScale = 0.1;
inline constexpr double kMaxLatentSdScale = 10.0;

}  // namespace vrreg::detail
