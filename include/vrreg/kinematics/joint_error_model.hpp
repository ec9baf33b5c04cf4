// SPDX-License-Identifier: Apache-2.0
#pragma once
// A joint-space model of a robot's positioning error, fitted to fiducials by linear
// least squares through the robot's Jacobian, as in kinematic calibration (Mooring, Roth &
// Driels 1991; Hollerbach & Wampler 1996), extended by smooth per-joint angle-error functions
// (Legendre polynomials over each joint's observed range) and a quadratic Cartesian trend.
//
// Sign convention: the model predicts e(q) = y_observed - y_nominal in the ROBOT frame [m], where
// y_nominal = FK_nominal(q) p_flange_marker and y_observed is where the marker really was (e.g.
// R X + tau, the registered sensor reading). A corrected target is y_observed_t - e(q_t).
//
// e(q) = p_actual(q + dq(q)) - p_nominal(q) + trend(p_nominal(q)), with
//   dq_i(q) = sum_k c_ik P_k(u_i(q_i))   (k = 0: the joint offset; u_i maps the range to [-1, 1])
//             + sum_m (s_m sin(w_m q_i) + c_m cos(w_m q_i))   (periodic terms of joint i, if any)
//   p_actual: the nominal DH table plus deltas of a, d, alpha per row and a marker offset delta,
//   trend: 10 monomials of the nominal position per axis (absorbs a slightly wrong registration).
// Without Gauss-Newton iterations the model is its first-order (linear) expansion at zero.
//
// Joints that follow others (URDF mimic joints, SerialChain::couplings) are physical joints with
// errors of their own: every per-joint term (dq_i, the DH deltas, periodic terms, ranges) is per
// DH row, evaluated at the rows' values the commanded variables give. A coupled chain's model is
// the model of the same chain with every row its own joint (SerialChain::uncoupled), asked at
// row_values(q); where two rows' terms act alike (e.g. two parallel slides), the rank-revealing
// solve keeps one of them.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "vrreg/core/types.hpp"
#include "vrreg/kinematics/joint_vector.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// A cyclic angle error of one joint, s sin(omega q) + c cos(omega q) [rad], e.g. a gear's or a
/// harmonic drive's transmission error with period 2 pi / omega. The amplitudes s, c are fitted.
struct JointPeriodicTerm {
  int joint = 0;               ///< 0-based physical joint (DH row) index
  double omega_per_rad = 0.0;  ///< angular frequency in the joint angle [1/rad], > 0
};

/// What the model contains and how it is fitted.
struct JointErrorModelOptions {
  /// Legendre degree of each physical joint's (DH row's) angle-error function (0: a constant
  /// offset only). Empty: chosen per joint by K-fold cross-validation among 0..max_joint_degree.
  std::vector<int> joint_degrees{};
  int max_joint_degree = 40;  ///< largest degree the automatic choice tries
  /// Periodic terms of the joint-angle errors. Empty: found from the fiducials when the degrees
  /// are chosen automatically (a periodogram of what a smooth model leaves, at most
  /// max_periodic_terms, the set kept only if it lowers the cross-validated RMS).
  std::vector<JointPeriodicTerm> periodic_terms{};
  int max_periodic_terms = 6;  ///< 0: no periodic terms unless given
  bool dh_deltas = true;       ///< a, d, alpha deltas of every DH row
  bool marker_offset = true;   ///< a 3-vector delta of the marker's flange offset
  int trend_degree = 2;  ///< Cartesian trend per axis: -1 none, 0 constant, 1 linear, 2 quadratic
  /// Gauss-Newton iterations with the exact perturbed-chain kinematics after the first-order
  /// solve, each kept only if it lowers the residual (else the model stays first-order: linear
  /// in the parameters, predictions linear too). Off by default: on the simulated cells the
  /// trend and the joint functions absorb the second-order terms (docs/joint-space-model.md).
  int gauss_newton_iterations = 0;
  /// Rank threshold of the column-pivoted QR on unit-norm columns, relative to the largest
  /// pivot: parameters whose pivot falls below it are redundant with the kept ones and stay 0.
  double relative_rank_tolerance = 1e-9;
  int cv_folds = 5;           ///< folds of the degree choice and of joint_error_cv_rms_m
  std::uint64_t cv_seed = 1;  ///< decides which fiducial goes to which fold
  /// Throws InputError on a value out of range.
  void validate() const;
};

/// Everything a fitted joint-space error model is, besides its nominal chain: what
/// JointErrorModel::restore needs to predict exactly as the fitted model did.
struct JointErrorModelParameters {
  std::vector<int> joint_degrees{};  ///< Legendre degree per physical joint (DH row)
  std::vector<JointPeriodicTerm> periodic_terms{};
  bool dh_deltas = true;
  bool marker_offset = true;
  int trend_degree = 2;
  Eigen::VectorXd q_lo_rad{};  ///< each physical joint's (DH row's) fitted range [rad]
  Eigen::VectorXd q_hi_rad{};
  Eigen::Vector3d trend_centre_m = Eigen::Vector3d::Zero();
  double trend_scale_m = 1.0;
  Eigen::Vector3d p_flange_marker_m = Eigen::Vector3d::Zero();  ///< the marker on the flange [m]
  bool linear = true;  ///< first-order model (no accepted Gauss-Newton step)
  Eigen::VectorXd
      x{};  ///< the parameters, unscaled (layout: src/kinematics/joint_error_design.hpp)
  int rank = 0;
  double selection_cv_rms_m = 0.0;  ///< NaN when the degrees were given
};

/// A fitted joint-space error model. Immutable; fit with JointErrorModel::fit.
class JointErrorModel {
 public:
  /// Fits the model to fiducials at commanded joints `q_rad` [rad] whose observed errors are
  /// `error_robot_m` (3 x J, y_observed - y_nominal, robot frame, m). `p_flange_marker_m`: the
  /// marker in the flange frame [m]; empty: the chain's TCP. Throws InputError on joint-count
  /// mismatch, non-finite values, or fewer equations (3 J) than the identifiable rank + 1.
  static JointErrorModel fit(const SerialChain& nominal, const std::vector<JointVector>& q_rad,
                             const ConstPoints3Ref& error_robot_m,
                             const JointErrorModelOptions& options = {},
                             const std::optional<Eigen::Vector3d>& p_flange_marker_m = {});

  /// The model with these parameters on `nominal` (no fit): it predicts what the model they were
  /// saved from predicted. Residuals are not kept (residuals_m() is empty). Throws InputError
  /// when the parameters do not fit the chain (joint counts, parameter count, ranges).
  static JointErrorModel restore(const SerialChain& nominal,
                                 const JointErrorModelParameters& parameters);
  /// What restore() needs.
  [[nodiscard]] JointErrorModelParameters saved() const;

  /// Predicted y_observed - y_nominal at commanded joints `q_rad` [m, robot frame]. Outside a
  /// joint's fitted range its angle-error function keeps its value at the nearer end (a
  /// polynomial would run away); the DH, marker and trend terms hold everywhere.
  [[nodiscard]] Eigen::Vector3d predict_m(const JointRef& q_rad) const;
  /// The arm's orientation error the model predicts at commanded joints `q_rad`: the rotation
  /// vector of R_actual(q + dq(q)) R_nominal(q)^T, robot frame [rad] (the DH and joint-function
  /// terms; the marker and trend terms move positions only). First order and exact agree to the
  /// square of the error.
  [[nodiscard]] Eigen::Vector3d predict_rotation_rad(const JointRef& q_rad) const;
  /// The part of predict_rotation_rad that the fitted joint-angle errors dq(q) give on the
  /// nominal arm, R_nominal(q + dq(q)) R_nominal(q)^T [rad]: without the DH deltas, which a
  /// fixed tool orientation leaves in combinations positions cannot tell apart.
  [[nodiscard]] Eigen::Vector3d predict_joint_angle_rotation_rad(const JointRef& q_rad) const;
  /// The fitted joint-angle errors dq(q) at commanded joints `q_rad`, one per physical joint
  /// (DH row; the joint variables' own on an uncoupled chain) [rad; m for prismatic].
  [[nodiscard]] JointVector joint_angle_errors_rad(const JointRef& q_rad) const;
  /// predict_m for each joint vector, one column each.
  [[nodiscard]] Points3 predict_m(const std::vector<JointVector>& q_rad) const;

  /// Number of commanded joint variables the model is asked at.
  [[nodiscard]] int n_joints() const;
  /// Fitted range of each commanded joint variable (lower, upper) [rad; m for prismatic]: the
  /// rows' ranges of JointErrorModelParameters, as values of the variables they follow.
  [[nodiscard]] std::pair<Eigen::VectorXd, Eigen::VectorXd> joint_range_rad() const;

  /// Observed minus predicted error at each fiducial (3 x J, m), e.g. for kriging what remains.
  [[nodiscard]] const Points3& residuals_m() const { return residuals_m_; }
  /// sqrt(mean_j |residual_j|^2) [m].
  [[nodiscard]] double residual_rms_m() const;
  /// Numerical rank of the last least-squares solve.
  [[nodiscard]] int rank() const { return rank_; }
  /// Number of parameters (columns) of the model.
  [[nodiscard]] int n_parameters() const { return static_cast<int>(parameters().size()); }
  /// The Legendre degree of each joint's function (given or chosen).
  [[nodiscard]] const std::vector<int>& joint_degrees() const { return degrees_; }
  /// The periodic terms of the joint-angle errors (given or found).
  [[nodiscard]] const std::vector<JointPeriodicTerm>& periodic_terms() const;
  /// First-order K-fold CV RMS of the degree choice [m]; NaN when degrees were given.
  [[nodiscard]] double selection_cv_rms_m() const { return selection_cv_rms_m_; }
  /// The fitted parameters in the unscaled units (rad, m), layout documented in the source.
  [[nodiscard]] const Eigen::VectorXd& parameters() const;

  // Implementation state, public for the module's helpers (see src/kinematics/joint_error_*.hpp).
  struct State;
  explicit JointErrorModel(std::shared_ptr<const State> state, Points3 residuals_m, int rank,
                           std::vector<int> degrees, double selection_cv_rms_m);

 private:
  // The same model asked by the joint variables of `commanded` (whose rows it was fitted on).
  [[nodiscard]] JointErrorModel as_commanded_by(const SerialChain& commanded) const;
  // Every DH row's value at commanded joints `q_rad` (checked).
  [[nodiscard]] JointVector rows_at(const JointRef& q_rad) const;

  std::shared_ptr<const State> state_{};
  Points3 residuals_m_{};
  int rank_ = 0;
  std::vector<int> degrees_{};
  double selection_cv_rms_m_ = 0.0;
};

/// K-fold cross-validation RMS [m] of the joint-space model on the fiducials (deterministic folds
/// from options.cv_seed): each fold predicted by a model fitted on the others, with the joint
/// degrees of options (or, when empty, chosen once on all fiducials), sqrt(mean |error|^2).
double joint_error_cv_rms_m(const SerialChain& nominal, const std::vector<JointVector>& q_rad,
                            const ConstPoints3Ref& error_robot_m,
                            const JointErrorModelOptions& options = {},
                            const std::optional<Eigen::Vector3d>& p_flange_marker_m = {});

}  // namespace vrreg::kinematics
