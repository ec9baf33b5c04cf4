// SPDX-License-Identifier: Apache-2.0
#include "vrreg/registration/rigid.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "rigid_moments.hpp"
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

namespace {

// Sum of w_j ||s R X_j + tau - Y_j||^2 (Eq. 2), optionally storing each residual.
double residual_sum(const ConstPoints3Ref& x, const ConstPoints3Ref& y,
                    const Eigen::Ref<const Eigen::VectorXd>& weights, const SimilarityTransform& t,
                    Eigen::VectorXd* residuals_m) {
  const bool weighted = weights.size() != 0;
  const Eigen::Index n = x.cols();
  if (residuals_m != nullptr) residuals_m->resize(n);
  const Eigen::Matrix3d sr = t.scale * t.rotation;
  double sum_sq = 0.0;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double r = (sr * x.col(j) + t.translation_m - y.col(j)).norm();
    if (residuals_m != nullptr) (*residuals_m)[j] = r;
    sum_sq += (weighted ? weights[j] : 1.0) * r * r;
  }
  return sum_sq;
}

// Rotation, scale, spread and collinearity from the centred moments (Eq. 2); translation from the
// means. Shared by both paths so that they differ only in how the sums are formed.
void solve(const Eigen::Matrix3d& h, const Eigen::Matrix3d& cxx, double w,
           const Eigen::Vector3d& mean_x, const Eigen::Vector3d& mean_y,
           const RegistrationOptions& options, RegistrationResult& result) {
  // Maximise tr(R H) with H = sum x y' = U S V': R = V diag(1, 1, det(V U')) U' (never a reflection).
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  // For corresponding points H ~ R Cxx, so sqrt(S / w) is the RMS spread along the principal axes
  // (exact for rigid data). Rank < 2 means collinear or coincident points in either frame, or sets
  // that do not correspond; the slow path then says which.
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
  t.translation_m = mean_y - t.scale * (t.rotation * mean_x);
}

// Below this many points the residuals path (without storing residuals) costs less than the
// fast kernel and the extended-precision closed form.
constexpr Eigen::Index kClosedFormMinPoints = 64;
// The closed-form FRE is used while the residual sum is at least this share of the spread terms
// (sum |s R a|^2 + sum |b|^2, centred): its relative rounding error is ~1e-16 / share (2e-12 for
// 0.5 mm noise on a 0.3 m layout), so at most ~1e-10 here (tests/registration/rigid_fast_test.cpp).
// Nearer fits take the residual pass.
constexpr long double kClosedFormMinShare = 1e-6L;

using Real = long double;  // the closed form's cancellation needs more than 53 bits

// The fast path (options.residuals == false): compensated one-pass moments, FRE from them.
RegistrationResult register_from_moments(const ConstPoints3Ref& x, const ConstPoints3Ref& y,
                                         const RegistrationOptions& options,
                                         const Eigen::Ref<const Eigen::VectorXd>& weights) {
  const Eigen::Vector3d shift_x = x.col(0);
  const Eigen::Vector3d shift_y = y.col(0);
  const detail::FastMoments m = detail::fast_moments(x, y, weights, shift_x, shift_y);
  const auto sum = [&m](int k) { return static_cast<Real>(m.hi[k]) + static_cast<Real>(m.lo[k]); };
  bool finite = true;
  for (int k = 0; k < detail::kMoments; ++k) finite = finite && std::isfinite(m.hi[k]);
  if (!finite) throw_non_finite(x, y);
  const Real w = weights.size() != 0 ? sum(detail::kWeight) : static_cast<Real>(x.cols());
  Real sx[3], sy[3];
  for (int r = 0; r < 3; ++r) {
    sx[r] = sum(detail::kSumX + r);
    sy[r] = sum(detail::kSumY + r);
  }
  // Centred moments: S - s s' / w.
  Real hc[3][3], cc[3][3];
  static constexpr int kXX[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      hc[r][c] = sum(detail::kSumXY + 3 * r + c) - sx[r] * sy[c] / w;
      cc[r][c] = sum(detail::kSumXX + kXX[r][c]) - sx[r] * sx[c] / w;
    }
  }
  const Real syy = sum(detail::kSumYY) - (sy[0] * sy[0] + sy[1] * sy[1] + sy[2] * sy[2]) / w;
  Eigen::Matrix3d h, cxx;
  Eigen::Vector3d mean_x, mean_y;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      h(r, c) = static_cast<double>(hc[r][c]);
      cxx(r, c) = static_cast<double>(cc[r][c]);
    }
    mean_x[r] = shift_x[r] + static_cast<double>(sx[r] / w);
    mean_y[r] = shift_y[r] + static_cast<double>(sy[r] / w);
  }
  RegistrationResult result;
  solve(h, cxx, static_cast<double>(w), mean_x, mean_y, options, result);
  const SimilarityTransform& t = result.T_robot_sensor;

  // sum w |s R a + tau - b|^2 = s^2 tr(R Cxx R') + tr(Cyy) - 2 s tr(R H) for the centred moments
  // and the optimal translation; exact for any R, so R's rounding is accounted for.
  Real rcr = 0.0L, rh = 0.0L;
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      const Real rik = t.rotation(i, k);
      rh += rik * hc[k][i];
      for (int l = 0; l < 3; ++l) rcr += rik * cc[k][l] * static_cast<Real>(t.rotation(i, l));
    }
  }
  const Real s = t.scale;
  const Real spread_terms = s * s * rcr + syy;
  const Real q = spread_terms - 2.0L * s * rh;
  double sum_sq = 0.0;
  if (q >= kClosedFormMinShare * spread_terms) {
    sum_sq = static_cast<double>(q);
  } else {
    sum_sq = residual_sum(x, y, weights, t, nullptr);
  }
  result.fre_m = std::sqrt(sum_sq / static_cast<double>(w));
  return result;
}

}  // namespace

RegistrationResult register_rigid(const ConstPoints3Ref& points_sensor_m,
                                  const ConstPoints3Ref& points_robot_m,
                                  const RegistrationOptions& options,
                                  const Eigen::Ref<const Eigen::VectorXd>& weights) {
  options.validate();
  check_inputs(points_sensor_m, points_robot_m, weights);
  // Few points: the two passes below cost less than the closed form (and give its exact numbers).
  if (!options.residuals && points_sensor_m.cols() >= kClosedFormMinPoints) {
    return register_from_moments(points_sensor_m, points_robot_m, options, weights);
  }
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

  RegistrationResult result;
  solve(h, cxx, w, shift_x + mean_x_shifted, shift_y + mean_y_shifted, options, result);
  // Residuals (Eq. 2) in a second pass: exact even when FRE is at rounding level.
  const double sum_sq =
      residual_sum(points_sensor_m, points_robot_m, weights, result.T_robot_sensor,
                   options.residuals ? &result.residuals_m : nullptr);
  result.fre_m = std::sqrt(sum_sq / w);
  return result;
}

}  // namespace vrreg
