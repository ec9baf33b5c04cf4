#include "vrreg/registration/rigid.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

// First and second moments of both point sets about a shift point taken from the data, in one
// pass: shifting by a data point keeps the cancellation in (sum x y' - n mx my') harmless.
struct Moments {
  double weight_sum = 0.0;
  Eigen::Vector3d sum_x = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_y = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sum_xy = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d sum_xx = Eigen::Matrix3d::Zero();
};

template <bool kWeighted>
Moments accumulate(const ConstPoints3Ref& x, const ConstPoints3Ref& y,
                   const Eigen::Ref<const Eigen::VectorXd>& w, const Eigen::Vector3d& shift_x,
                   const Eigen::Vector3d& shift_y) {
  // Scalar accumulators: the compiler keeps them in registers (Eigen temporaries would not be).
  double s = 0, sx0 = 0, sx1 = 0, sx2 = 0, sy0 = 0, sy1 = 0, sy2 = 0;
  double h00 = 0, h01 = 0, h02 = 0, h10 = 0, h11 = 0, h12 = 0, h20 = 0, h21 = 0, h22 = 0;
  double c00 = 0, c01 = 0, c02 = 0, c11 = 0, c12 = 0, c22 = 0;
  const double* px = x.data();
  const double* py = y.data();
  const Eigen::Index n = x.cols();
  const Eigen::Index stride_x = x.outerStride();
  const Eigen::Index stride_y = y.outerStride();
  for (Eigen::Index j = 0; j < n; ++j, px += stride_x, py += stride_y) {
    const double wj = kWeighted ? w[j] : 1.0;
    const double a0 = px[0] - shift_x[0], a1 = px[1] - shift_x[1], a2 = px[2] - shift_x[2];
    const double b0 = py[0] - shift_y[0], b1 = py[1] - shift_y[1], b2 = py[2] - shift_y[2];
    const double wa0 = wj * a0, wa1 = wj * a1, wa2 = wj * a2;
    const double wb0 = wj * b0, wb1 = wj * b1, wb2 = wj * b2;
    s += wj;
    sx0 += wa0, sx1 += wa1, sx2 += wa2;
    sy0 += wb0, sy1 += wb1, sy2 += wb2;
    h00 += wa0 * b0, h01 += wa0 * b1, h02 += wa0 * b2;
    h10 += wa1 * b0, h11 += wa1 * b1, h12 += wa1 * b2;
    h20 += wa2 * b0, h21 += wa2 * b1, h22 += wa2 * b2;
    c00 += wa0 * a0, c01 += wa0 * a1, c02 += wa0 * a2, c11 += wa1 * a1, c12 += wa1 * a2;
    c22 += wa2 * a2;
  }
  Moments m;
  m.weight_sum = s;
  m.sum_x << sx0, sx1, sx2;
  m.sum_y << sy0, sy1, sy2;
  m.sum_xy << h00, h01, h02, h10, h11, h12, h20, h21, h22;
  m.sum_xx << c00, c01, c02, c01, c11, c12, c02, c12, c22;
  return m;
}

// RMS spread along the principal axes, largest first.
Eigen::Vector3d principal_spread(const Eigen::Matrix3d& covariance) {
  // Iterative, not computeDirect: the closed form leaves ~1e-13 relative on a zero eigenvalue,
  // which would hide exact collinearity. Only the failure path calls this.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d ev = eig.eigenvalues().cwiseMax(0.0);  // ascending
  return {std::sqrt(ev[2]), std::sqrt(ev[1]), std::sqrt(ev[0])};
}

void check_inputs(const ConstPoints3Ref& x, const ConstPoints3Ref& y,
                  const Eigen::Ref<const Eigen::VectorXd>& w) {
  VRREG_THROW_UNLESS(x.cols() == y.cols(), "registration needs corresponding points: "
                                               << x.cols() << " sensor points but " << y.cols()
                                               << " robot points");
  VRREG_THROW_UNLESS(x.cols() >= 3, "registration needs at least 3 fiducials, got " << x.cols());
  if (w.size() != 0) {
    VRREG_THROW_UNLESS(w.size() == x.cols(),
                       "registration got " << w.size() << " weights for " << x.cols() << " points");
    VRREG_THROW_UNLESS(w.allFinite() && (w.array() >= 0.0).all(),
                       "registration weights must be finite and non-negative");
    VRREG_THROW_UNLESS((w.array() > 0.0).count() >= 3,
                       "registration needs at least 3 points with positive weight");
  }
}

// Called only when the sums came out non-finite: names the first bad point.
[[noreturn]] void throw_non_finite(const ConstPoints3Ref& x, const ConstPoints3Ref& y) {
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    VRREG_THROW_UNLESS(x.col(j).allFinite(), "sensor point " << j << " is not finite");
    VRREG_THROW_UNLESS(y.col(j).allFinite(), "robot point " << j << " is not finite");
  }
  VRREG_THROW_UNLESS(false, "registration sums overflowed: coordinates too large");
}

void check_spread(double spread_0, double spread_1, double tolerance, const char* frame) {
  VRREG_THROW_UNLESS(spread_0 > 0.0,
                     "the " << frame << " fiducials all coincide: registration is undefined");
  VRREG_THROW_UNLESS(spread_1 > tolerance * spread_0,
                     "the " << frame << " fiducials are collinear (spread ratio "
                            << spread_1 / spread_0 << " < " << tolerance
                            << "): rotation about their line is undefined");
}

}  // namespace

void RegistrationOptions::validate() const {
  VRREG_THROW_UNLESS(std::isfinite(collinearity_tolerance) && collinearity_tolerance >= 0.0 &&
                         collinearity_tolerance < 1.0,
                     "collinearity_tolerance must be in [0, 1), got " << collinearity_tolerance);
}

RegistrationResult register_rigid(const ConstPoints3Ref& points_sensor_m,
                                  const ConstPoints3Ref& points_robot_m,
                                  const RegistrationOptions& options,
                                  const Eigen::Ref<const Eigen::VectorXd>& weights) {
  options.validate();
  check_inputs(points_sensor_m, points_robot_m, weights);
  const bool weighted = weights.size() != 0;
  const Eigen::Vector3d shift_x = points_sensor_m.col(0);
  const Eigen::Vector3d shift_y = points_robot_m.col(0);
  const Moments m =
      weighted ? accumulate<true>(points_sensor_m, points_robot_m, weights, shift_x, shift_y)
               : accumulate<false>(points_sensor_m, points_robot_m, weights, shift_x, shift_y);

  // Non-finite input makes the sums non-finite: one check instead of two extra passes.
  if (!(m.sum_xy.allFinite() && m.sum_xx.allFinite() && m.sum_x.allFinite() &&
        m.sum_y.allFinite())) {
    throw_non_finite(points_sensor_m, points_robot_m);
  }
  const double w = m.weight_sum;
  const Eigen::Vector3d mean_x_shifted = m.sum_x / w;
  const Eigen::Vector3d mean_y_shifted = m.sum_y / w;
  // Centred second moments (weighted covariances times the weight sum).
  const Eigen::Matrix3d h = m.sum_xy - w * mean_x_shifted * mean_y_shifted.transpose();
  const Eigen::Matrix3d cxx = m.sum_xx - w * mean_x_shifted * mean_x_shifted.transpose();

  // Maximise tr(R H) with H = sum x y' = U S V': R = V diag(1, 1, det(V U')) U' (never a reflection).
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  // For corresponding points H ~ R Cxx, so sqrt(S / w) is the RMS spread along the principal axes
  // (exact for rigid data). Rank < 2 means collinear or coincident points in either frame, or sets
  // that do not correspond; the slow path then says which.
  RegistrationResult result;
  const Eigen::Vector3d singular_values = svd.singularValues();
  result.spread_m = (singular_values / w).cwiseMax(0.0).cwiseSqrt();
  if (!(result.spread_m[1] > options.collinearity_tolerance * result.spread_m[0])) {
    const Eigen::Vector3d spread_x = principal_spread(cxx / w);
    check_spread(spread_x[0], spread_x[1], options.collinearity_tolerance, "sensor");
    VRREG_THROW_UNLESS(false, "the robot fiducials are collinear or coincide, or do not correspond "
                              "to the sensor fiducials (cross-covariance rank < 2)");
  }
  result.collinearity = result.spread_m[1] / result.spread_m[0];
  Eigen::Vector3d d = Eigen::Vector3d::Ones();
  if ((svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0) d[2] = -1.0;
  SimilarityTransform& t = result.T_robot_sensor;
  t.rotation = svd.matrixV() * d.asDiagonal() * svd.matrixU().transpose();
  if (options.estimate_scale) {
    t.scale = singular_values.dot(d) / cxx.trace();
  }
  const Eigen::Vector3d mean_x = shift_x + mean_x_shifted;
  const Eigen::Vector3d mean_y = shift_y + mean_y_shifted;
  t.translation_m = mean_y - t.scale * (t.rotation * mean_x);

  // Residuals (Eq. 2) in a second pass: exact even when FRE is at rounding level.
  const Eigen::Index n = points_sensor_m.cols();
  result.residuals_m.resize(n);
  const Eigen::Matrix3d sr = t.scale * t.rotation;
  double sum_sq = 0.0;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double r = (sr * points_sensor_m.col(j) + t.translation_m - points_robot_m.col(j)).norm();
    result.residuals_m[j] = r;
    sum_sq += (weighted ? weights[j] : 1.0) * r * r;
  }
  result.fre_m = std::sqrt(sum_sq / w);
  return result;
}

}  // namespace vrreg
