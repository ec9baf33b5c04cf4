// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/procedure2.hpp"

#include "vrreg/core/check.hpp"

namespace vrreg::planning {

int strategy_number(Strategy strategy) { return static_cast<int>(strategy); }

Strategy strategy_from_number(int number) {
  VRREG_THROW_UNLESS(number >= 0 && number <= 3,
                     "Procedure 2 strategy " << number << " does not exist (0, 1, 2 or 3)");
  return static_cast<Strategy>(number);
}

}  // namespace vrreg::planning
