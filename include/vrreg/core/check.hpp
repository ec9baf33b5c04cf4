// SPDX-License-Identifier: Apache-2.0
#pragma once
// Bad caller input throws InputError with the offending values in the message (design.md 7).
#include <sstream>
#include <stdexcept>
#include <string>

namespace vrreg {

/// Thrown when a caller passes input the method cannot use (too few points, NaN, ...).
class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

namespace detail {
[[noreturn]] void throw_input_error(const std::string& message, const char* file, int line);
}  // namespace detail

}  // namespace vrreg

/// Throws vrreg::InputError with a streamed message unless `condition` holds.
#define VRREG_THROW_UNLESS(condition, message)                                  \
  do {                                                                          \
    if (!(condition)) {                                                         \
      std::ostringstream vrreg_message_stream_;                                 \
      vrreg_message_stream_ << message;                                         \
      ::vrreg::detail::throw_input_error(vrreg_message_stream_.str(), __FILE__, \
                                         __LINE__);                             \
    }                                                                           \
  } while (false)
