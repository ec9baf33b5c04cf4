// SPDX-License-Identifier: Apache-2.0
#include "vrreg/metrics/monitor_check.hpp"

#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

#include "vrreg/core/check.hpp"
#include "vrreg/metrics/distributions.hpp"

namespace vrreg {
namespace {

// Weighted least squares of d_i = omega x p_i + t = [-[p_i]x, I] (omega, t), p about the
// weighted centroid (so omega and t decouple for an isotropic sd).
struct RigidFit {
  RigidChange change;
  double residual_chi2 = 0.0;
  bool ok = false;
};

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

RigidFit fit_rigid(const ConstPoints3Ref& p, const Points3& d, const Eigen::VectorXd& sd,
                   const std::vector<bool>& use) {
  RigidFit fit;
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  for (Eigen::Index i = 0; i < p.cols(); ++i) {
    if (!use[static_cast<std::size_t>(i)]) continue;
    Eigen::Matrix<double, 3, 6> a;
    a.leftCols<3>() = -cross_matrix(p.col(i));
    a.rightCols<3>() = Eigen::Matrix3d::Identity();
    const double w = 1.0 / (sd(i) * sd(i));
    normal += w * a.transpose() * a;
    rhs += w * a.transpose() * d.col(i);
  }
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(normal);
  // Collinear points leave a rotation about their line unobservable.
  const Eigen::JacobiSVD<Eigen::Matrix<double, 6, 6>> svd(normal);
  if (svd.singularValues()(5) <= 1e-12 * svd.singularValues()(0)) return fit;
  const Eigen::Matrix<double, 6, 1> x = ldlt.solve(rhs);
  fit.change.rotation_rad = x.head<3>();
  fit.change.translation_m = x.tail<3>();
  fit.change.covariance = ldlt.solve(Eigen::Matrix<double, 6, 6>::Identity());
  double moved = 0.0;
  int n = 0;
  for (Eigen::Index i = 0; i < p.cols(); ++i) {
    if (!use[static_cast<std::size_t>(i)]) continue;
    const Eigen::Vector3d motion = x.head<3>().cross(p.col(i)) + x.tail<3>();
    moved += motion.squaredNorm();
    fit.residual_chi2 += (d.col(i) - motion).squaredNorm() / (sd(i) * sd(i));
    ++n;
  }
  fit.change.displacement_rms_m = std::sqrt(moved / n);
  fit.ok = true;
  return fit;
}

double chi2_of(const Points3& d, const Eigen::VectorXd& sd, const std::vector<bool>& use) {
  double chi2 = 0.0;
  for (Eigen::Index i = 0; i < d.cols(); ++i) {
    if (use[static_cast<std::size_t>(i)]) chi2 += d.col(i).squaredNorm() / (sd(i) * sd(i));
  }
  return chi2;
}

}  // namespace

const char* to_string(MonitorVerdict verdict) {
  switch (verdict) {
    case MonitorVerdict::kValid:
      return "valid";
    case MonitorVerdict::kRigidChange:
      return "rigid change";
    case MonitorVerdict::kOutlier:
      return "outlier";
    case MonitorVerdict::kSmoothChange:
      return "smooth change";
  }
  return "unknown";
}

void MonitorCheckOptions::validate() const {
  VRREG_THROW_UNLESS(
      false_alarm_rate > 0.0 && false_alarm_rate < 0.5,
      "monitor check: the false-alarm rate must be in (0, 0.5), got " << false_alarm_rate);
  VRREG_THROW_UNLESS(
      std::isfinite(variance_dof) && variance_dof >= 0.0,
      "monitor check: the variance's degrees of freedom must be >= 0, got " << variance_dof);
}

MonitorCheck check_monitors(const ConstPoints3Ref& baseline_sensor_m,
                            const ConstPoints3Ref& today_sensor_m,
                            const Eigen::Ref<const Eigen::VectorXd>& difference_sd_m,
                            const MonitorCheckOptions& options) {
  options.validate();
  const Eigen::Index n = baseline_sensor_m.cols();
  VRREG_THROW_UNLESS(n >= 1, "monitor check: no monitor points");
  VRREG_THROW_UNLESS(today_sensor_m.cols() == n && difference_sd_m.size() == n,
                     "monitor check: " << n << " baseline points, " << today_sensor_m.cols()
                                       << " read today, " << difference_sd_m.size() << " sd");
  VRREG_THROW_UNLESS(baseline_sensor_m.allFinite() && today_sensor_m.allFinite(),
                     "monitor check: a reading is not finite");
  VRREG_THROW_UNLESS(difference_sd_m.allFinite() && (difference_sd_m.array() > 0.0).all(),
                     "monitor check: every difference sd must be > 0");
  const Points3 d = today_sensor_m - baseline_sensor_m;
  const Eigen::VectorXd sd = difference_sd_m;
  const double alpha = options.false_alarm_rate;
  std::vector<bool> all(static_cast<std::size_t>(n), true);

  const double nu = options.variance_dof;
  const auto bound = [nu](double tail, int k) { return squared_sum_bound(tail, k, nu); };
  MonitorCheck out;
  out.dof = static_cast<int>(3 * n);
  out.chi2 = chi2_of(d, sd, all);
  out.change_rms_m = std::sqrt(d.colwise().squaredNorm().mean());
  // Centred about the sd-weighted centroid: rotation and translation then decouple.
  const Eigen::VectorXd w = sd.array().square().inverse();
  const Eigen::Vector3d centroid = (baseline_sensor_m * w) / w.sum();
  const Points3 p = baseline_sensor_m.colwise() - centroid;
  std::optional<RigidFit> fit;
  if (n >= 3) {
    RigidFit f = fit_rigid(p, d, sd, all);
    if (f.ok) fit = f;
  }
  std::ostringstream why;
  why << std::fixed << std::setprecision(2);  // chi-square values; lengths below in mm, 3 places
  const auto mm = [](double m) {
    std::ostringstream t;
    t << std::fixed << std::setprecision(3) << 1e3 * m;
    return t.str();
  };
  bool rigid_alarm = false;
  bool rest_alarm = false;
  if (fit) {
    const int rest_dof = out.dof - 6;
    const double beta = split_rate(alpha, 6, rest_dof, nu);
    out.rigid_chi2 = out.chi2 - fit->residual_chi2;
    out.rigid_threshold = bound(beta, 6);
    out.residual_threshold = bound(beta, rest_dof);
    out.rigid_residual_chi2 = fit->residual_chi2;
    rigid_alarm = out.rigid_chi2 > out.rigid_threshold;
    rest_alarm = fit->residual_chi2 > out.residual_threshold;
    // Back to the sensor frame's origin: t' = t - omega x centroid.
    fit->change.translation_m -= fit->change.rotation_rad.cross(centroid);
    out.rigid = fit->change;
    if (!rigid_alarm && !rest_alarm) {
      why << "unchanged: rigid part chi2 " << out.rigid_chi2 << " <= " << out.rigid_threshold
          << " (6 dof), the rest " << fit->residual_chi2 << " <= " << out.residual_threshold << " ("
          << rest_dof << " dof); false-alarm rate " << alpha;
      out.rigid.reset();
      out.message = why.str();
      return out;
    }
    if (!rest_alarm) {
      out.verdict = MonitorVerdict::kRigidChange;
      why << "the sensor moved rigidly: " << mm(fit->change.displacement_rms_m)
          << " mm RMS at the monitor points (rigid part chi2 " << out.rigid_chi2 << " > "
          << out.rigid_threshold << ", the rest " << fit->residual_chi2
          << " <= " << out.residual_threshold << ")";
      out.message = why.str();
      return out;
    }
  } else {
    out.threshold = bound(alpha, out.dof);
    if (out.chi2 <= out.threshold) {
      why << "unchanged: chi2 " << out.chi2 << " <= " << out.threshold << " (" << out.dof
          << " dof, false-alarm rate " << alpha << ")";
      out.message = why.str();
      return out;
    }
  }
  // One point off, the others unchanged: the largest standardised difference, the rest tested
  // again (Sidak over the N candidates keeps the rate).
  Eigen::Index worst = 0;
  const Eigen::VectorXd z2 = d.colwise().squaredNorm().transpose().cwiseQuotient(sd.cwiseAbs2());
  z2.maxCoeff(&worst);
  if (n >= 2) {
    std::vector<bool> rest = all;
    rest[static_cast<std::size_t>(worst)] = false;
    const double per_candidate = -std::expm1(std::log1p(-alpha) / static_cast<double>(n));
    if (chi2_of(d, sd, rest) <= bound(per_candidate, out.dof - 3)) {
      out.verdict = MonitorVerdict::kOutlier;
      out.outlier = worst;
      why << "monitor point " << worst + 1 << " moved by " << mm(d.col(worst).norm())
          << " mm, the others are unchanged";
      out.message = why.str();
      return out;
    }
  }
  out.verdict = MonitorVerdict::kSmoothChange;
  why << "changed, not rigidly: " << mm(out.change_rms_m)
      << " mm RMS at the monitor points (the robot drifted?)";
  out.message = why.str();
  return out;
}

}  // namespace vrreg
