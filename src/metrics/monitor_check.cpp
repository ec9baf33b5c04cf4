// SPDX-License-Identifier: Apache-2.0
#include "vrreg/metrics/monitor_check.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

#include "vrreg/core/check.hpp"
#include "vrreg/metrics/distributions.hpp"

namespace vrreg {
namespace {

// Weighted least squares of d_i = omega x p_i + t, p about the weighted centroid: with one sd per
// point the translation is the weighted mean and the rotation decouples from it.
struct RigidFit {
  RigidChange change;
  double residual_chi2 = 0.0;
};

Eigen::Matrix3d skew_of(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// Below this fraction of the points' weighted squared size (their distance from the origin
// included) a rotation axis is not seen: points on a line, one point.
constexpr double kUnseenRotation = 1e-9;

RigidFit fit_rigid(const ConstPoints3Ref& baseline, const Points3& d, const Eigen::VectorXd& sd) {
  const Eigen::VectorXd w = sd.array().square().inverse();
  const double total = w.sum();
  const Eigen::Vector3d centroid = (baseline * w) / total;
  const Eigen::Vector3d t_centroid = (d * w) / total;
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < baseline.cols(); ++i) {
    const Eigen::Vector3d p = baseline.col(i) - centroid;
    normal += w(i) * (p.squaredNorm() * Eigen::Matrix3d::Identity() - p * p.transpose());
    rhs += w(i) * p.cross(d.col(i));
  }
  // Pseudo-inverse: an axis the points do not turn about (a line, one point) gets no rotation.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(normal);
  // Against the points' own size (not the spread's, which rounding alone gives one point).
  double size = 0.0;
  for (Eigen::Index i = 0; i < baseline.cols(); ++i) size += w(i) * baseline.col(i).squaredNorm();
  const int most = baseline.cols() == 1 ? 0 : baseline.cols() == 2 ? 2 : 3;
  Eigen::Matrix3d inverse = Eigen::Matrix3d::Zero();
  int rank = 0;
  for (int k = 2; k >= 0 && rank < most; --k) {  // largest first
    const double lambda = eigen.eigenvalues()(k);
    if (lambda > kUnseenRotation * size) {
      inverse += eigen.eigenvectors().col(k) * eigen.eigenvectors().col(k).transpose() / lambda;
      ++rank;
    }
  }
  RigidFit fit;
  RigidChange& c = fit.change;
  c.rotation_rad = inverse * rhs;
  c.rotation_rank = rank;
  c.centroid_m = centroid;
  c.translation_at_centroid_m = t_centroid;
  c.covariance_at_centroid.topLeftCorner<3, 3>() = inverse;
  c.covariance_at_centroid.bottomRightCorner<3, 3>() = Eigen::Matrix3d::Identity() / total;
  // The origin's move: t0 = t_c - omega x c = t_c + [c]x omega; its covariance by the same map.
  c.translation_m = t_centroid - c.rotation_rad.cross(centroid);
  Eigen::Matrix<double, 6, 6> to_origin = Eigen::Matrix<double, 6, 6>::Identity();
  to_origin.bottomLeftCorner<3, 3>() = skew_of(centroid);
  c.covariance = to_origin * c.covariance_at_centroid * to_origin.transpose();
  double moved = 0.0;
  for (Eigen::Index i = 0; i < baseline.cols(); ++i) {
    const Eigen::Vector3d motion = c.rotation_rad.cross(baseline.col(i) - centroid) + t_centroid;
    moved += motion.squaredNorm();
    fit.residual_chi2 += (d.col(i) - motion).squaredNorm() * w(i);
  }
  c.displacement_rms_m = std::sqrt(moved / static_cast<double>(baseline.cols()));
  return fit;
}

double chi2_of(const Points3& d, const Eigen::VectorXd& sd, const std::vector<bool>& use) {
  double chi2 = 0.0;
  for (Eigen::Index i = 0; i < d.cols(); ++i) {
    if (use[static_cast<std::size_t>(i)]) chi2 += d.col(i).squaredNorm() / (sd(i) * sd(i));
  }
  return chi2;
}

std::string mm_text(double m) {
  std::ostringstream t;
  t << std::fixed << std::setprecision(3) << 1e3 * m;
  return t.str();
}

// What a rigid change of these points says, and does not.
std::string rigid_words(const MonitorCheck& out, int n) {
  const RigidChange& r = *out.rigid;
  if (n == 1) {
    return "the monitor point moved by " + mm_text(r.displacement_rms_m) +
           " mm: consistent with a move of the sensor (a bump); one point cannot tell it from a "
           "drift of the robot or from the point itself moving, nor see a turn of the sensor";
  }
  std::string text = "the sensor moved rigidly: " + mm_text(r.displacement_rms_m) +
                     " mm RMS at the monitor points";
  if (r.rotation_rank < 3) text += " (a turn about the line through them is not seen)";
  return text;
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
    case MonitorVerdict::kNoisier:
      return "noisier today";
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

std::vector<std::string> monitor_blind_spots(const ConstPoints3Ref& points_m) {
  VRREG_THROW_UNLESS(points_m.allFinite(), "monitor points: a position is not finite");
  const Eigen::Index n = points_m.cols();
  std::vector<std::string> out;
  if (n == 1) {
    out.emplace_back(
        "one point: a bump, a drift of the robot and the point itself moving look the same, and "
        "a turn of the sensor is not seen");
    return out;
  }
  if (n == 0) return out;
  const Points3 centred = points_m.colwise() - points_m.rowwise().mean();
  const Eigen::Vector3d s =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(centred * centred.transpose())
          .eigenvalues()
          .cwiseMax(0.0)
          .cwiseSqrt();  // ascending: off-plane, off-line, along
  // A spread below 5 % of the largest counts as none: the test then has no power there.
  const bool line = s(1) < 0.05 * s(2);
  const bool plane = s(0) < 0.05 * s(2);
  if (line) {
    out.emplace_back(
        "points on a line: a turn of the sensor about it is not seen, and a drift that moves "
        "them alike looks like a bump");
  } else if (plane) {
    out.emplace_back(
        "points on a plane: a change that grows along its normal from zero on it (a tilt or "
        "stretch of the robot out of that plane) moves none of them; 4 monitor points off one "
        "plane see it (vrreg plan --monitor)");
  }
  return out;
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
  out.blind_spots = monitor_blind_spots(baseline_sensor_m);
  RigidFit fit = fit_rigid(baseline_sensor_m, d, sd);
  out.rigid_dof = 3 + fit.change.rotation_rank;
  out.residual_dof = out.dof - out.rigid_dof;
  out.rigid_chi2 = out.chi2 - fit.residual_chi2;
  out.rigid_residual_chi2 = fit.residual_chi2;
  std::ostringstream why;
  why << std::fixed << std::setprecision(2);  // chi-square values; lengths in mm, 3 places
  bool rest_alarm = false;
  if (out.residual_dof == 0) {
    // One point: the whole change is its translation.
    out.threshold = bound(alpha, out.dof);
    if (out.chi2 <= out.threshold) {
      why << "unchanged: chi2 " << out.chi2 << " <= " << out.threshold << " (" << out.dof
          << " dof, false-alarm rate " << alpha << ")";
      out.message = why.str();
      return out;
    }
  } else {
    const double beta = split_rate(alpha, out.rigid_dof, out.residual_dof, nu);
    out.rigid_threshold = bound(beta, out.rigid_dof);
    out.residual_threshold = bound(beta, out.residual_dof);
    const bool rigid_alarm = out.rigid_chi2 > out.rigid_threshold;
    rest_alarm = fit.residual_chi2 > out.residual_threshold;
    if (!rigid_alarm && !rest_alarm) {
      why << "unchanged: rigid part chi2 " << out.rigid_chi2 << " <= " << out.rigid_threshold
          << " (" << out.rigid_dof << " dof), the rest " << fit.residual_chi2
          << " <= " << out.residual_threshold << " (" << out.residual_dof
          << " dof); false-alarm rate " << alpha;
      out.message = why.str();
      return out;
    }
  }
  out.rigid = fit.change;
  if (!rest_alarm) {
    out.verdict = MonitorVerdict::kRigidChange;
    why << rigid_words(out, static_cast<int>(n));
    if (out.residual_dof > 0) {
      why << " (rigid part chi2 " << out.rigid_chi2 << " > " << out.rigid_threshold << ", the rest "
          << fit.residual_chi2 << " <= " << out.residual_threshold << ")";
    } else {
      why << " (chi2 " << out.chi2 << " > " << out.threshold << ", " << out.dof << " dof)";
    }
    out.message = why.str();
    return out;
  }
  // One point off, the others unchanged: the largest standardised difference, the rest tested
  // again (Sidak over the N candidates keeps the rate).
  Eigen::Index worst = 0;
  const Eigen::VectorXd z2 = d.colwise().squaredNorm().transpose().cwiseQuotient(sd.cwiseAbs2());
  z2.maxCoeff(&worst);
  std::vector<bool> rest = all;
  rest[static_cast<std::size_t>(worst)] = false;
  const double per_candidate = -std::expm1(std::log1p(-alpha) / static_cast<double>(n));
  if (chi2_of(d, sd, rest) <= bound(per_candidate, out.dof - 3)) {
    out.verdict = MonitorVerdict::kOutlier;
    out.outlier = worst;
    why << "monitor point " << worst + 1 << " moved by " << mm_text(d.col(worst).norm())
        << " mm, the others are unchanged";
    if (n == 2) why << " (or the robot drifted near it: two points cannot tell)";
    out.message = why.str();
    return out;
  }
  out.verdict = MonitorVerdict::kSmoothChange;
  why << "changed, not rigidly: " << mm_text(out.change_rms_m)
      << " mm RMS at the monitor points (the robot drifted?)";
  out.message = why.str();
  return out;
}

}  // namespace vrreg
