#include <Eigen/QR>
#include <cmath>
#include <limits>
#include <utility>

#include "joint_error_solve.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg::kinematics {

void JointErrorModelOptions::validate() const {
  VRREG_THROW_UNLESS(max_joint_degree >= 0 && max_joint_degree <= 60,
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
  VRREG_THROW_UNLESS(cv_folds >= 2, "joint error model: cv_folds must be >= 2, got " << cv_folds);
}

JointErrorStep solve_rank_revealing(const Eigen::MatrixXd& a, const Eigen::VectorXd& r,
                                    double relative_rank_tolerance) {
  Eigen::VectorXd norms = a.colwise().norm().transpose();
  for (Eigen::Index c = 0; c < norms.size(); ++c) {
    if (!(norms(c) > 0.0)) norms(c) = 1.0;  // an all-zero column: its pivot is zero, rank drops
  }
  // Unit-norm columns make the threshold independent of units (rad vs m, degree of P_k).
  const Eigen::MatrixXd scaled = a * norms.cwiseInverse().asDiagonal();
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
  cod.setThreshold(relative_rank_tolerance);
  cod.compute(scaled);
  JointErrorStep step;
  step.dx = cod.solve(r).cwiseQuotient(norms);
  step.rank = static_cast<int>(cod.rank());
  return step;
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
  VRREG_THROW_UNLESS(options.joint_degrees.empty() ||
                         static_cast<int>(options.joint_degrees.size()) == n,
                     "joint error model: " << options.joint_degrees.size() << " joint degrees for "
                                           << n << " joints");
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
  const Eigen::Map<const Eigen::VectorXd> e(error_robot_m.data(), n_rows);  // column-major 3 x J
  s.x = Eigen::VectorXd::Zero(s.layout.n_columns());
  s.linear = options.gauss_newton_iterations == 0;
  int rank = 0;
  for (int it = 0; it <= options.gauss_newton_iterations; ++it) {
    const SerialChain chain_x = perturbed_chain(s, s.x);
    Eigen::VectorXd r = e;
    if (it > 0) {
      for (std::size_t j = 0; j < q_rad.size(); ++j) {
        r.segment<3>(3 * static_cast<Eigen::Index>(j)) -= model_error_m(s, chain_x, s.x, q_rad[j]);
      }
    }
    const JointErrorStep step =
        solve_rank_revealing(design_matrix(s, s.x, q_rad), r, options.relative_rank_tolerance);
    rank = step.rank;
    VRREG_THROW_UNLESS(rank < n_rows, "joint error model: " << q_rad.size() << " fiducials ("
                                                            << n_rows << " equations) for "
                                                            << rank
                                                            << " identifiable parameters: "
                                                               "need more fiducials or lower degrees");
    s.x += step.dx;
    // Converged when the step no longer moves the marker by more than a picometre-scale amount.
    if (it > 0 && step.dx.norm() <= 1e-14 * (1.0 + s.x.norm())) break;
  }
  return rank;
}

}  // namespace vrreg::kinematics
