// SPDX-License-Identifier: Apache-2.0
// Strategy 2 (paper section 4.4) on a measurement set: the visiting path is the order of first
// appearance of the points, every location of a point is one of its configurations.
#include "vrreg/planning/strategy2_labels.hpp"

#include <gtest/gtest.h>

#include "vrreg/core/check.hpp"

namespace vrreg::planning {
namespace {

Location location(const std::string& point, Role role, int config, std::vector<double> q) {
  Location loc;
  loc.point = point;
  loc.role = role;
  loc.config = config;
  loc.q_rad = std::move(q);
  loc.n_readings = 1;
  return loc;
}

// Arm "near" (joints ~0) and arm "far" (joints ~2); the file lists them in either order.
MeasurementSet set_with_swaps() {
  MeasurementSet set;
  set.source = "cell.csv";
  set.has_config = true;
  set.n_joints = 2;
  const std::vector<double> near0{0.0, 0.0}, far0{2.0, 2.0};
  const std::vector<double> near1{0.1, 0.0}, far1{2.1, 2.0};
  set.locations = {
      location("P1", Role::kFiducial, 1, near0), location("P1", Role::kFiducial, 2, far0),
      location("P2", Role::kTarget, 1, far1),    location("P3", Role::kFiducial, 1, near1),
      location("P2", Role::kTarget, 2, near1),  // P2's second row comes after P3's first
      location("P3", Role::kFiducial, 2, far1),
  };
  return set;
}

TEST(Strategy2Labels, RelabelsEveryLocationAlongTheFileOrder) {
  const Strategy2Result r = relabel_strategy2(set_with_swaps());
  const std::vector<int> expected = {1, 2, 2, 1, 1, 2};  // P2 swapped: label 1 follows "near"
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(r.set.locations[i].config, expected[i]) << i;
  }
  EXPECT_EQ(r.summary.n_points, 3);
  EXPECT_EQ(r.summary.n_locations, 6);
  EXPECT_EQ(r.summary.n_switched, 2);
  EXPECT_EQ(r.summary.n_switched_points, 1);
  EXPECT_DOUBLE_EQ(r.summary.switched_locations_fraction(), 2.0 / 6.0);
  EXPECT_DOUBLE_EQ(r.summary.switched_points_fraction(), 1.0 / 3.0);
  EXPECT_EQ(r.summary.switched_by_file_label, (std::map<int, int>{{1, 1}, {2, 1}}));
  EXPECT_EQ(r.set.select(Role::kTarget, 1), (std::vector<std::size_t>{4}));
  // Everything else is kept.
  EXPECT_EQ(r.set.source, "cell.csv");
  EXPECT_EQ(r.set.locations[2].q_rad, (std::vector<double>{2.1, 2.0}));
}

TEST(Strategy2Labels, NeedsConfigurationsAndJoints) {
  MeasurementSet no_config = set_with_swaps();
  no_config.has_config = false;
  EXPECT_THROW(relabel_strategy2(no_config), InputError);
  MeasurementSet no_joints = set_with_swaps();
  no_joints.n_joints = 0;
  EXPECT_THROW(relabel_strategy2(no_joints), InputError);
  MeasurementSet short_row = set_with_swaps();
  short_row.locations[3].q_rad.pop_back();
  EXPECT_THROW(relabel_strategy2(short_row), InputError);
  MeasurementSet unlabelled = set_with_swaps();
  unlabelled.locations[1].config.reset();
  EXPECT_THROW(relabel_strategy2(unlabelled), InputError);
}

}  // namespace
}  // namespace vrreg::planning
