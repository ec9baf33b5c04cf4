// SPDX-License-Identifier: Apache-2.0
// Fitting the joint-space error model: input checks, the shared state, the first-order solve
// and the optional Gauss-Newton refinement (joint_error_model.hpp).
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "joint_error_solve.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg::kinematics {

void JointErrorModelOptions::validate() const {
  VRREG_THROW_UNLESS(
      max_joint_degree >= 0 && max_joint_degree <= 60,
      "joint error model: max_joint_degree must be in 0..60, got " << max_joint_degree);
  for (const int d : joint_degrees) {
    VRREG_THROW_UNLESS(d >= 0 && d <= 60,
                       "joint error model: a joint degree must be in 0..60, got " << d);
  }
  VRREG_THROW_UNLESS(trend_degree >= -1 && trend_degree <= 2,
                     "joint error model: trend_degree must be -1, 0, 1 or 2, got " << trend_degree);
  VRREG_THROW_UNLESS(gauss_newton_iterations >= 0 && gauss_newton_iterations <= 100,
                     "joint error model: Gauss-Newton iterations must be in 0..100, got "
                         << gauss_newton_iterations);
  VRREG_THROW_UNLESS(std::isfinite(relative_rank_tolerance) && relative_rank_tolerance > 0.0 &&
                         relative_rank_tolerance < 1.0,
                     "joint error model: relative_rank_tolerance must be in (0, 1), got "
                         << relative_rank_tolerance);
  VRREG_THROW_UNLESS(max_periodic_terms >= 0 && max_periodic_terms <= 16,
                     "joint error model: max_periodic_terms must be in 0..16, got "
                         << max_periodic_terms);
  for (const JointPeriodicTerm& t : periodic_terms) {
    VRREG_THROW_UNLESS(std::isfinite(t.omega_per_rad) && t.omega_per_rad > 0.0,
                       "joint error model: a periodic term's frequency must be finite and > 0, got "
                           << t.omega_per_rad << " per rad");
  }
  VRREG_THROW_UNLESS(cv_folds >= 2, "joint error model: cv_folds must be >= 2, got " << cv_folds);
}

std::vector<Eigen::Index> independent_columns(const Eigen::MatrixXd& a,
                                              double relative_rank_tolerance) {
  // Unit-norm columns make the threshold independent of units (rad vs m, degree of P_k).
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a * inverse_column_norms(a).asDiagonal());
  qr.setThreshold(relative_rank_tolerance);
  std::vector<Eigen::Index> cols;
  for (Eigen::Index k = 0; k < qr.rank(); ++k) cols.push_back(qr.colsPermutation().indices()(k));
  std::sort(cols.begin(), cols.end());
  return cols;
}

Eigen::VectorXd solve_columns(const Eigen::MatrixXd& a, const std::vector<Eigen::Index>& cols,
                              const Eigen::VectorXd& r) {
  const Eigen::MatrixXd sub = a(Eigen::all, cols);
  const Eigen::VectorXd inverse_norms = inverse_column_norms(sub);
  const Eigen::VectorXd y =
      Eigen::HouseholderQR<Eigen::MatrixXd>(sub * inverse_norms.asDiagonal()).solve(r);
  Eigen::VectorXd dx = Eigen::VectorXd::Zero(a.cols());
  for (std::size_t k = 0; k < cols.size(); ++k) {
    dx(cols[k]) = y(static_cast<Eigen::Index>(k)) * inverse_norms(static_cast<Eigen::Index>(k));
  }
  return dx;
}

JointErrorModel::State make_joint_error_state(
    const SerialChain& nominal, const std::vector<JointVector>& q_rad,
    const ConstPoints3Ref& error_robot_m, const JointErrorModelOptions& options,
    const std::optional<Eigen::Vector3d>& p_flange_marker_m) {
  options.validate();
  const int n = nominal.n_joints();
  VRREG_THROW_UNLESS(!q_rad.empty(), "joint error model: no fiducials");
  VRREG_THROW_UNLESS(static_cast<Eigen::Index>(q_rad.size()) == error_robot_m.cols(),
                     "joint error model: " << q_rad.size() << " joint vectors but "
                                           << error_robot_m.cols() << " errors");
  VRREG_THROW_UNLESS(
      options.joint_degrees.empty() || static_cast<int>(options.joint_degrees.size()) == n,
      "joint error model: " << options.joint_degrees.size() << " joint degrees for " << n
                            << " joints");
  for (const JointPeriodicTerm& t : options.periodic_terms) {
    VRREG_THROW_UNLESS(t.joint >= 0 && t.joint < n, "joint error model: a periodic term of joint "
                                                        << t.joint + 1 << " on a robot with " << n
                                                        << " joints");
  }
  VRREG_THROW_UNLESS(error_robot_m.allFinite(), "joint error model: non-finite observed error");
  VRREG_THROW_UNLESS(!p_flange_marker_m || p_flange_marker_m->allFinite(),
                     "joint error model: non-finite marker offset");
  JointErrorModel::State s(nominal);
  s.p_flange_marker_m = p_flange_marker_m.value_or(nominal.T_flange_tcp().translation());
  s.layout.dh = options.dh_deltas;
  s.layout.marker = options.marker_offset;
  s.layout.trend_degree = options.trend_degree;
  s.q_lo_rad = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  s.q_hi_rad = -s.q_lo_rad;
  Points3 p(3, static_cast<Eigen::Index>(q_rad.size()));
  for (std::size_t j = 0; j < q_rad.size(); ++j) {
    VRREG_THROW_UNLESS(q_rad[j].size() == n, "joint error model: fiducial "
                                                 << j << " has " << q_rad[j].size()
                                                 << " joints, the robot " << n);
    nominal.check_joints(q_rad[j], "joint error model");
    s.q_lo_rad = s.q_lo_rad.cwiseMin(q_rad[j]);
    s.q_hi_rad = s.q_hi_rad.cwiseMax(q_rad[j]);
    p.col(static_cast<Eigen::Index>(j)) =
        nominal.T_base_dh0() * (flange_in_dh0(nominal, q_rad[j]) * s.p_flange_marker_m);
  }
  s.trend_centre_m = p.rowwise().mean();
  const double extent = (p.colwise() - s.trend_centre_m).cwiseAbs().maxCoeff();
  s.trend_scale_m = extent > 0.0 ? extent : 1.0;
  return s;
}

Eigen::Vector3d predict_joint_error_m(const JointErrorModel::State& s, const SerialChain& chain_x,
                                      const JointRef& q_rad) {
  if (!s.linear) return model_error_m(s, chain_x, s.x, q_rad);
  Eigen::MatrixXd rows(3, s.layout.n_columns());
  design_rows(s, s.nominal, Eigen::VectorXd::Zero(s.x.size()), q_rad, rows);
  return rows * s.x;
}

int fit_joint_error_parameters(JointErrorModel::State& s, const std::vector<JointVector>& q_rad,
                               const ConstPoints3Ref& error_robot_m,
                               const JointErrorModelOptions& options) {
  const auto n_rows = static_cast<Eigen::Index>(3 * q_rad.size());
  const Points3 e_points = error_robot_m;  // a Ref may have an outer stride: stack a copy
  const Eigen::Map<const Eigen::VectorXd> e(e_points.data(), n_rows);
  s.x = Eigen::VectorXd::Zero(s.layout.n_columns());
  s.linear = true;
  // The identifiable parameters are chosen once, at the nominal linearisation (redundant ones
  // eliminated, Hollerbach & Wampler 1996 sec. 5): later iterates may make a dropped direction
  // weakly visible (a fitted marker offset moves the marker off the last joint's axis), and
  // fitting noise along it would throw Gauss-Newton off.
  const Eigen::MatrixXd a0 = design_matrix(s, s.x, q_rad);
  const std::vector<Eigen::Index> cols = independent_columns(a0, options.relative_rank_tolerance);
  VRREG_THROW_UNLESS(static_cast<Eigen::Index>(cols.size()) < n_rows,
                     "joint error model: " << q_rad.size() << " fiducials (" << n_rows
                                           << " equations) for " << cols.size()
                                           << " identifiable parameters: need more "
                                              "fiducials or lower degrees");
  s.x = solve_columns(a0, cols, e);
  // Gauss-Newton on the exact model while it lowers the residual, kept only if it ends below the
  // first-order fit: near-degenerate parameter combinations (parallel joints, a fixed tool
  // orientation coupling joints 2-4) may cancel at first order and not beyond.
  auto exact_residual = [&](const Eigen::VectorXd& x) {
    const SerialChain chain_x = perturbed_chain(s, x);
    Eigen::VectorXd r = e;
    for (std::size_t j = 0; j < q_rad.size(); ++j) {
      r.segment<3>(3 * static_cast<Eigen::Index>(j)) -= model_error_m(s, chain_x, x, q_rad[j]);
    }
    return r;
  };
  if (options.gauss_newton_iterations == 0) return static_cast<int>(cols.size());
  Eigen::VectorXd x = s.x;
  Eigen::VectorXd r = exact_residual(x);
  for (int it = 0; it < options.gauss_newton_iterations; ++it) {
    const Eigen::VectorXd dx = solve_columns(design_matrix(s, x, q_rad), cols, r);
    const Eigen::VectorXd r_next = exact_residual(x + dx);
    if (!(r_next.squaredNorm() < r.squaredNorm())) break;
    x += dx;
    r = r_next;
    // Converged when the step is at rounding level of the parameters.
    if (dx.norm() <= 1e-14 * (1.0 + x.norm())) break;
  }
  if (r.squaredNorm() <= (a0 * s.x - e).squaredNorm()) {
    s.x = x;
    s.linear = false;
  }
  return static_cast<int>(cols.size());
}

}  // namespace vrreg::kinematics
