// SPDX-License-Identifier: Apache-2.0
// The identification Jacobian of marker_partials against central finite differences of forward
// kinematics with perturbed DH rows, joints and marker offsets.
#include "vrreg/kinematics/marker_partials.hpp"

#include <gtest/gtest.h>

#include "kinematics_test_support.hpp"
#include "vrreg/kinematics/forward_kinematics.hpp"
#include "vrreg/kinematics/robots.hpp"

namespace vrreg::kinematics {
namespace {

using testing::marker_at;

SerialChain with_row_delta(const SerialChain& c, int i, int which, double h) {
  std::vector<DhRow> rows = c.rows();
  DhRow& r = rows[static_cast<std::size_t>(i)];
  (which == 0 ? r.a_m : which == 1 ? r.d_m : which == 2 ? r.alpha_rad : r.theta_offset_rad) += h;
  return SerialChain(c.name(), rows, c.limits(), c.T_base_dh0(), c.T_flange_tcp());
}

void expect_partials_match(const SerialChain& chain, std::uint64_t seed) {
  Random rng(seed);
  const Eigen::Vector3d p(0.03, -0.02, 0.09);
  constexpr double kH = 1e-6;
  // Central differences: truncation ~h^2 |p'''| ~ 1e-12, rounding ~1e-16 / h ~ 1e-10.
  constexpr double kTol = 1e-8;
  for (int trial = 0; trial < 5; ++trial) {
    const JointVector q = testing::random_joints(rng, chain);
    const MarkerPartials d = marker_partials(chain, q, p);
    EXPECT_LT((d.position_m - marker_at(chain, q, p)).norm(), 1e-15);
    for (int i = 0; i < chain.n_joints(); ++i) {
      JointVector qp = q, qm = q;
      qp(i) += kH;
      qm(i) -= kH;
      const Eigen::Vector3d fd = (marker_at(chain, qp, p) - marker_at(chain, qm, p)) / (2 * kH);
      EXPECT_LT((fd - d.d_joint.col(i)).norm(), kTol) << "joint " << i;
      const Eigen::Matrix3Xd* cols[4] = {&d.d_a, &d.d_d, &d.d_alpha, &d.d_theta};
      for (int which = 0; which < 4; ++which) {
        const Eigen::Vector3d fd_dh = (marker_at(with_row_delta(chain, i, which, kH), q, p) -
                                       marker_at(with_row_delta(chain, i, which, -kH), q, p)) /
                                      (2 * kH);
        EXPECT_LT((fd_dh - cols[which]->col(i)).norm(), kTol) << "row " << i << " param " << which;
      }
    }
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d dp = kH * Eigen::Vector3d::Unit(k);
      const Eigen::Vector3d fd =
          (marker_at(chain, q, p + dp) - marker_at(chain, q, p - dp)) / (2 * kH);
      EXPECT_LT((fd - d.R_base_flange.col(k)).norm(), kTol);
    }
  }
}

TEST(MarkerPartials, Ur5MatchesFiniteDifferences) { expect_partials_match(ur5(), 3); }

TEST(MarkerPartials, PrismaticJointsMatchFiniteDifferences) {
  // A UR5 whose first and fourth joints slide (along z0, z3) instead of turning.
  std::vector<DhRow> rows = ur5().rows();
  rows[0].type = JointType::kPrismatic;
  rows[3].type = JointType::kPrismatic;
  std::vector<JointLimits> limits = ur5().limits();
  limits[0] = limits[3] = {-0.5, 0.5};
  expect_partials_match(SerialChain("sliding", rows, limits), 5);
}

TEST(MarkerPartials, Lwr4WithBaseTransformMatchesFiniteDifferences) {
  Eigen::Isometry3d base = testing::pose_from({0.1, -0.2, 0.3}, 0.2, -0.1, 0.7);
  expect_partials_match(lwr4().with_base(base), 4);
}

}  // namespace
}  // namespace vrreg::kinematics
