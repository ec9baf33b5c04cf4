// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading numbers out of reproduce.json (docs/report.md): a number, or {"mean": m, "sd": s} when
// `vrreg reproduce --seeds K` averaged over seeds. Absent or null means "not given"; anything
// else is an InputError naming the key.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace vrreg::report::detail {

/// A value over seeds: the mean, and the standard deviation when averaged.
struct Stat {
  double mean = 0.0;
  std::optional<double> sd;
};

/// obj[key] as a Stat; empty when absent or null. `where` names obj in errors ("table1.A1").
std::optional<Stat> stat_at(const nlohmann::json& obj, const std::string& key,
                            const std::string& where);

/// obj[key] as an integer label (config, strategy); empty when absent or null.
std::optional<int> int_at(const nlohmann::json& obj, const std::string& key,
                          const std::string& where);

/// obj[key] as a string; empty when absent or null.
std::optional<std::string> string_at(const nlohmann::json& obj, const std::string& key,
                                     const std::string& where);

/// obj[key] as an array of numbers (means, when an entry is {mean, sd}); empty when absent.
std::vector<double> numbers_at(const nlohmann::json& obj, const std::string& key,
                               const std::string& where);

/// obj[key] as an array of strings (labels); numbers are written as text; empty when absent.
std::vector<std::string> strings_at(const nlohmann::json& obj, const std::string& key,
                                    const std::string& where);

/// "0.626", "0.626 ± 0.012" or "—" with `decimals` places.
std::string stat_text(const std::optional<Stat>& value, int decimals);

/// A fixed-point number as text.
std::string fixed(double value, int decimals);

/// Spearman rank correlation of two equally long sequences (ties share their mean rank).
double spearman(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace vrreg::report::detail
