// SPDX-License-Identifier: Apache-2.0
#include "far_field.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "point_index.hpp"
#include "vrreg/registration/fitzpatrick.hpp"

namespace vrreg::detail {
namespace {

// Fiducials averaged into an anchor for methods without one at the support's edge: a cube's
// corners on a lattice.
constexpr std::size_t kAnchorNeighbours = 8;

// The weight of "the trend goes on" against "the field stops" beyond the support: nothing
// inside tells them apart (file comment), so even; the answer holds half the trend's change and
// the sd the mixture's w (1 - w) of its square.
constexpr double kTrendWeight = 0.5;
// The absorbed rotation's growth, in units of the field's mean squared rate |G|_F^2 / 3 times the
// curl share. Calibrated on the far-field cells (seeds 1-5, docs/uncertainty.md): with 1 a
// tracker's warp gave RMS of TRE/sd up to 1.61 at 100 lattice sizes; with 1.25, 1.4.
constexpr double kAbsorbedTiltShare = 1.25;
// Where the point's joints left the fiducials' ranges (the joint model: the arm moved joints the
// fiducials never did), the field changes another way at its mean rate |G|_F / sqrt(3) times
// sqrt of this. A UR5 plan asked about a cell turned 90 degrees about the base
// (tests/cli/joint_extrapolation_cli_test.cpp) gave RMS of TRE/sd 1.62 with none (seed 2), 1.41,
// 0.67, 0.88 on seeds 2-4 with 2.
constexpr double kClampedJointsShare = 2.0;

// The quadratic basis in scaled coordinates u: 1, u0, u1, u2, u0^2, u1^2, u2^2, u0 u1, u0 u2,
// u1 u2, and its derivative along u_a.
constexpr int kQuadraticTerms = 10;
Eigen::Matrix<double, kQuadraticTerms, 1> quadratic_terms(const Eigen::Vector3d& u) {
  Eigen::Matrix<double, kQuadraticTerms, 1> t;
  t << 1, u(0), u(1), u(2), u(0) * u(0), u(1) * u(1), u(2) * u(2), u(0) * u(1), u(0) * u(2),
      u(1) * u(2);
  return t;
}
Eigen::Matrix<double, kQuadraticTerms, 1> quadratic_derivative(const Eigen::Vector3d& u, int a) {
  Eigen::Matrix<double, kQuadraticTerms, 1> d = Eigen::Matrix<double, kQuadraticTerms, 1>::Zero();
  d(1 + a) = 1.0;
  d(4 + a) = 2.0 * u(a);
  // u_a u_b for b != a: columns 7 (0,1), 8 (0,2), 9 (1,2).
  const int b = (a + 1) % 3;
  const int c = (a + 2) % 3;
  d(a + b == 1 ? 7 : a + b == 2 ? 8 : 9) = u(b);
  d(a + c == 1 ? 7 : a + c == 2 ? 8 : 9) = u(c);
  return d;
}

// A field whose gradient has no evidence of its curl is taken halfway between none and an
// isotropic field's.
constexpr double kCurlShareUnknown = 0.5;

// How much of an isotropic field's curl the corrections show, 0..1: twice the variation over the
// fiducials of the antisymmetric part of their gradient against the symmetric part's (an
// isotropic field's ratio is 1/2; a field whose components each vary along their own axis, a
// tracker's axis-wise distortion, has none), from a quadratic fit of the robot-frame corrections,
// each part less what the noise <FLE^2> puts into it; weighed against kCurlShareUnknown by how
// much of the symmetric variation is the field's (a straight field shows none). 1 where the fit
// cannot be made (fewer than 20 fiducials, a flat layout). The registration absorbed the mean of
// the antisymmetric part as a rotation.
double curl_share(const CorrectorData& data, const Eigen::Vector3d& centre_m, double scale_m,
                  double fle_sq_m2) {
  const Eigen::Index n = data.size();
  if (n < 2 * kQuadraticTerms) return 1.0;
  const Points3 u = (data.fiducials_robot_m.colwise() - centre_m) / scale_m;
  Eigen::MatrixXd basis(n, kQuadraticTerms);
  for (Eigen::Index j = 0; j < n; ++j) basis.row(j) = quadratic_terms(u.col(j)).transpose();
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(basis);
  if (qr.rank() < kQuadraticTerms) return 1.0;
  const Eigen::MatrixXd coefficients = qr.solve(
      Eigen::MatrixXd((data.T_robot_sensor.rotation * data.corrections_sensor_m).transpose()));
  const Eigen::MatrixXd normal_inverse = (basis.transpose() * basis).inverse();
  // The gradient (d correction_i / d u_a) at each fiducial, and the derivative rows' deviations
  // from their mean, whose spread under the coefficients' noise is the noise's share.
  std::array<Eigen::MatrixXd, 3> derivative;
  for (int a = 0; a < 3; ++a) {
    derivative[static_cast<std::size_t>(a)].resize(n, kQuadraticTerms);
    for (Eigen::Index j = 0; j < n; ++j)
      derivative[static_cast<std::size_t>(a)].row(j) = quadratic_derivative(u.col(j), a).transpose();
    Eigen::MatrixXd& d = derivative[static_cast<std::size_t>(a)];
    d.rowwise() -= d.colwise().mean();
  }
  double anti = 0.0;
  double sym = 0.0;
  for (Eigen::Index j = 0; j < n; ++j) {
    Eigen::Matrix3d g;
    for (int a = 0; a < 3; ++a)
      g.col(a) = (derivative[static_cast<std::size_t>(a)].row(j) * coefficients).transpose();
    anti += (0.5 * (g - g.transpose())).squaredNorm();
    sym += (0.5 * (g + g.transpose())).squaredNorm();
  }
  // Noise of variance s^2 per component: entry (i, a) of the gradient varies by
  // w_a = s^2 sum_j d_aj' (F'F)^-1 d_aj over the fiducials, the components independently; an
  // off-diagonal pair splits evenly between the two parts, a diagonal entry is symmetric.
  const double s2 = fle_sq_m2 / 3.0;
  std::array<double, 3> w{};
  for (int a = 0; a < 3; ++a) {
    const Eigen::MatrixXd& d = derivative[static_cast<std::size_t>(a)];
    w[static_cast<std::size_t>(a)] = s2 * (d * normal_inverse).cwiseProduct(d).sum();
  }
  const double pairs = w[0] + w[1] + w[2];  // sum over a < b of (w_a + w_b) / 2
  const double anti_field = std::max(0.0, anti - pairs);
  const double sym_noise = pairs + w[0] + w[1] + w[2];
  const double sym_field = std::max(0.0, sym - sym_noise);
  if (!(sym_field > 0.0)) return kCurlShareUnknown;
  const double evidence = sym_field / (sym_field + sym_noise);
  return evidence * std::min(1.0, 2.0 * anti_field / sym_field) +
         (1.0 - evidence) * kCurlShareUnknown;
}

double median_of(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

}  // namespace

FarField::FarField(const CorrectorData& data)
    : fiducials_robot_m_(data.fiducials_robot_m),
      corrections_sensor_m_(data.corrections_sensor_m),
      index_(std::make_unique<PointIndex>(data.fiducials_robot_m)) {
  const Eigen::Index n = data.size();
  if (n == 0) return;
  box_lo_m_ = fiducials_robot_m_.rowwise().minCoeff();
  box_hi_m_ = fiducials_robot_m_.rowwise().maxCoeff();
  const Eigen::Vector3d mean_m = corrections_sensor_m_.rowwise().mean();
  field_spread_m_ = std::sqrt(2.0 * (corrections_sensor_m_.colwise() - mean_m).squaredNorm() /
                              static_cast<double>(n));
  std::vector<double> ratio;
  std::vector<double> difference_sq;
  for (Eigen::Index j = 0; j < n; ++j) {
    const std::vector<Eigen::Index> two = index_->nearest_k(fiducials_robot_m_.col(j), 2);
    if (two.size() < 2) continue;
    const double d_m = (fiducials_robot_m_.col(two[1]) - fiducials_robot_m_.col(j)).norm();
    if (d_m <= 0.0) continue;
    const double difference_m =
        (corrections_sensor_m_.col(two[1]) - corrections_sensor_m_.col(j)).norm();
    ratio.push_back(difference_m / d_m);
    difference_sq.push_back(difference_m * difference_m);
  }
  neighbour_gradient_ = median_of(ratio);
  fle_sq_m2_ = data.noise_sd_m ? 3.0 * *data.noise_sd_m * *data.noise_sd_m
                               : 0.5 * median_of(difference_sq);

  // The affine trend by least squares on [1, (y - c) / s] (scaled: well conditioned), its slope
  // block's covariance per unit residual variance from the pseudo-inverse (a flat layout leaves
  // the gradient across its plane at 0: only the other terms grow that way).
  const Eigen::Vector3d centre_m = fiducials_robot_m_.rowwise().mean();
  const double scale_m =
      std::max((box_hi_m_ - box_lo_m_).maxCoeff(), std::numeric_limits<double>::min());
  Eigen::MatrixXd basis(n, 4);
  basis.col(0).setOnes();
  basis.rightCols(3) = ((fiducials_robot_m_.colwise() - centre_m) / scale_m).transpose();
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(basis);
  const Eigen::MatrixXd coefficients = cod.solve(corrections_sensor_m_.transpose());  // 4 x 3
  gradient_ = coefficients.bottomRows(3).transpose() / scale_m;
  // B+ (B+)' = (B' B)+: the 4 x 4 Gram matrix's pseudo-inverse, not the 4 x n one (whose
  // pseudoInverse() solves against an n x n identity: minutes and gigabytes at 10^4 fiducials).
  const Eigen::Matrix4d gram = basis.transpose() * basis;
  const Eigen::Matrix4d gram_pinv =
      Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix4d>(gram).pseudoInverse();
  slope_covariance_per_m2_ = gram_pinv.bottomRightCorner(3, 3) / (scale_m * scale_m);
  const Eigen::Index dof = n - cod.rank();
  const double rss_m2 =
      (basis * coefficients - corrections_sensor_m_.transpose()).squaredNorm();
  // Without redundancy the residual says nothing: the noise is the least it can be.
  residual_variance_m2_ =
      std::max(dof > 0 ? rss_m2 / static_cast<double>(dof) : 0.0, fle_sq_m2_);
  curl_share_ = curl_share(data, centre_m, scale_m, fle_sq_m2_);
}

Eigen::Vector3d FarField::trend_step_sensor_m(const Eigen::Vector3d& at_m,
                                              const Eigen::Vector3d& anchor_m) const {
  return kTrendWeight * (gradient_ * (at_m - anchor_m));
}

FarField::~FarField() = default;
FarField::FarField(FarField&&) noexcept = default;
FarField& FarField::operator=(FarField&&) noexcept = default;

double FarField::extrapolated_sd_m(double sd_anchor_m, double moved_m, const Eigen::Vector3d& at_m,
                                   const Eigen::Vector3d& anchor_m, bool joints_clamped) const {
  const Eigen::Vector3d step_m = at_m - anchor_m;
  const double rate_sq = gradient_.squaredNorm() / 3.0;  // the mean squared change per metre
  // The trend goes on or stops: the mixture's spread of the trend's change and slope.
  const double trend_sq_m2 =
      kTrendWeight * (1.0 - kTrendWeight) *
      ((gradient_ * step_m).squaredNorm() +
       residual_variance_m2_ * step_m.dot(slope_covariance_per_m2_ * step_m));
  // The field stops: the registration's rotation, which absorbed the antisymmetric part of its
  // gradient, keeps turning the mapping (as much as the corrections' curl shows), and joints the
  // fiducials never moved change it further.
  const double share =
      kAbsorbedTiltShare * curl_share_ + (joints_clamped ? kClampedJointsShare : 0.0);
  const double other_way_sq_m2 = share * rate_sq * step_m.squaredNorm();
  // Between neighbours it changes by up to its spread over the distance (a joint clamped, a move
  // without a length: the whole spread).
  const double neighbours_m = joints_clamped
                                  ? field_spread_m_
                                  : std::min(neighbour_gradient_ * moved_m, field_spread_m_);
  const double registration_sq_m2 =
      fiducials_robot_m_.cols() < 3
          ? 0.0
          : std::max(0.0, expected_tre_squared(fiducials_robot_m_, at_m, fle_sq_m2_) -
                              expected_tre_squared(fiducials_robot_m_, anchor_m, fle_sq_m2_));
  return std::sqrt(sd_anchor_m * sd_anchor_m + trend_sq_m2 + other_way_sq_m2 +
                   neighbours_m * neighbours_m + registration_sq_m2);
}

void FarField::nearest_mean(const Eigen::Vector3d& at_m, Eigen::Vector3d& correction_sensor_m,
                            double& sd_m) const {
  const std::vector<Eigen::Index> near = index_->nearest_k(at_m, kAnchorNeighbours);
  correction_sensor_m.setZero();
  for (const Eigen::Index j : near) correction_sensor_m += corrections_sensor_m_.col(j);
  const auto k = static_cast<double>(near.size());
  correction_sensor_m /= k;
  // The mean's error as the field at the edge: the field's change over the neighbourhood and
  // the noise left in the mean, both about what the k corrections scatter about their mean.
  double scatter_m2 = 0.0;
  for (const Eigen::Index j : near)
    scatter_m2 += (corrections_sensor_m_.col(j) - correction_sensor_m).squaredNorm();
  sd_m = near.size() > 1 ? std::sqrt(scatter_m2 / (k - 1.0)) : std::sqrt(fle_sq_m2_);
}

}  // namespace vrreg::detail
