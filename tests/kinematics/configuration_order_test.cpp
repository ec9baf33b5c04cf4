// SPDX-License-Identifier: Apache-2.0
// Strategy 2 of Procedure 2 (paper section 4.4): relabelling along a hand-made path with known
// switches, the norm's effect on the choice, angle wrapping, and bad input.
#include "vrreg/kinematics/configuration_order.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::kinematics {
namespace {

using Vec = Eigen::Matrix<double, 4, 1>;

// Three arms far apart in joint space; B is nearer A than C is.
Vec arm(char which, int point) {
  const double drift = 0.02 * point;  // small motion from point to point
  switch (which) {
    case 'A':
      return Vec(0.1 + drift, 0.2, 0.3, 0.4);
    case 'B':
      return Vec(0.1 + drift, 0.2, 1.3, 0.4);  // 1 rad from A
    default:
      return Vec(2.1 + drift, 0.2, 0.3, -1.6);  // ~2.8 rad from A
  }
}

// A point whose configurations are listed (labels 1, 2, 3) as the arms in `listing`.
PointConfigurations listed(const std::string& listing, int point) {
  PointConfigurations p;
  p.q_rad.resize(4, static_cast<Eigen::Index>(listing.size()));
  for (std::size_t k = 0; k < listing.size(); ++k) {
    p.labels.push_back(static_cast<int>(k) + 1);
    p.q_rad.col(static_cast<Eigen::Index>(k)) = arm(listing[k], point);
  }
  return p;
}

TEST(Strategy2Relabelling, HandMadePathWithKnownSwitches) {
  // 5 points x 3 configurations; the IK lists the arms in a different order at points 2 and 4.
  const std::vector<std::string> listings = {"ABC", "ABC", "CAB", "ABC", "BCA"};
  std::vector<PointConfigurations> path;
  for (int p = 0; p < 5; ++p) path.push_back(listed(listings[static_cast<std::size_t>(p)], p));
  const PathRelabelling r = relabel_along_path(path);
  // Label 1 follows arm A, 2 arm B (nearer A), 3 arm C, wherever the IK listed them.
  const std::vector<std::vector<int>> expected = {
      {1, 2, 3}, {1, 2, 3}, {3, 1, 2}, {1, 2, 3}, {2, 3, 1}};
  EXPECT_EQ(r.labels, expected);
  EXPECT_EQ(r.reference, (std::vector<int>{0, 0, 1, 0, 2}));
  EXPECT_EQ(r.n_configurations, 15);
  EXPECT_EQ(r.n_switched, 6);  // all three locations at points 2 and 4
  EXPECT_EQ(r.n_switched_points, 2);
  EXPECT_DOUBLE_EQ(r.switched_locations_fraction(), 6.0 / 15.0);
  EXPECT_DOUBLE_EQ(r.switched_points_fraction(), 2.0 / 5.0);
}

TEST(Strategy2Relabelling, OthersAreRankedByDistanceToTheReferenceAtEachPoint) {
  // At point 1 arm C comes nearer A than B: labels 2 and 3 swap there although the IK did not.
  std::vector<PointConfigurations> path = {listed("ABC", 0), listed("ABC", 1)};
  path[1].q_rad.col(2) = arm('A', 1) + Vec(0.0, 0.0, 0.0, 0.5);
  const PathRelabelling r = relabel_along_path(path);
  EXPECT_EQ(r.labels[1], (std::vector<int>{1, 3, 2}));
  EXPECT_EQ(r.n_switched, 2);
  EXPECT_EQ(r.n_switched_points, 1);
  EXPECT_DOUBLE_EQ(r.switched_points_fraction(), 1.0 / 2.0);     // 1 of 2 nominal points
  EXPECT_DOUBLE_EQ(r.switched_locations_fraction(), 2.0 / 6.0);  // 2 of 6 (point, config)
}

TEST(Strategy2Relabelling, ReferenceStartsAtTheSmallestLabelNotTheFirstColumn) {
  PointConfigurations p0 = listed("BA", 0);
  p0.labels = {2, 1};  // column 0 is label 2: arm A (label 1) is the reference
  const PathRelabelling r = relabel_along_path({p0, listed("AB", 1)});
  EXPECT_EQ(r.reference[0], 1);
  EXPECT_EQ(r.labels[0], (std::vector<int>{2, 1}));
  EXPECT_EQ(r.labels[1], (std::vector<int>{1, 2}));
  EXPECT_EQ(r.n_switched, 0);
}

TEST(Strategy2Relabelling, LinfAndL2PickDifferentReferences) {
  // From the reference 0: X moves every joint by 1 (L2 2, Linf 1), Y one joint by 1.5 (L2 1.5,
  // Linf 1.5). L2 takes Y as the new reference, Linf takes X.
  PointConfigurations p0;
  p0.labels = {1, 2};
  p0.q_rad = Eigen::MatrixXd::Zero(4, 2);
  p0.q_rad.col(1).setConstant(3.0);
  PointConfigurations p1;
  p1.labels = {1, 2};
  p1.q_rad.resize(4, 2);
  p1.q_rad.col(0) = Vec(1.0, 1.0, 1.0, 1.0);  // X, label 1
  p1.q_rad.col(1) = Vec(1.5, 0.0, 0.0, 0.0);  // Y, label 2
  const PathRelabelling l2 = relabel_along_path({p0, p1}, JointNorm::kL2);
  const PathRelabelling linf = relabel_along_path({p0, p1}, JointNorm::kLinf);
  EXPECT_EQ(l2.labels[1], (std::vector<int>{2, 1}));
  EXPECT_EQ(l2.n_switched, 2);
  EXPECT_EQ(linf.labels[1], (std::vector<int>{1, 2}));
  EXPECT_EQ(linf.n_switched, 0);
}

TEST(Strategy2Relabelling, AnglesAreWrapped) {
  using units::kPi;
  PointConfigurations p0;
  p0.labels = {1, 2};
  p0.q_rad.resize(1, 2);
  p0.q_rad << kPi - 0.05, 0.0;
  PointConfigurations p1 = p0;
  p1.q_rad << 1.0, -kPi + 0.05;  // label 2 is 0.1 rad from the reference across +-pi
  const PathRelabelling r = relabel_along_path({p0, p1});
  EXPECT_EQ(r.labels[1], (std::vector<int>{2, 1}));
}

TEST(Strategy2Relabelling, RanksTakeTheLabelsTheFileUses) {
  PointConfigurations p0 = listed("AB", 0);
  p0.labels = {0, 1};
  PointConfigurations p1 = listed("BA", 1);
  p1.labels = {0, 1};
  const PathRelabelling r = relabel_along_path({p0, p1});
  EXPECT_EQ(r.labels[0], (std::vector<int>{0, 1}));
  EXPECT_EQ(r.labels[1], (std::vector<int>{1, 0}));
}

TEST(Strategy2Relabelling, EmptyPathAndBadInput) {
  EXPECT_TRUE(relabel_along_path({}).labels.empty());
  EXPECT_DOUBLE_EQ(relabel_along_path({}).switched_points_fraction(), 0.0);
  EXPECT_DOUBLE_EQ(relabel_along_path({}).switched_locations_fraction(), 0.0);
  PointConfigurations twice = listed("AB", 0);
  twice.labels = {1, 1};
  EXPECT_THROW(relabel_along_path({twice}), InputError);
  PointConfigurations none;
  EXPECT_THROW(relabel_along_path({listed("AB", 0), none}), InputError);
  PointConfigurations short_joints = listed("AB", 1);
  short_joints.q_rad.conservativeResize(3, 2);
  EXPECT_THROW(relabel_along_path({listed("AB", 0), short_joints}), InputError);
  PointConfigurations nan = listed("AB", 1);
  nan.q_rad(0, 0) = std::nan("");
  EXPECT_THROW(relabel_along_path({listed("AB", 0), nan}), InputError);
}

TEST(JointNormNames, ParseWhatToStringPrints) {
  EXPECT_EQ(parse_joint_norm(to_string(JointNorm::kL2)), JointNorm::kL2);
  EXPECT_EQ(parse_joint_norm(to_string(JointNorm::kLinf)), JointNorm::kLinf);
  EXPECT_THROW(parse_joint_norm("L1"), InputError);
}

}  // namespace
}  // namespace vrreg::kinematics
