// SPDX-License-Identifier: Apache-2.0
#pragma once
// io's name for vrreg::FileError (core/file_error.hpp), which every reader throws.
#include "vrreg/core/file_error.hpp"

namespace vrreg::io {
using vrreg::FileError;
}  // namespace vrreg::io
