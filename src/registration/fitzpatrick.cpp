// SPDX-License-Identifier: Apache-2.0
#include "vrreg/registration/fitzpatrick.hpp"

#include <Eigen/Eigenvalues>

#include "vrreg/core/check.hpp"

namespace vrreg {

double expected_tre_squared(const ConstPoints3Ref& fiducials_m, const Eigen::Vector3d& target_m,
                            double fle_sq_m2) {
  const Eigen::Index n = fiducials_m.cols();
  VRREG_THROW_UNLESS(n >= 3, "TRE prediction needs at least 3 fiducials, got " << n);
  const Eigen::Vector3d centroid = fiducials_m.rowwise().mean();
  const Points3 centred = fiducials_m.colwise() - centroid;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(centred * centred.transpose());
  const Eigen::Matrix3d axes = eig.eigenvectors();
  const Eigen::Vector3d r = target_m - centroid;
  // Squared distance from axis k = |r|^2 - (r . u_k)^2; f_k^2 likewise averaged over fiducials.
  const Eigen::Vector3d proj_target = axes.transpose() * r;
  const Points3 proj_fid = axes.transpose() * centred;
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double d_sq = r.squaredNorm() - proj_target[k] * proj_target[k];
    const double f_sq =
        (proj_fid.colwise().squaredNorm().array() - proj_fid.row(k).array().square()).mean();
    VRREG_THROW_UNLESS(f_sq > 0.0, "TRE prediction: fiducials are collinear");
    sum += d_sq / f_sq;
  }
  return fle_sq_m2 / static_cast<double>(n) * (1.0 + sum / 3.0);
}

double expected_fre_squared(Eigen::Index n_fiducials, double fle_sq_m2) {
  VRREG_THROW_UNLESS(n_fiducials >= 3, "FRE prediction needs at least 3 fiducials");
  return (1.0 - 2.0 / static_cast<double>(n_fiducials)) * fle_sq_m2;
}

}  // namespace vrreg
