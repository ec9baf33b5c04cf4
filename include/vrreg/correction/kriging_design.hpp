// SPDX-License-Identifier: Apache-2.0
#pragma once
// Kriging's posterior uncertainty depends on where the fiducials are, not on what they measure:
// the posterior covariance of the latent field for a design of fiducial locations, with given
// hyperparameters, for choosing where to measure next (planning/plan_next.hpp).
#include <Eigen/Core>
#include <array>
#include <memory>
#include <optional>

#include "vrreg/core/types.hpp"
#include "vrreg/correction/kriging.hpp"

namespace vrreg {
namespace detail {
class BaseCylinder;
}

/// One axis of a kriging model without its data: hyperparameters, kernel and trend degree.
struct KrigingDesignModel {
  KrigingHyperparameters hyperparameters{};
  KrigingKernel kernel = KrigingKernel::matern52;
  int trend_degree = 0;  ///< 0, 1 or 2
};

/// Universal-kriging posterior covariance of the latent field between the columns of a_m and b_m
/// (3 x Na, 3 x Nb, robot frame [m]) given one noisy observation (nugget) at each column of
/// design_m [m]: c(a, b) - k_a' K^-1 k_b + u_a' A^-1 u_b with K = C + nugget^2 I,
/// u = f - F' K^-1 k, A = F' K^-1 F (the trend coefficients' uncertainty included; no latent sd
/// scale). Returns Na x Nb [m^2]. Throws InputError when the design cannot determine the trend or
/// K is not positive definite.
Eigen::MatrixXd kriging_posterior_covariance(const ConstPoints3Ref& design_m,
                                             const ConstPoints3Ref& a_m, const ConstPoints3Ref& b_m,
                                             const KrigingDesignModel& model);

/// The diagonal of kriging_posterior_covariance(design_m, query_m, query_m, model) [m^2].
Eigen::VectorXd kriging_posterior_variance(const ConstPoints3Ref& design_m,
                                           const ConstPoints3Ref& query_m,
                                           const KrigingDesignModel& model);

/// The kriging corrector's model of the fiducial corrections (interpolation "kriging"), without
/// its data: the per-component design models and leave-one-out sd factors, and the inputs it
/// krigs on (cylindrical coordinates about the robot's base axis where the fiducials allow it,
/// components radial, tangential, vertical; else Cartesian, components along the robot axes).
/// The predicted sd of a corrected point is sqrt(sum over components of latent variance x
/// factor^2 + nugget^2), the same in any component frame.
struct KrigingCorrectorDesign {
  std::array<KrigingDesignModel, 3> axes{};
  std::array<double, 3> latent_sd_scale{1.0, 1.0, 1.0};
  std::shared_ptr<const detail::BaseCylinder> cylinder{};  ///< empty: Cartesian inputs
  /// The model's inputs for robot-frame positions robot_m (3 x N) [m].
  [[nodiscard]] Points3 inputs(const ConstPoints3Ref& robot_m) const;
};

/// The kriging corrector's trend degree for J fiducials: 0 below 40, 1 below 100, else 2 (a
/// quadratic trend's 10 terms per axis want ~10 fiducials each).
int kriging_trend_degree_for(Eigen::Index n_fiducials);

/// Fits the kriging corrector's hyperparameters (REML, as `register --interpolation kriging`
/// does) on fiducials commanded to fiducials_robot_m [m] with corrections corrections_sensor_m
/// (Eq. 6) [m] under the registration T_robot_sensor; noise_sd_m: the known noise of one
/// fiducial value (the nugget's floor). Throws InputError as KrigingModel::fit.
KrigingCorrectorDesign fit_kriging_corrector_design(const SimilarityTransform& T_robot_sensor,
                                                    const ConstPoints3Ref& fiducials_robot_m,
                                                    const ConstPoints3Ref& corrections_sensor_m,
                                                    std::optional<double> noise_sd_m);

}  // namespace vrreg
