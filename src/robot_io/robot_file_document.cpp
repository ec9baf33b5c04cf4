#include "robot_file_document.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdlib>

#include "vrreg/io/file_error.hpp"

namespace vrreg::io::detail {
namespace {

std::size_t line_of_byte(const std::string& text, std::size_t byte) {
  const std::size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
  return 1 + static_cast<std::size_t>(
                 std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
}

// A plain YAML scalar that reads as a number becomes one; quoted scalars stay strings.
nlohmann::json scalar_value(const YAML::Node& node) {
  const std::string& text = node.Scalar();
  if (node.Tag() != "!") {
    if (text == "~" || text == "null" || text == "Null" || text == "NULL") return nullptr;
    double value = 0.0;
    if (YAML::convert<double>::decode(node, value)) return value;
    if (text == "true" || text == "false") return text == "true";
  }
  return text;
}

nlohmann::json convert(const YAML::Node& node, const std::string& path, RobotDocument& doc,
                       const std::string& source) {
  doc.lines[path] = static_cast<std::size_t>(node.Mark().line + 1);
  switch (node.Type()) {
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined:
      return nullptr;
    case YAML::NodeType::Scalar:
      return scalar_value(node);
    case YAML::NodeType::Sequence: {
      nlohmann::json array = nlohmann::json::array();
      std::size_t i = 0;
      for (const YAML::Node& item : node) {
        array.push_back(convert(item, path + "[" + std::to_string(i++) + "]", doc, source));
      }
      return array;
    }
    case YAML::NodeType::Map: {
      nlohmann::json object = nlohmann::json::object();
      for (const auto& item : node) {
        if (!item.first.IsScalar()) {
          throw FileError(source, static_cast<std::size_t>(item.first.Mark().line + 1),
                          "keys must be plain names");
        }
        const std::string key = item.first.Scalar();
        const std::string child = path.empty() ? key : path + "." + key;
        if (object.contains(key)) {
          throw FileError(source, static_cast<std::size_t>(item.first.Mark().line + 1),
                          child + ": duplicate key");
        }
        object[key] = convert(item.second, child, doc, source);
      }
      return object;
    }
  }
  return nullptr;
}

}  // namespace

std::size_t RobotDocument::line_of(std::string path) const {
  while (true) {
    const auto it = lines.find(path);
    if (it != lines.end()) return it->second;
    if (path.empty()) return 0;
    const std::size_t cut = path.find_last_of(".[");
    path = cut == std::string::npos ? std::string() : path.substr(0, cut);
  }
}

RobotDocument parse_robot_json(const std::string& text, const std::string& source) {
  RobotDocument doc;
  try {
    doc.root = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    std::string detail = e.what();
    const std::size_t colon = detail.find(": ", detail.find("parse error"));
    if (colon != std::string::npos) detail.erase(0, colon + 2);
    throw FileError(source, line_of_byte(text, e.byte), "invalid JSON: " + detail);
  }
  return doc;
}

RobotDocument parse_robot_yaml(const std::string& text, const std::string& source) {
  RobotDocument doc;
  try {
    const YAML::Node node = YAML::Load(text);
    doc.root = convert(node, "", doc, source);
  } catch (const YAML::Exception& e) {
    throw FileError(source, e.mark.is_null() ? 0 : static_cast<std::size_t>(e.mark.line + 1),
                    "invalid YAML: " + e.msg);
  }
  return doc;
}

}  // namespace vrreg::io::detail
