// SPDX-License-Identifier: Apache-2.0
#include "vrreg/config.hpp"

namespace vrreg {

const char* version() noexcept { return VRREG_VERSION_STRING; }

}  // namespace vrreg
