// SPDX-License-Identifier: Apache-2.0
// Library messages name options as `name`; a front end swaps in its own words from one table.
#include <gtest/gtest.h>

#include <array>

#include "vrreg/core/format.hpp"

namespace vrreg {
namespace {

TEST(OptionWords, EveryNamedOptionTakesItsWordAndOthersStay) {
  constexpr std::array<OptionWord, 2> words{{{"cube_edge", "--cube-mm"}, {"robot", "--robot"}}};
  EXPECT_EQ(with_option_words("set `cube_edge` (got 0 mm); `cube_edge` > 0; no `robot`", words),
            "set --cube-mm (got 0 mm); --cube-mm > 0; no --robot");
  EXPECT_EQ(with_option_words("`seed` and cube_edge unquoted", words),
            "`seed` and cube_edge unquoted");
  EXPECT_EQ(with_option_words("", words), "");
  // A word that contains its own name is not replaced again.
  constexpr std::array<OptionWord, 1> self{{{"robot", "`robot` (arm)"}}};
  EXPECT_EQ(with_option_words("`robot`", self), "`robot` (arm)");
}

}  // namespace
}  // namespace vrreg
