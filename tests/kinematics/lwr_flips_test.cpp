// SPDX-License-Identifier: Apache-2.0
// The eight LWR configurations from the base one at once (lwr_flips, used by the IK) give the
// bits of one configuration at a time (lwr_flip), also where wrapping is at its edges.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <numbers>
#include <vector>

#include "kinematics/lwr_solver.hpp"
#include "vrreg/core/random.hpp"

namespace vrreg::kinematics {
namespace {

TEST(LwrFlips, SameBitsAsOneConfigurationAtATime) {
  constexpr double pi = std::numbers::pi;
  std::vector<double> values = {0.0,     -0.0, pi,   -pi,    pi / 2,  -pi / 2,   1e-300,
                                -1e-300, 3.0,  -3.0, 2 * pi, -2 * pi, 3.1415926, -3.1415926};
  Random rng(7);
  for (int k = 0; k < 2000; ++k) values.push_back(rng.uniform(-3.5 * pi, 3.5 * pi));
  for (std::size_t k = 0; k + 7 <= values.size(); ++k) {
    double base[7];
    for (int i = 0; i < 7; ++i) {
      base[i] = values[(k + static_cast<std::size_t>(3 * i)) % values.size()];
    }
    double all[8][7];
    detail::lwr_flips(base, all);
    for (int index = 0; index < 8; ++index) {
      double one[7];
      detail::lwr_flip(base, index, one);
      for (int i = 0; i < 7; ++i) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(all[index][i]), std::bit_cast<std::uint64_t>(one[i]))
            << "joint " << i << " of configuration " << index << " from " << base[i];
      }
    }
  }
}

}  // namespace
}  // namespace vrreg::kinematics
