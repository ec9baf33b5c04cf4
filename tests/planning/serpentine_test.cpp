// SPDX-License-Identifier: Apache-2.0
// Visiting order inside a cube: every node once, consecutive nodes one grid step apart (paper
// Fig. 2), for every start corner and axis order; the target goes between two cell corners.
#include "vrreg/planning/serpentine.hpp"

#include <set>

#include "vrreg/core/check.hpp"
#include "vrreg_test.hpp"

namespace vrreg::planning {
namespace {

int manhattan(const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
  return (a - b).cwiseAbs().sum();
}

TEST(Serpentine, EveryVariantVisitsEveryNodeOnceInUnitSteps) {
  for (int n = 1; n <= 5; ++n) {
    for (int k = 0; k < kSerpentineVariants; ++k) {
      const SerpentineVariant v = serpentine_variant(k);
      const std::vector<Eigen::Vector3i> path = serpentine(n, v);
      ASSERT_EQ(path.size(), static_cast<std::size_t>(n * n * n));
      std::set<std::array<int, 3>> seen;
      for (std::size_t i = 0; i < path.size(); ++i) {
        const Eigen::Vector3i& p = path[i];
        ASSERT_TRUE((p.array() >= 0).all() && (p.array() < n).all());
        EXPECT_TRUE(seen.insert({p.x(), p.y(), p.z()}).second) << "node visited twice";
        if (i > 0) {
          EXPECT_EQ(manhattan(path[i - 1], p), 1) << "n " << n << " variant " << k;
        }
      }
      // Starts at the variant's corner; serpentine_ends agrees with the path.
      for (int axis = 0; axis < 3; ++axis) {
        EXPECT_EQ(path.front()(axis), ((v.start_corner >> axis) & 1) != 0 ? n - 1 : 0);
      }
      const auto ends = serpentine_ends(n, v);
      EXPECT_EQ(ends[0], path.front());
      EXPECT_EQ(ends[1], path.back());
    }
  }
}

TEST(Serpentine, VariantsCoverEveryCornerAndAxisOrder) {
  std::set<std::pair<int, std::array<int, 3>>> variants;
  for (int k = 0; k < kSerpentineVariants; ++k) {
    const SerpentineVariant v = serpentine_variant(k);
    variants.insert({v.start_corner, v.axes});
  }
  EXPECT_EQ(variants.size(), 48u);
  EXPECT_THROW(serpentine_variant(48), InputError);
  EXPECT_THROW(serpentine(0, {}), InputError);
}

TEST(Serpentine, CentreGoesBetweenTwoAdjacentCornersOfTheCentreCell) {
  for (const int n : {2, 4, 6}) {
    for (int k = 0; k < kSerpentineVariants; k += 5) {
      std::vector<Eigen::Vector3i> path = serpentine(n, serpentine_variant(k));
      const std::size_t at = insert_centre(path, n);
      ASSERT_EQ(path.size(), static_cast<std::size_t>(n * n * n + 1));
      ASSERT_GT(at, 0u);
      ASSERT_LT(at, path.size() - 1);
      EXPECT_EQ(path[at], kCentreIndex);
      const int lo = n / 2 - 1;
      for (const Eigen::Vector3i& corner : {path[at - 1], path[at + 1]}) {
        EXPECT_TRUE((corner.array() >= lo).all() && (corner.array() <= lo + 1).all())
            << "n " << n << ": neighbour of the target is not a corner of its cell";
      }
      EXPECT_EQ(manhattan(path[at - 1], path[at + 1]), 1);
    }
  }
}

}  // namespace
}  // namespace vrreg::planning
