// SPDX-License-Identifier: Apache-2.0
#include "vrreg/registration/marker_offset.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "vrreg/core/check.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg {
namespace {

constexpr int kMinPoses = 5;  // the linear start has 15 unknowns, 3 equations per pose

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

// Nearest proper rotation (Frobenius norm): the SVD with the last singular value's sign fixed.
Eigen::Matrix3d project_to_rotation(const Eigen::Matrix3d& m) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixU() * d * svd.matrixV().transpose();
}

struct Problem {
  const std::vector<Eigen::Isometry3d>& flange;
  const ConstPoints3Ref& y;
  // Marker orientations in the sensor frame (empty: positions only) and the residual weights
  // (1 / noise standard deviation) of the position and rotation blocks.
  std::vector<Eigen::Matrix3d> R_sensor_marker;
  double position_weight = 1.0;
  double rotation_weight = 1.0;
  [[nodiscard]] Eigen::Index n() const { return y.cols(); }
  [[nodiscard]] bool with_orientation() const { return !R_sensor_marker.empty(); }
  [[nodiscard]] int n_params() const { return with_orientation() ? 12 : 9; }
  [[nodiscard]] Eigen::Index n_residuals() const { return (with_orientation() ? 6 : 3) * n(); }
};

struct Estimate {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d tau = Eigen::Vector3d::Zero();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R_flange_marker = Eigen::Matrix3d::Identity();
};

// Rotation error of pose j: E = R R_sensor_marker R_flange_marker' R_flange' (I when exact).
Eigen::AngleAxisd rotation_error(const Problem& problem, const Estimate& e, Eigen::Index j) {
  const Eigen::Matrix3d f = problem.flange[static_cast<std::size_t>(j)].linear();
  return Eigen::AngleAxisd(e.R * problem.R_sensor_marker[static_cast<std::size_t>(j)] *
                           e.R_flange_marker.transpose() * f.transpose());
}

Eigen::Vector3d rotation_log(const Eigen::AngleAxisd& a) { return a.angle() * a.axis(); }

// Inverse of the left Jacobian of SO(3) at phi: d log(exp(d) E) = J_l^-1(log E) d. The right one
// is J_l^-1(-phi).
Eigen::Matrix3d inverse_left_jacobian(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  const Eigen::Matrix3d k = skew(phi);
  const double c = theta < 1e-6 ? 1.0 / 12.0
                                : 1.0 / (theta * theta) -
                                      (1.0 + std::cos(theta)) / (2.0 * theta * std::sin(theta));
  return Eigen::Matrix3d::Identity() - 0.5 * k + c * k * k;
}

// Residuals, stacked: position r_j = R y_j + tau - R_f p - t_f (3J), then, with orientations,
// rotation log(E_j) (3J), each block times its weight.
Eigen::VectorXd residuals(const Problem& problem, const Estimate& e) {
  Eigen::VectorXd r(problem.n_residuals());
  for (Eigen::Index j = 0; j < problem.n(); ++j) {
    const Eigen::Isometry3d& f = problem.flange[static_cast<std::size_t>(j)];
    r.segment<3>(3 * j) = e.R * problem.y.col(j) + e.tau - (f.linear() * e.p + f.translation());
  }
  if (problem.with_orientation()) {
    r.head(3 * problem.n()) *= problem.position_weight;
    for (Eigen::Index j = 0; j < problem.n(); ++j) {
      r.segment<3>(3 * (problem.n() + j)) =
          problem.rotation_weight * rotation_log(rotation_error(problem, e, j));
    }
  }
  return r;
}

// Jacobian of the residuals in (left rotation increment of R, tau, p[, right rotation increment
// of R_flange_marker]): n_residuals x n_params.
Eigen::MatrixXd jacobian(const Problem& problem, const Estimate& e) {
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(problem.n_residuals(), problem.n_params());
  for (Eigen::Index j = 0; j < problem.n(); ++j) {
    jac.block<3, 3>(3 * j, 0) = -skew(e.R * problem.y.col(j));
    jac.block<3, 3>(3 * j, 3) = Eigen::Matrix3d::Identity();
    jac.block<3, 3>(3 * j, 6) = -problem.flange[static_cast<std::size_t>(j)].linear();
  }
  if (problem.with_orientation()) {
    jac.topRows(3 * problem.n()) *= problem.position_weight;
    for (Eigen::Index j = 0; j < problem.n(); ++j) {
      const Eigen::Vector3d phi = rotation_log(rotation_error(problem, e, j));
      const Eigen::Index row = 3 * (problem.n() + j);
      // E exp(-c) with c = R_f R_flange_marker d for R_flange_marker <- R_flange_marker exp(d).
      jac.block<3, 3>(row, 0) = problem.rotation_weight * inverse_left_jacobian(phi);
      jac.block<3, 3>(row, 9) = -problem.rotation_weight * inverse_left_jacobian(-phi) *
                                problem.flange[static_cast<std::size_t>(j)].linear() *
                                e.R_flange_marker;
    }
  }
  return jac;
}

// Given R, the least-squares tau and p: [I, -R_f] [tau; p] = t_f - R y (linear).
void solve_translation_and_offset(const Problem& problem, Estimate& e) {
  Eigen::MatrixXd a(3 * problem.n(), 6);
  Eigen::VectorXd b(3 * problem.n());
  for (Eigen::Index j = 0; j < problem.n(); ++j) {
    const Eigen::Isometry3d& f = problem.flange[static_cast<std::size_t>(j)];
    a.block<3, 3>(3 * j, 0) = Eigen::Matrix3d::Identity();
    a.block<3, 3>(3 * j, 3) = -f.linear();
    b.segment<3>(3 * j) = f.translation() - e.R * problem.y.col(j);
  }
  const Eigen::Matrix<double, 6, 1> x = a.colPivHouseholderQr().solve(b);
  e.tau = x.head<3>();
  e.p = x.tail<3>();
}

// Closed-form start: R (9 entries, unconstrained), tau, p from one linear least-squares problem
// (sensor points centred for conditioning), R projected onto SO(3), then tau and p again for it.
// Returns false when the linear problem is rank deficient (e.g. coplanar sensor points).
bool linear_start(const Problem& problem, Estimate& e) {
  const Eigen::Vector3d y_mean = problem.y.rowwise().mean();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3 * problem.n(), 15);
  Eigen::VectorXd b(3 * problem.n());
  for (Eigen::Index j = 0; j < problem.n(); ++j) {
    const Eigen::Vector3d d = problem.y.col(j) - y_mean;
    const Eigen::Isometry3d& f = problem.flange[static_cast<std::size_t>(j)];
    for (int k = 0; k < 3; ++k) a.block<3, 3>(3 * j, 3 * k) = d(k) * Eigen::Matrix3d::Identity();
    a.block<3, 3>(3 * j, 9) = Eigen::Matrix3d::Identity();  // tau' = R y_mean + tau
    a.block<3, 3>(3 * j, 12) = -f.linear();
    b.segment<3>(3 * j) = f.translation();
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < 15) return false;
  const Eigen::VectorXd x = qr.solve(b);
  e.R = project_to_rotation(Eigen::Map<const Eigen::Matrix3d>(x.data()));
  solve_translation_and_offset(problem, e);
  return true;
}

// Start when the linear problem is rank deficient: alternate point registration of the sensor
// points onto the marker positions implied by p, and the linear tau, p for that R.
void alternating_start(const Problem& problem, Estimate& e) {
  Points3 robot(3, problem.n());
  for (int round = 0; round < 50; ++round) {
    for (Eigen::Index j = 0; j < problem.n(); ++j)
      robot.col(j) = problem.flange[static_cast<std::size_t>(j)] * e.p;
    e.R = register_rigid(problem.y, robot).T_robot_sensor.rotation;
    solve_translation_and_offset(problem, e);
  }
}

// Start of R_flange_marker given R: the chordal mean of R_f' R R_sensor_marker over the poses.
void orientation_start(const Problem& problem, Estimate& e) {
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  for (Eigen::Index j = 0; j < problem.n(); ++j) {
    sum += problem.flange[static_cast<std::size_t>(j)].linear().transpose() * e.R *
           problem.R_sensor_marker[static_cast<std::size_t>(j)];
  }
  e.R_flange_marker = project_to_rotation(sum);
}

Eigen::Matrix3d exp_rotation(const Eigen::Vector3d& v) {
  return Eigen::AngleAxisd(v.norm(), v.norm() > 0.0 ? v.normalized() : Eigen::Vector3d::UnitX())
      .toRotationMatrix();
}

// Levenberg-Marquardt (Marquardt's diagonal scaling). Returns true when it converged.
bool refine(const Problem& problem, const MarkerOffsetOptions& options, Estimate& e,
            int& iterations) {
  Eigen::VectorXd r = residuals(problem, e);
  double cost = r.squaredNorm();
  double lambda = 1e-6;
  for (iterations = 0; iterations < options.max_iterations; ++iterations) {
    const Eigen::MatrixXd jac = jacobian(problem, e);
    const Eigen::MatrixXd h = jac.transpose() * jac;
    const Eigen::VectorXd g = jac.transpose() * r;
    bool accepted = false;
    while (!accepted) {
      Eigen::MatrixXd damped = h;
      damped.diagonal() += lambda * h.diagonal();
      const Eigen::VectorXd step = -damped.ldlt().solve(g);
      Estimate trial = e;
      trial.R = exp_rotation(step.head<3>()) * e.R;
      trial.tau += step.segment<3>(3);
      trial.p += step.segment<3>(6);
      if (problem.with_orientation()) {
        trial.R_flange_marker = e.R_flange_marker * exp_rotation(step.segment<3>(9));
      }
      const Eigen::VectorXd r_trial = residuals(problem, trial);
      const double cost_trial = r_trial.squaredNorm();
      if (cost_trial <= cost) {
        e = trial;
        r = r_trial;
        const bool small = step.norm() <= options.step_tolerance_m;
        const bool flat = cost - cost_trial <= 1e-15 * cost;
        cost = cost_trial;
        lambda = std::max(lambda / 10.0, 1e-12);
        accepted = true;
        if (small || flat) return true;
      } else {
        lambda *= 10.0;
        // No step lowers the cost any more: at the minimum within rounding.
        if (lambda > 1e12) return step.norm() <= 1e-9 * (1.0 + e.tau.norm() + e.p.norm());
      }
    }
  }
  return false;
}

// Variance components (Helmert/Foerstner): each block's noise variance from its weighted sum of
// squares over its redundancy, n_block - trace of its part of the hat matrix. Returns
// {sigma_position_m, sigma_rotation_rad}.
std::pair<double, double> variance_components(const Problem& problem, const Estimate& e) {
  const Eigen::MatrixXd jac = jacobian(problem, e);
  const Eigen::VectorXd r = residuals(problem, e);
  const Eigen::MatrixXd n_inv = (jac.transpose() * jac).inverse();
  const Eigen::Index half = 3 * problem.n();
  double redundancy_position = 0.0;
  double redundancy_rotation = 0.0;
  for (Eigen::Index i = 0; i < 2 * half; ++i) {
    const double leverage = jac.row(i).dot(n_inv * jac.row(i).transpose());
    (i < half ? redundancy_position : redundancy_rotation) += 1.0 - leverage;
  }
  const double ssr_position = r.head(half).squaredNorm() /
                              (problem.position_weight * problem.position_weight);
  const double ssr_rotation = r.tail(half).squaredNorm() /
                              (problem.rotation_weight * problem.rotation_weight);
  return {std::sqrt(ssr_position / std::max(redundancy_position, 1e-12)),
          std::sqrt(ssr_rotation / std::max(redundancy_rotation, 1e-12))};
}

Eigen::Vector3d sqrt_diagonal(const Eigen::Matrix3d& block) {
  return block.diagonal().cwiseMax(0.0).cwiseSqrt();
}

}  // namespace

void MarkerOffsetOptions::validate() const {
  VRREG_THROW_UNLESS(
      std::isfinite(min_orientation_spread) && min_orientation_spread >= 0.0,
      "min_orientation_spread must be finite and >= 0, got " << min_orientation_spread);
  VRREG_THROW_UNLESS(std::isfinite(joint_offset_sigma_rad) && joint_offset_sigma_rad >= 0.0,
                     "joint_offset_sigma_rad must be finite and >= 0, got "
                         << joint_offset_sigma_rad);
  VRREG_THROW_UNLESS(std::isfinite(orientation_sigma_rad) && orientation_sigma_rad >= 0.0,
                     "orientation_sigma_rad must be finite and >= 0, got "
                         << orientation_sigma_rad);
  VRREG_THROW_UNLESS(max_iterations >= 1, "max_iterations must be >= 1, got " << max_iterations);
  VRREG_THROW_UNLESS(std::isfinite(step_tolerance_m) && step_tolerance_m >= 0.0,
                     "step_tolerance_m must be finite and >= 0, got " << step_tolerance_m);
}

const char* to_string(MarkerOffsetStatus status) {
  switch (status) {
    case MarkerOffsetStatus::kOk:
      return "ok";
    case MarkerOffsetStatus::kUnobservable:
      return "unobservable";
    case MarkerOffsetStatus::kNotConverged:
      return "not-converged";
  }
  return "unknown";
}

double orientation_spread(const std::vector<Eigen::Isometry3d>& T_robot_flange) {
  if (T_robot_flange.empty()) return 0.0;
  Eigen::Matrix3d mean = Eigen::Matrix3d::Zero();
  for (const Eigen::Isometry3d& f : T_robot_flange) mean += f.linear();
  mean /= static_cast<double>(T_robot_flange.size());
  // (1/J) sum_j R_j' R_j - M'M = I - M'M: the Schur complement of p against tau, per pose.
  const Eigen::Matrix3d s = Eigen::Matrix3d::Identity() - mean.transpose() * mean;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (s + s.transpose()));
  return std::sqrt(std::max(0.0, eig.eigenvalues()(0)));
}

MarkerOffsetResult estimate_marker_offset(const std::vector<Eigen::Isometry3d>& T_robot_flange,
                                          const ConstPoints3Ref& markers_sensor_m,
                                          const MarkerOffsetOptions& options) {
  return estimate_marker_offset(T_robot_flange, markers_sensor_m, {}, options);
}

MarkerOffsetResult estimate_marker_offset(const std::vector<Eigen::Isometry3d>& T_robot_flange,
                                          const ConstPoints3Ref& markers_sensor_m,
                                          const std::vector<Eigen::Quaterniond>& q_sensor_marker,
                                          const MarkerOffsetOptions& options) {
  options.validate();
  const auto n = static_cast<Eigen::Index>(T_robot_flange.size());
  VRREG_THROW_UNLESS(markers_sensor_m.cols() == n, "marker offset: " << n << " flange poses but "
                                                                     << markers_sensor_m.cols()
                                                                     << " sensor points");
  VRREG_THROW_UNLESS(n >= kMinPoses, "marker offset: " << n << " poses; at least " << kMinPoses
                                                       << " are needed (3 equations each, 9 "
                                                          "unknowns, 15 for the linear start)");
  VRREG_THROW_UNLESS(markers_sensor_m.allFinite(), "marker offset: non-finite sensor points");
  for (const Eigen::Isometry3d& f : T_robot_flange) {
    VRREG_THROW_UNLESS(f.matrix().allFinite(), "marker offset: non-finite flange pose");
  }
  VRREG_THROW_UNLESS(q_sensor_marker.empty() || static_cast<Eigen::Index>(q_sensor_marker.size()) == n,
                     "marker offset: " << n << " flange poses but " << q_sensor_marker.size()
                                       << " marker orientations");
  Problem problem{T_robot_flange, markers_sensor_m, {}, 1.0, 1.0};
  for (const Eigen::Quaterniond& q : q_sensor_marker) {
    VRREG_THROW_UNLESS(q.coeffs().allFinite() && q.norm() > 0.5,
                       "marker offset: marker orientation quaternion not finite or not unit");
    problem.R_sensor_marker.push_back(q.normalized().toRotationMatrix());
  }

  MarkerOffsetResult out;
  out.orientation_spread = orientation_spread(T_robot_flange);
  if (out.orientation_spread < options.min_orientation_spread) {
    std::ostringstream message;
    message << "the marker offset is not observable: the flange orientations vary too little "
               "(spread "
            << out.orientation_spread << " rad about the least-tilted axis, below "
            << options.min_orientation_spread
            << "); visit positions with the flange tilted about two axes (plan with "
               "`offset_tilt`), or give the offset";
    out.status = MarkerOffsetStatus::kUnobservable;
    out.message = message.str();
    return out;
  }

  Estimate e;
  if (!linear_start(problem, e)) alternating_start(problem, e);
  bool converged = false;
  if (!problem.with_orientation()) {
    converged = refine(problem, options, e, out.iterations);
  } else {
    // Positions alone first (their solution starts R_flange_marker), then both blocks, the
    // weights re-estimated from the residuals until they settle.
    Problem positions{T_robot_flange, markers_sensor_m, {}, 1.0, 1.0};
    converged = refine(positions, options, e, out.iterations);
    orientation_start(problem, e);
    double sigma_m = 1e-4;
    double sigma_rad =
        options.orientation_sigma_rad > 0.0 ? options.orientation_sigma_rad : 1e-3;
    for (int round = 0; round < 20; ++round) {
      problem.position_weight = 1.0 / sigma_m;
      problem.rotation_weight = 1.0 / sigma_rad;
      int iterations = 0;
      converged = refine(problem, options, e, iterations);
      out.iterations += iterations;
      const auto [new_sigma_m, new_sigma_rad] = variance_components(problem, e);
      // Noise-free data leave nothing to estimate: keep the weights.
      if (!(new_sigma_m > 1e-13) || !(new_sigma_rad > 1e-13)) break;
      const bool settled = std::abs(new_sigma_m / sigma_m - 1.0) < 1e-6 &&
                           (options.orientation_sigma_rad > 0.0 ||
                            std::abs(new_sigma_rad / sigma_rad - 1.0) < 1e-6);
      sigma_m = new_sigma_m;
      if (options.orientation_sigma_rad <= 0.0) sigma_rad = new_sigma_rad;
      if (settled) break;
    }
    problem.position_weight = 1.0 / sigma_m;
    problem.rotation_weight = 1.0 / sigma_rad;
  }
  if (!converged) {
    out.status = MarkerOffsetStatus::kNotConverged;
    out.message = "the Levenberg-Marquardt refinement did not converge in " +
                  std::to_string(options.max_iterations) + " iterations";
  }

  out.T_robot_sensor = RigidTransform(e.R, e.tau);
  out.p_flange_marker_m = e.p;
  const Eigen::VectorXd r = residuals(problem, e);
  const Eigen::VectorXd r_position = r.head(3 * n) / problem.position_weight;
  out.residuals_m.resize(n);
  for (Eigen::Index j = 0; j < n; ++j) out.residuals_m(j) = r_position.segment<3>(3 * j).norm();
  out.fre_m = std::sqrt(r_position.squaredNorm() / static_cast<double>(n));
  const double dof = static_cast<double>(3 * n - 9);
  out.sigma_m = std::sqrt(r_position.squaredNorm() / dof);

  const Eigen::MatrixXd jac = jacobian(problem, e);
  const Eigen::MatrixXd h = jac.transpose() * jac;
  if (problem.with_orientation()) {
    // The weights are 1 / sigma already: the covariance is the inverse normal matrix.
    const Eigen::MatrixXd covariance = h.inverse();
    out.covariance = covariance.topLeftCorner<9, 9>();
    out.has_marker_orientation = true;
    out.q_flange_marker = Eigen::Quaterniond(e.R_flange_marker);
    out.marker_rotation_std_rad = sqrt_diagonal(covariance.block<3, 3>(9, 9));
    out.sigma_m = 1.0 / problem.position_weight;
    out.sigma_rad = 1.0 / problem.rotation_weight;
    out.rotation_residuals_rad.resize(n);
    for (Eigen::Index j = 0; j < n; ++j) {
      out.rotation_residuals_rad(j) = r.segment<3>(3 * (n + j)).norm() / problem.rotation_weight;
    }
  } else {
    out.covariance = out.sigma_m * out.sigma_m * h.inverse();
  }
  out.rotation_std_rad = sqrt_diagonal(out.covariance.block<3, 3>(0, 0));
  out.translation_std_m = sqrt_diagonal(out.covariance.block<3, 3>(3, 3));
  out.p_std_m = sqrt_diagonal(out.covariance.block<3, 3>(6, 6));
  Eigen::MatrixXd scaled = jac;
  for (Eigen::Index c = 0; c < scaled.cols(); ++c) {
    const double norm = scaled.col(c).norm();
    if (norm > 0.0) scaled.col(c) /= norm;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled);
  const Eigen::VectorXd s = svd.singularValues();
  out.condition_number =
      s(s.size() - 1) > 0.0 ? s(0) / s(s.size() - 1) : std::numeric_limits<double>::infinity();
  return out;
}

}  // namespace vrreg
