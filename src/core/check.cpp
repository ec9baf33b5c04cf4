// SPDX-License-Identifier: Apache-2.0
#include "vrreg/core/check.hpp"

namespace vrreg::detail {

void throw_input_error(const std::string& message, const char* /*file*/, int /*line*/) {
  // The source location is deliberately not in the text: users see the message, not our code.
  throw InputError(message);
}

}  // namespace vrreg::detail
