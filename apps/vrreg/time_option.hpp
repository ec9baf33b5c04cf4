// SPDX-License-Identifier: Apache-2.0
#pragma once
// `--time` of check and update: when the points were read, ISO 8601 (io::kIso8601Forms); anything
// else is a one-line usage error.
#include <CLI/CLI.hpp>
#include <string>

namespace vrreg::cli {

/// Adds --time (not a file) checked as ISO 8601; empty when not given (the command takes now).
CLI::Option* add_time_option(CLI::App& command, std::string& time);

}  // namespace vrreg::cli
