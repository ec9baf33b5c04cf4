#include "vrreg/registration/marker_offset.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <cmath>
#include <sstream>

#include "vrreg/core/check.hpp"
#include "vrreg/registration/rigid.hpp"

namespace vrreg {
namespace {

using Matrix9d = Eigen::Matrix<double, 9, 9>;
using Vector9d = Eigen::Matrix<double, 9, 1>;
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
  [[nodiscard]] Eigen::Index n() const { return y.cols(); }
};

struct Estimate {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d tau = Eigen::Vector3d::Zero();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
};

// Residuals r_j = R y_j + tau - R_f p - t_f, stacked (3J).
Eigen::VectorXd residuals(const Problem& problem, const Estimate& e) {
  Eigen::VectorXd r(3 * problem.n());
  for (Eigen::Index j = 0; j < problem.n(); ++j) {
    const Eigen::Isometry3d& f = problem.flange[static_cast<std::size_t>(j)];
    r.segment<3>(3 * j) = e.R * problem.y.col(j) + e.tau - (f.linear() * e.p + f.translation());
  }
  return r;
}

// Jacobian of the residuals in (left rotation increment, tau, p): 3J x 9.
Eigen::MatrixXd jacobian(const Problem& problem, const Estimate& e) {
  Eigen::MatrixXd jac(3 * problem.n(), 9);
  for (Eigen::Index j = 0; j < problem.n(); ++j) {
    jac.block<3, 3>(3 * j, 0) = -skew(e.R * problem.y.col(j));
    jac.block<3, 3>(3 * j, 3) = Eigen::Matrix3d::Identity();
    jac.block<3, 3>(3 * j, 6) = -problem.flange[static_cast<std::size_t>(j)].linear();
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

// Levenberg-Marquardt (Marquardt's diagonal scaling). Returns true when it converged.
bool refine(const Problem& problem, const MarkerOffsetOptions& options, Estimate& e,
            int& iterations) {
  Eigen::VectorXd r = residuals(problem, e);
  double cost = r.squaredNorm();
  double lambda = 1e-6;
  for (iterations = 0; iterations < options.max_iterations; ++iterations) {
    const Eigen::MatrixXd jac = jacobian(problem, e);
    const Matrix9d h = jac.transpose() * jac;
    const Vector9d g = jac.transpose() * r;
    bool accepted = false;
    while (!accepted) {
      Matrix9d damped = h;
      damped.diagonal() += lambda * h.diagonal();
      const Vector9d step = -damped.ldlt().solve(g);
      Estimate trial = e;
      trial.R = Eigen::AngleAxisd(step.head<3>().norm(), step.head<3>().norm() > 0.0
                                                             ? step.head<3>().normalized()
                                                             : Eigen::Vector3d::UnitX())
                    .toRotationMatrix() *
                e.R;
      trial.tau += step.segment<3>(3);
      trial.p += step.tail<3>();
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

  MarkerOffsetResult out;
  out.orientation_spread = orientation_spread(T_robot_flange);
  if (out.orientation_spread < options.min_orientation_spread) {
    std::ostringstream message;
    message << "the marker offset is not observable: the flange orientations vary too little "
               "(spread "
            << out.orientation_spread << " rad about the least-tilted axis, below "
            << options.min_orientation_spread
            << "); visit positions with the flange tilted about two axes (vrreg plan "
               "--offset-tilt-deg), or give the offset";
    out.status = MarkerOffsetStatus::kUnobservable;
    out.message = message.str();
    return out;
  }

  const Problem problem{T_robot_flange, markers_sensor_m};
  Estimate e;
  if (!linear_start(problem, e)) alternating_start(problem, e);
  const bool converged = refine(problem, options, e, out.iterations);
  if (!converged) {
    out.status = MarkerOffsetStatus::kNotConverged;
    out.message = "the Levenberg-Marquardt refinement did not converge in " +
                  std::to_string(options.max_iterations) + " iterations";
  }

  out.T_robot_sensor = RigidTransform(e.R, e.tau);
  out.p_flange_marker_m = e.p;
  const Eigen::VectorXd r = residuals(problem, e);
  out.residuals_m.resize(n);
  for (Eigen::Index j = 0; j < n; ++j) out.residuals_m(j) = r.segment<3>(3 * j).norm();
  out.fre_m = std::sqrt(r.squaredNorm() / static_cast<double>(n));
  const double dof = static_cast<double>(3 * n - 9);
  out.sigma_m = std::sqrt(r.squaredNorm() / dof);

  const Eigen::MatrixXd jac = jacobian(problem, e);
  const Matrix9d h = jac.transpose() * jac;
  out.covariance = out.sigma_m * out.sigma_m * h.inverse();
  out.rotation_std_rad = sqrt_diagonal(out.covariance.block<3, 3>(0, 0));
  out.translation_std_m = sqrt_diagonal(out.covariance.block<3, 3>(3, 3));
  out.p_std_m = sqrt_diagonal(out.covariance.block<3, 3>(6, 6));
  Eigen::MatrixXd scaled = jac;
  for (int c = 0; c < 9; ++c) {
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
