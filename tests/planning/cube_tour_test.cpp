// SPDX-License-Identifier: Apache-2.0
// Order of the cubes: a permutation, travel reported right, never worse than the input order,
// and the obvious order on a line of cubes.
#include "vrreg/planning/cube_tour.hpp"

#include <algorithm>
#include <numeric>

#include "vrreg/core/check.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/planning/fiducial_grid.hpp"
#include "vrreg/planning/serpentine.hpp"
#include "vrreg_test.hpp"

namespace vrreg::planning {
namespace {

struct Offsets {
  Points3 entry{3, kSerpentineVariants};
  Points3 exit{3, kSerpentineVariants};
};

Offsets offsets(const CubeGeometry& g) {
  Offsets o;
  for (int v = 0; v < kSerpentineVariants; ++v) {
    const auto ends = serpentine_ends(g.nodes_per_axis, serpentine_variant(v));
    o.entry.col(v) = cube_node(g, Eigen::Vector3d::Zero(), ends[0]);
    o.exit.col(v) = cube_node(g, Eigen::Vector3d::Zero(), ends[1]);
  }
  return o;
}

TEST(CubeTour, NeverWorseThanTheInputOrderAndReportsItsTravel) {
  const CubeGeometry g = cube_geometry(0.010, 0.005);
  const Offsets o = offsets(g);
  Random rng(7);
  for (int trial = 0; trial < 30; ++trial) {
    const int m = 1 + static_cast<int>(rng.below(12));
    const Points3 centres = testing::random_points(rng, m, 0.15);
    const CubeTour tour = plan_cube_tour(centres, o.entry, o.exit);
    std::vector<int> sorted = tour.order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> identity(static_cast<std::size_t>(m));
    std::iota(identity.begin(), identity.end(), 0);
    EXPECT_EQ(sorted, identity) << "not a permutation";
    EXPECT_NEAR(between_cube_travel_m(centres, o.entry, o.exit, tour.order, tour.variant),
                tour.between_cubes_m, 1e-12);
    for (int v = 0; v < kSerpentineVariants; v += 7) {
      const double naive = between_cube_travel_m(centres, o.entry, o.exit, identity,
                                                 std::vector<int>(static_cast<std::size_t>(m), v));
      EXPECT_LE(tour.between_cubes_m, naive + 1e-12) << "trial " << trial << " variant " << v;
    }
  }
}

TEST(CubeTour, CubesOnALineAreVisitedAlongTheLine) {
  const CubeGeometry g = cube_geometry(0.010, 0.005);  // edge 25 mm
  const Offsets o = offsets(g);
  Points3 centres(3, 5);
  const std::vector<double> x{0.2, 0.0, 0.3, 0.1, 0.4};
  for (int i = 0; i < 5; ++i)
    centres.col(i) = Eigen::Vector3d(x[static_cast<std::size_t>(i)], 0, 0);
  const CubeTour tour = plan_cube_tour(centres, o.entry, o.exit);
  const std::vector<int> forward{1, 3, 0, 2, 4};
  std::vector<int> backward(forward.rbegin(), forward.rend());
  EXPECT_TRUE(tour.order == forward || tour.order == backward);
  // Each hop leaves a cube by its face towards the next: 100 mm apart minus the 25 mm edge.
  EXPECT_NEAR(tour.between_cubes_m, 4 * (0.1 - 0.025), 1e-12);
}

TEST(CubeTour, BadInputThrows) {
  const Offsets o = offsets(cube_geometry(0.01, 0.005));
  EXPECT_THROW(plan_cube_tour(Points3(3, 0), o.entry, o.exit), InputError);
  EXPECT_THROW(plan_cube_tour(Points3::Zero(3, 2), o.entry, Points3::Zero(3, 1)), InputError);
  EXPECT_THROW(between_cube_travel_m(Points3::Zero(3, 2), o.entry, o.exit, {0, 1}, {0}),
               InputError);
}

}  // namespace
}  // namespace vrreg::planning
