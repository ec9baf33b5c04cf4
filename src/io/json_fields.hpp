// SPDX-License-Identifier: Apache-2.0
#pragma once
// Typed access to the members of a parsed JSON document, with errors that name the key path
// (e.g. "fiducials[3].robot_mm") and the file.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vrreg/core/types.hpp"

namespace vrreg::io::detail {

/// Reads members of JSON objects; every failure throws FileError(source, 0, "<path>: ...").
class JsonFields {
 public:
  explicit JsonFields(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& message) const;

  /// The member `key` of `object` (at `path`); throws when `object` lacks it.
  const nlohmann::json& member(const nlohmann::json& object, const std::string& path,
                               const std::string& key) const;
  /// A finite number.
  double number(const nlohmann::json& object, const std::string& path,
                const std::string& key) const;
  /// An integer (no fraction).
  int integer(const nlohmann::json& object, const std::string& path, const std::string& key) const;
  /// An integer or null.
  std::optional<int> optional_integer(const nlohmann::json& object, const std::string& path,
                                      const std::string& key) const;
  /// A string.
  std::string string(const nlohmann::json& object, const std::string& path,
                     const std::string& key) const;
  /// An array of finite numbers; `size` >= 0 requires that many elements.
  std::vector<double> numbers(const nlohmann::json& object, const std::string& path,
                              const std::string& key, int size) const;
  /// `value` itself as an array of finite numbers (`where` names it in errors).
  std::vector<double> array_of_numbers(const nlohmann::json& value, const std::string& where,
                                       int size) const;
  /// An array of three finite numbers, divided by `divisor` (a unit conversion).
  Eigen::Vector3d vector3(const nlohmann::json& object, const std::string& path,
                          const std::string& key, double divisor) const;
  /// Throws unless `object` is a JSON object.
  void require_object(const nlohmann::json& object, const std::string& path) const;

 private:
  std::string source_;
};

/// "path.key" (or "key" at the top level).
std::string join_path(const std::string& path, const std::string& key);

}  // namespace vrreg::io::detail
