// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internals of the joint-space error model (joint_error_model.hpp): the parameter layout, the
// basis functions and the design rows d e / d x of one fiducial.
//
// Parameter layout (columns of the design matrix, in this order):
//   per joint i: c_i0 .. c_iD_i   Legendre coefficients of dq_i [rad; prismatic: m]
//   per DH row i (dh_deltas): delta a_i [m], delta d_i [m] (prismatic: delta theta_i [rad]),
//                             delta alpha_i [rad]
//   marker (marker_offset): delta p_flange_marker x, y, z [m]
//   trend: for axis x, y, z the monomials of (p_nominal - centre) / scale, 1, 4 or 10 each [m]
//   per periodic term m: s_m, c_m, amplitudes of sin and cos (omega_m q_joint) in dq_joint [rad]
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "vrreg/kinematics/joint_error_model.hpp"
#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::kinematics {

/// Column layout of the model.
struct JointErrorLayout {
  std::vector<int> degrees;  ///< Legendre degree per joint
  bool dh = true;
  bool marker = true;
  int trend_degree = 2;  ///< -1 none, 0, 1, 2
  std::vector<JointPeriodicTerm> periodic;

  [[nodiscard]] int n_joints() const { return static_cast<int>(degrees.size()); }
  [[nodiscard]] int joint_column(int joint) const;  ///< first column of joint `joint`
  [[nodiscard]] int dh_column() const;              ///< first DH column (a_0, d_0, alpha_0, a_1..)
  [[nodiscard]] int marker_column() const;
  [[nodiscard]] int trend_column() const;
  [[nodiscard]] int n_trend_terms() const;  ///< monomials per axis
  [[nodiscard]] int periodic_column() const;  ///< first column of the periodic terms
  [[nodiscard]] int n_columns() const;
};

/// Everything a fitted model needs to evaluate itself.
struct JointErrorModel::State {
  explicit State(const SerialChain& chain) : nominal(chain.uncoupled()), commanded(chain) {}
  /// The physical joints, one variable per DH row: what every term below is a function of.
  SerialChain nominal;
  /// The chain as commanded; its joint variables give nominal's rows (row_values).
  SerialChain commanded;
  Eigen::Vector3d p_flange_marker_m = Eigen::Vector3d::Zero();
  JointErrorLayout layout;
  Eigen::VectorXd q_lo_rad;  ///< fitted range of each joint
  Eigen::VectorXd q_hi_rad;
  Eigen::Vector3d trend_centre_m = Eigen::Vector3d::Zero();
  double trend_scale_m = 1.0;
  bool linear = false;  ///< first-order model: e = A(q; x = 0) x
  Eigen::VectorXd x;    ///< parameters, unscaled
};

/// P_0..P_degree at u in [-1, 1] (three-term recurrence), into `out` (degree + 1 values).
void legendre_values(double u, int degree, double* out);
/// u_i in [-1, 1] for joint angle `q_rad` of joint `joint` (clamped to the fitted range).
double joint_unit(const JointErrorModel::State& s, int joint, double q_rad);
/// Monomials 1, x, y, z, x^2, xy, xz, y^2, yz, z^2 (first n_trend_terms) of the scaled position.
void trend_monomials(const JointErrorModel::State& s, const Eigen::Vector3d& p_nominal_m, int n,
                     double* out);
/// A periodic term's factors on its joint's column: sin and cos of omega q_joint.
std::pair<double, double> periodic_factors(const JointPeriodicTerm& term, double q_joint_rad);
/// dq(q) [rad] of parameters `x`.
JointVector joint_error_rad(const JointErrorModel::State& s, const Eigen::VectorXd& x,
                            const JointRef& q_rad);
/// The nominal chain with the DH deltas of `x` applied.
SerialChain perturbed_chain(const JointErrorModel::State& s, const Eigen::VectorXd& x);
/// The nonlinear model value e(q) for parameters `x` (`chain_x` = perturbed_chain(s, x)).
Eigen::Vector3d model_error_m(const JointErrorModel::State& s, const SerialChain& chain_x,
                              const Eigen::VectorXd& x, const JointRef& q_rad);
/// Design rows d e / d x at parameters `x` (3 x n_columns) into `rows`.
void design_rows(const JointErrorModel::State& s, const SerialChain& chain_x,
                 const Eigen::VectorXd& x, const JointRef& q_rad, Eigen::Ref<Eigen::MatrixXd> rows);
/// The stacked design matrix (3 J x n_columns) of all `q_rad` at `x`, 3 rows per fiducial.
Eigen::MatrixXd design_matrix(const JointErrorModel::State& s, const Eigen::VectorXd& x,
                              const std::vector<JointVector>& q_rad);

/// 1 / |column| of `a`, and 0 for a column that is zero up to rounding (|column| <= 1e-10 of the
/// largest), e.g. the last joint's rotation when the marker sits on its axis: scaled to unit
/// norm, such a column would be rounding noise the solve could fit.
Eigen::VectorXd inverse_column_norms(const Eigen::MatrixXd& a);

/// Fold of each of `n` items, 0..folds-1, from a seeded shuffle (same seed, same folds).
std::vector<int> cv_fold_of(int n, int folds, std::uint64_t seed);

}  // namespace vrreg::kinematics
