// SPDX-License-Identifier: Apache-2.0
// Corner look-up with several arm configurations per nominal position (Strategy 3, section 4.4).
#include "vrreg/correction/corner_candidates.hpp"

#include <gtest/gtest.h>

#include "vrreg/core/check.hpp"

namespace vrreg {
namespace {

// A 3 x 3 x 3 grid (10 mm), every node twice (two configurations), the second copy after all
// the first ones; one corner node of the first copy is missing.
Points3 doubled_grid() {
  Points3 p(3, 53);
  Eigen::Index c = 0;
  for (int copy = 0; copy < 2; ++copy) {
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
          if (copy == 0 && i == 2 && j == 2 && k == 2) continue;
          p.col(c++) = 0.01 * Eigen::Vector3d(i, j, k);
        }
  }
  return p;
}

TEST(CornerCandidates, FindsEveryConfigurationAtACorner) {
  const Points3 p = doubled_grid();
  const CornerCandidates index(p, 1e-6);
  EXPECT_EQ(index.at(Eigen::Vector3d(0, 0, 0)), (std::vector<Eigen::Index>{0, 26}));
  EXPECT_EQ(index.at(Eigen::Vector3d(0.02, 0.02, 0.02)), (std::vector<Eigen::Index>{52}));
  EXPECT_TRUE(index.at(Eigen::Vector3d(0.005, 0, 0)).empty());

  const CornerFiducials cube = index.octuplet(Eigen::Vector3d(0.005, 0.015, 0.005), 0.01);
  for (std::size_t c = 0; c < 8; ++c) {
    ASSERT_EQ(cube[c].size(), 2U) << c;
    const Eigen::Vector3d expected(c & 1U ? 0.01 : 0.0, c & 2U ? 0.02 : 0.01, c & 4U ? 0.01 : 0.0);
    for (const Eigen::Index j : cube[c]) EXPECT_LT((p.col(j) - expected).norm(), 1e-12) << c;
  }
  const CornerFiducials outside = index.octuplet(Eigen::Vector3d(0.025, 0.015, 0.015), 0.01);
  EXPECT_TRUE(outside[1].empty());
  EXPECT_EQ(outside[0].size(), 2U);
  EXPECT_THROW((void)index.octuplet(Eigen::Vector3d::Zero(), 2e-6), InputError);
}

TEST(CornerCandidates, VolumeCornersAreTheBoundingBoxCorners) {
  const Points3 p = doubled_grid();
  const CornerFiducials corners = CornerCandidates(p, 1e-6).volume_corners();
  for (std::size_t c = 0; c < 8; ++c) {
    const Eigen::Vector3d expected(c & 1U ? 0.02 : 0.0, c & 2U ? 0.02 : 0.0, c & 4U ? 0.02 : 0.0);
    ASSERT_FALSE(corners[c].empty());
    EXPECT_EQ(corners[c].size(), c == 7 ? 1U : 2U);
    for (const Eigen::Index j : corners[c]) EXPECT_LT((p.col(j) - expected).norm(), 1e-12) << c;
  }
}

TEST(CornerCandidates, BadInput) {
  EXPECT_THROW(CornerCandidates(Points3(3, 0), 1e-6), InputError);
  EXPECT_THROW(CornerCandidates(doubled_grid(), 0.0), InputError);
  Points3 flat(3, 4);
  flat << 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0;
  EXPECT_THROW((void)CornerCandidates(flat, 1e-6).volume_corners(), InputError);
}

}  // namespace
}  // namespace vrreg
