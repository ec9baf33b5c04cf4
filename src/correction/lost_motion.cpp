// SPDX-License-Identifier: Apache-2.0
#include "lost_motion.hpp"

#include <Eigen/QR>
#include <cmath>
#include <vector>

#include "vrreg/core/check.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"

namespace vrreg::detail {
namespace {

void check_sizes(const kinematics::SerialChain& chain, const Eigen::Ref<const Eigen::MatrixXd>& q,
                 const Eigen::Ref<const Eigen::MatrixXd>& sign) {
  VRREG_THROW_UNLESS(
      q.rows() == chain.n_joints() && sign.rows() == q.rows() && sign.cols() == q.cols(),
      "lost motion: joints " << q.rows() << " x " << q.cols() << " and signs " << sign.rows()
                             << " x " << sign.cols() << " for " << chain.n_joints() << " joints");
}

// Column j of point i: -J_pos,j(q_i) s_ij / 2 (3 rows per point).
Eigen::MatrixXd design(const kinematics::SerialChain& chain,
                       const Eigen::Ref<const Eigen::MatrixXd>& q,
                       const Eigen::Ref<const Eigen::MatrixXd>& sign) {
  Eigen::MatrixXd a(3 * q.cols(), q.rows());
  for (Eigen::Index i = 0; i < q.cols(); ++i) {
    const kinematics::Jacobian jac = kinematics::jacobian(chain, q.col(i));
    for (Eigen::Index j = 0; j < q.rows(); ++j) {
      a.block<3, 1>(3 * i, j) = -0.5 * sign(j, i) * jac.block<3, 1>(0, j);
    }
  }
  return a;
}

// Monomials of degree <= d in the centred, scaled position.
Eigen::VectorXd monomials(const Eigen::Vector3d& p, int degree) {
  std::vector<double> m{1.0};
  if (degree >= 1) m.insert(m.end(), {p.x(), p.y(), p.z()});
  if (degree >= 2) {
    m.insert(m.end(), {p.x() * p.x(), p.y() * p.y(), p.z() * p.z(), p.x() * p.y(), p.x() * p.z(),
                       p.y() * p.z()});
  }
  return Eigen::Map<Eigen::VectorXd>(m.data(), static_cast<Eigen::Index>(m.size()));
}

}  // namespace

Points3 lost_motion_deviation_m(const kinematics::SerialChain& chain,
                                const Eigen::Ref<const Eigen::MatrixXd>& joints_rad,
                                const Eigen::Ref<const Eigen::MatrixXd>& approach_sign,
                                const Eigen::Ref<const Eigen::VectorXd>& beta_rad) {
  check_sizes(chain, joints_rad, approach_sign);
  VRREG_THROW_UNLESS(
      beta_rad.size() == joints_rad.rows(),
      "lost motion: " << beta_rad.size() << " plays for " << joints_rad.rows() << " joints");
  const Eigen::VectorXd stacked = design(chain, joints_rad, approach_sign) * beta_rad;
  return Eigen::Map<const Points3>(stacked.data(), 3, joints_rad.cols());
}

LostMotionFit fit_lost_motion(const kinematics::SerialChain& chain,
                              const Eigen::Ref<const Eigen::MatrixXd>& joints_rad,
                              const Eigen::Ref<const Eigen::MatrixXd>& approach_sign,
                              const ConstPoints3Ref& positions_m,
                              const ConstPoints3Ref& deviation_m, int trend_degree) {
  check_sizes(chain, joints_rad, approach_sign);
  const Eigen::Index n = joints_rad.cols();
  const Eigen::Index n_joints = joints_rad.rows();
  VRREG_THROW_UNLESS(positions_m.cols() == n && deviation_m.cols() == n,
                     "lost motion: " << n << " joint columns, " << positions_m.cols()
                                     << " positions, " << deviation_m.cols() << " deviations");
  VRREG_THROW_UNLESS(trend_degree >= 0 && trend_degree <= 2,
                     "lost motion: trend degree must be 0, 1 or 2, got " << trend_degree);
  VRREG_THROW_UNLESS(positions_m.allFinite() && deviation_m.allFinite() && joints_rad.allFinite() &&
                         approach_sign.allFinite(),
                     "lost motion: non-finite input");
  // Joints that never arrive from a known side carry no information: left out of the fit.
  std::vector<Eigen::Index> active;
  for (Eigen::Index j = 0; j < n_joints; ++j) {
    if (approach_sign.row(j).cwiseAbs().maxCoeff() > 0.0) active.push_back(j);
  }
  const Eigen::Vector3d centre = positions_m.rowwise().mean();
  const double scale =
      std::max((positions_m.colwise() - centre).cwiseAbs().maxCoeff(), 1e-9);  // O(1) monomials
  const Eigen::Index n_terms = monomials(Eigen::Vector3d::Zero(), trend_degree).size();
  Eigen::Index n_active = 0;
  Eigen::Index n_params = 0;
  const Eigen::MatrixXd lm = design(chain, joints_rad, approach_sign);
  Eigen::MatrixXd trend = Eigen::MatrixXd::Zero(3 * n, 3 * n_terms);
  Eigen::VectorXd y(3 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::VectorXd m = monomials((positions_m.col(i) - centre) / scale, trend_degree);
    for (int axis = 0; axis < 3; ++axis) {
      trend.block(3 * i + axis, axis * n_terms, 1, n_terms) = m.transpose();
    }
    y.segment<3>(3 * i) = deviation_m.col(i);
  }
  // A joint whose column the trend (or the other joints) already spans is not identified, e.g.
  // joint 1 always arriving from one side (its column is then linear in the position) or a joint
  // whose axis passes through the marker: left out, beta 0 with variance 0.
  Eigen::MatrixXd a;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
  for (;;) {
    n_active = static_cast<Eigen::Index>(active.size());
    n_params = n_active + 3 * n_terms;
    VRREG_THROW_UNLESS(3 * n > n_params + 1,
                       "lost motion: " << n << " points cannot fit " << n_params << " parameters");
    a.resize(3 * n, n_params);
    for (Eigen::Index k = 0; k < n_active; ++k) {
      a.col(k) = lm.col(active[static_cast<std::size_t>(k)]);
    }
    a.rightCols(3 * n_terms) = trend;
    qr.compute(a);
    qr.setThreshold(1e-9);
    if (qr.rank() == n_params) break;
    // The last pivoted column among the joints' is the most dependent one.
    Eigen::Index drop = -1;
    for (Eigen::Index p = n_params - 1; p >= qr.rank() && drop < 0; --p) {
      const Eigen::Index column = qr.colsPermutation().indices()(p);
      if (column < n_active) drop = column;
    }
    VRREG_THROW_UNLESS(drop >= 0, "lost motion: the trend cannot be determined from the positions");
    active.erase(active.begin() + drop);
  }
  const Eigen::VectorXd x = qr.solve(y);
  const Eigen::VectorXd r = y - a * x;
  const double variance_m2 = r.squaredNorm() / static_cast<double>(3 * n - n_params);
  // (A'A)^-1 from R of the QR: P R^-1 R^-T P'.
  const Eigen::MatrixXd r_upper =
      qr.matrixR().topLeftCorner(n_params, n_params).triangularView<Eigen::Upper>();
  const Eigen::MatrixXd r_inv =
      r_upper.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(n_params, n_params));
  const Eigen::MatrixXd ata_inv =
      qr.colsPermutation() * (r_inv * r_inv.transpose()) * qr.colsPermutation().transpose();

  LostMotionFit fit;
  fit.beta_rad = Eigen::VectorXd::Zero(n_joints);
  fit.covariance_rad2 = Eigen::MatrixXd::Zero(n_joints, n_joints);
  for (Eigen::Index k = 0; k < n_active; ++k) {
    const Eigen::Index j = active[static_cast<std::size_t>(k)];
    fit.beta_rad(j) = x(k);
    for (Eigen::Index l = 0; l < n_active; ++l) {
      fit.covariance_rad2(j, active[static_cast<std::size_t>(l)]) = variance_m2 * ata_inv(k, l);
    }
  }
  fit.trend_coefficients =
      Eigen::Map<const Eigen::MatrixXd>(x.data() + n_active, n_terms, 3).transpose();
  fit.residual_sd_m = std::sqrt(variance_m2);
  return fit;
}

}  // namespace vrreg::detail
