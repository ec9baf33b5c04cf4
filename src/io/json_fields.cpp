// SPDX-License-Identifier: Apache-2.0
#include "json_fields.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include "vrreg/io/file_error.hpp"
#include "vrreg/io/json_text.hpp"

namespace vrreg::io::detail {

using nlohmann::json;

std::string join_path(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

void JsonFields::fail(const std::string& path, const std::string& message) const {
  throw FileError(source_, 0,
                  (path.empty() ? std::string("model") : "'" + path + "'") + ": " + message);
}

void JsonFields::require_object(const json& object, const std::string& path) const {
  if (!object.is_object())
    fail(path, std::string("expected an object, found ") + object.type_name());
}

const json& JsonFields::member(const json& object, const std::string& path,
                               const std::string& key) const {
  require_object(object, path);
  const auto it = object.find(key);
  if (it == object.end()) fail(join_path(path, key), "missing key");
  return *it;
}

double JsonFields::number(const json& object, const std::string& path,
                          const std::string& key) const {
  const json& value = member(object, path, key);
  if (!value.is_number()) {
    fail(join_path(path, key), std::string("expected a number, found ") + value.type_name());
  }
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(join_path(path, key), "number is not finite");
  return x;
}

int JsonFields::integer(const json& object, const std::string& path, const std::string& key) const {
  const json& value = member(object, path, key);
  const std::string where = join_path(path, key);
  constexpr auto kMax = std::numeric_limits<int>::max();
  if (value.is_number_unsigned()) {
    const auto v = value.get<std::uint64_t>();
    if (v > static_cast<std::uint64_t>(kMax)) fail(where, "integer out of range");
    return static_cast<int>(v);
  }
  if (value.is_number_integer()) {
    const auto v = value.get<std::int64_t>();
    if (v < std::numeric_limits<int>::min() || v > kMax) fail(where, "integer out of range");
    return static_cast<int>(v);
  }
  fail(where, std::string("expected an integer, found ") +
                  (value.is_number() ? quote_value(value) : value.type_name()));
}

std::optional<int> JsonFields::optional_integer(const json& object, const std::string& path,
                                                const std::string& key) const {
  if (member(object, path, key).is_null()) return std::nullopt;
  return integer(object, path, key);
}

std::string JsonFields::string(const json& object, const std::string& path,
                               const std::string& key) const {
  const json& value = member(object, path, key);
  if (!value.is_string()) {
    fail(join_path(path, key), std::string("expected a string, found ") + value.type_name());
  }
  return value.get<std::string>();
}

std::vector<double> JsonFields::numbers(const json& object, const std::string& path,
                                        const std::string& key, int size) const {
  return array_of_numbers(member(object, path, key), join_path(path, key), size);
}

std::vector<double> JsonFields::array_of_numbers(const json& value, const std::string& where,
                                                 int size) const {
  if (!value.is_array()) fail(where, std::string("expected an array, found ") + value.type_name());
  if (size >= 0 && value.size() != static_cast<std::size_t>(size)) {
    fail(where,
         "expected " + std::to_string(size) + " numbers, found " + std::to_string(value.size()));
  }
  std::vector<double> out;
  out.reserve(value.size());
  for (std::size_t i = 0; i < value.size(); ++i) {
    const json& element = value[i];
    const std::string element_path = where + "[" + std::to_string(i) + "]";
    if (!element.is_number()) {
      fail(element_path, std::string("expected a number, found ") + element.type_name());
    }
    const double x = element.get<double>();
    if (!std::isfinite(x)) fail(element_path, "number is not finite");
    out.push_back(x);
  }
  return out;
}

Eigen::Vector3d JsonFields::vector3(const json& object, const std::string& path,
                                    const std::string& key, double divisor) const {
  const std::vector<double> v = numbers(object, path, key, 3);
  return Eigen::Vector3d(v[0], v[1], v[2]) / divisor;
}

}  // namespace vrreg::io::detail
