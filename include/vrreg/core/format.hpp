// SPDX-License-Identifier: Apache-2.0
#pragma once
// Number formatting for messages, tables and files: one place (fmt underneath), so that every
// command and report prints a length the same way. Lengths come in metres (SI inside) and are
// printed in millimetres, like the paper.
#include <Eigen/Core>
#include <span>
#include <string>
#include <string_view>
#include <utility>

namespace vrreg {

/// `value` with `decimals` places after the point ("%.*f").
std::string format_fixed(double value, int decimals);
/// `value` with at most `significant` significant digits, shortest of fixed or exponent ("%.*g").
std::string format_general(double value, int significant);
/// A length in metres printed in millimetres with `decimals` places: "0.626".
std::string format_mm(double length_m, int decimals = 3);
/// A 3-vector in metres printed in millimetres: "[x, y, z]".
std::string format_mm3(const Eigen::Vector3d& v_m, int decimals = 3);

/// A library option's name and what a front end calls it ("cube_edge", "--cube-mm").
using OptionWord = std::pair<std::string_view, std::string_view>;
/// `message` with every option named as `name` (backquoted, as library messages name options)
/// replaced by its word from `words`; names not in `words` are left as they are.
std::string with_option_words(std::string message, std::span<const OptionWord> words);

}  // namespace vrreg
