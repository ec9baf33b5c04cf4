// SPDX-License-Identifier: Apache-2.0
#pragma once
// Universal kriging (Gaussian-process regression with a polynomial trend) of a 3-vector field,
// one independent model per axis: the fiducial corrections epsilon_j (paper Eq. 6) as a smooth
// field of the fiducials' nominal robot positions, predicted at the targets with a posterior
// standard deviation (docs/field-models.md).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/correction_values.hpp"
#include "vrreg/correction/field_prediction.hpp"
#include "vrreg/correction/method_state.hpp"

namespace vrreg {

/// Stationary covariance of the latent field, in the anisotropic distance
/// r = sqrt(sum_i (dx_i / length_i)^2).
enum class KrigingKernel {
  matern52,            ///< s^2 (1 + sqrt5 r + 5 r^2 / 3) exp(-sqrt5 r): twice differentiable
  squared_exponential  ///< s^2 exp(-r^2 / 2): infinitely smooth
};

/// Hyperparameters of one axis' model.
struct KrigingHyperparameters {
  Eigen::Vector3d length_m = Eigen::Vector3d::Constant(0.1);  ///< per robot axis x, y, z [m]
  double signal_sd_m = 1e-4;  ///< sd of the latent field around its trend [m]
  double nugget_sd_m = 1e-5;  ///< sd of the independent noise of one fiducial value [m]
};

struct KrigingOptions {
  /// Polynomial trend degree 0, 1 or 2 (1, 4 or 10 terms); the trend's coefficients are
  /// estimated (universal kriging) and their uncertainty enters the predicted sd.
  int trend_degree = 2;
  KrigingKernel kernel = KrigingKernel::matern52;
  /// Known sd of the noise of one fiducial value [m] (e.g. from repeats): a lower bound on the
  /// fitted nugget sd (nugget variance = noise_sd^2 + a fitted non-negative excess, which
  /// absorbs field structure shorter than the fiducial spacing). Unset: the nugget is free.
  std::optional<double> noise_sd_m{};
  /// Up to this many fiducials the model is exact (dense Cholesky of all of them); above it,
  /// each query is predicted from its `local_neighbours` nearest fiducials.
  Eigen::Index exact_limit = 2000;
  Eigen::Index local_neighbours = 150;
  /// The hyperparameters are fitted on at most this many fiducials: all of them if there are
  /// fewer, else clusters of the `fit_cluster` nearest fiducials around seeded centres (below):
  /// the clusters keep the short pairs that reveal a short length scale, the spread centres the
  /// long ones (1: a uniform random subset).
  Eigen::Index fit_subset = 500;
  Eigen::Index fit_cluster = 64;
  std::uint64_t subset_seed = 1;
  /// Starts of the optimiser (deterministic: length scales at fractions of the extent).
  int restarts = 2;
  int max_iterations = 60;
  /// Check the predicted sd by leave-one-out (exact models): when the fiducials' leave-one-out
  /// z-scores have a mean square more than 3 standard errors from 1, that axis' latent posterior
  /// sd is multiplied by the factor that makes it 1, the nugget kept
  /// (KrigingAxisFit::latent_sd_scale): e.g. a signal sd misstated, or hyperparameters from other
  /// data. Local models (J > exact_limit) keep factor 1.
  bool loo_sd_calibration = true;
  /// Given factors instead (e.g. a model refitted on a subset keeps its parent's): no
  /// leave-one-out, in exact and local models alike. Each must be finite and > 0.
  std::optional<std::array<double, 3>> latent_sd_scale{};
};

/// Result of fitting one axis' hyperparameters.
struct KrigingAxisFit {
  KrigingHyperparameters hyperparameters{};
  double restricted_log_likelihood = 0.0;  ///< REML objective at the optimum (fit subset)
  int evaluations = 0;                     ///< likelihood + gradient evaluations, all starts
  Eigen::Index n_fit = 0;                  ///< fiducials the hyperparameters were fitted on
  /// Factor on the latent posterior sd (KrigingOptions::loo_sd_calibration); 1: none.
  double latent_sd_scale = 1.0;
};

/// A fitted per-axis universal-kriging model of a 3-vector field.
class KrigingModel {
 public:
  /// Fits hyperparameters per axis by maximum restricted (REML) marginal likelihood, then
  /// conditions on all fiducials. positions_m: 3 x J nominal robot positions [m]; values_m:
  /// 3 x J field values [m]. Throws InputError for J < trend terms + 1, non-finite input, a
  /// trend the positions cannot determine (e.g. coplanar fiducials with degree >= 1), or bad
  /// options.
  static KrigingModel fit(const ConstPoints3Ref& positions_m, const ConstPoints3Ref& values_m,
                          const KrigingOptions& options = {});
  /// Conditions on the fiducials with given hyperparameters (no fit; tests, reuse).
  static KrigingModel with_hyperparameters(
      const ConstPoints3Ref& positions_m, const ConstPoints3Ref& values_m,
      const std::array<KrigingHyperparameters, 3>& hyperparameters,
      const KrigingOptions& options = {});

  /// The model saved by save() for the same positions and values, conditioned again with its
  /// saved hyperparameters and sd factors (no fit, no leave-one-out): the same predictions, bit
  /// for bit. Throws InputError when the state is incomplete or out of range.
  static KrigingModel restore(const ConstPoints3Ref& positions_m, const ConstPoints3Ref& values_m,
                              const MethodState& state);
  /// Writes the options, hyperparameters and sd factors into `state` (keys "trend_degree",
  /// "x.length_m", ...): what restore() needs besides the data.
  void save(MethodState& state) const;

  ~KrigingModel();
  KrigingModel(KrigingModel&&) noexcept;
  KrigingModel& operator=(KrigingModel&&) noexcept;

  /// Posterior mean and sd of the latent field at query_m (3 x N, [m]); the sd includes the
  /// trend coefficients' uncertainty but not the nugget, and is scaled by latent_sd_scale.
  [[nodiscard]] FieldPrediction predict(const ConstPoints3Ref& query_m) const;
  [[nodiscard]] const std::array<KrigingAxisFit, 3>& axes() const;
  /// Nugget sd per axis [m]: the noise of one measured value, to add for a new measurement.
  [[nodiscard]] Eigen::Vector3d nugget_sd_m() const;
  /// True when predictions use all fiducials (J <= exact_limit).
  [[nodiscard]] bool exact() const;
  /// E.g. "kriging (Matern 5/2, trend 2) of 1167 fiducials, exact; x: l = 0.12 0.2 0.3 m ...",
  /// its signal and nugget sd in `values`' unit.
  [[nodiscard]] std::string describe(CorrectionValues values = CorrectionValues::kLengthM) const;

 private:
  struct Impl;
  explicit KrigingModel(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_{};
};

}  // namespace vrreg
