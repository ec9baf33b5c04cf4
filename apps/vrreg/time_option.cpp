// SPDX-License-Identifier: Apache-2.0
#include "time_option.hpp"

#include "file_options.hpp"
#include "vrreg/io/monitor_json.hpp"

namespace vrreg::cli {

CLI::Option* add_time_option(CLI::App& command, std::string& time) {
  const CLI::Validator iso8601(
      [](const std::string& text) {
        return io::parse_iso8601_s(text)
                   ? std::string()
                   : "'" + text + "' is not an ISO 8601 time (" + io::kIso8601Forms + ")";
      },
      "ISO 8601");
  return not_a_file(command, command
                                 .add_option("--time", time,
                                             std::string("when the points were read, ISO 8601: ") +
                                                 io::kIso8601Forms + " (default: now, UTC)")
                                 ->check(iso8601));
}

}  // namespace vrreg::cli
