// SPDX-License-Identifier: Apache-2.0
#include "robot_file_document.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdlib>

#include "vrreg/io/file_error.hpp"
#include "vrreg/io/json_text.hpp"

namespace vrreg::io::detail {
namespace {

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

// Bounds on what a YAML document may expand to: its aliases can make a few hundred bytes stand for
// billions of values ("billion laughs"), and nesting drives the recursion below.
struct Budget {
  std::size_t values = 0;
};

nlohmann::json convert(const YAML::Node& node, const std::string& path, RobotDocument& doc,
                       const std::string& source, std::size_t depth, Budget& budget) {
  const auto line = static_cast<std::size_t>(node.Mark().line + 1);
  if (++budget.values > kMaxDocumentValues) {
    throw FileError(source, line,
                    "more than " + std::to_string(kMaxDocumentValues) +
                        " values (YAML aliases expanding without bound?)");
  }
  if (depth > kMaxDocumentDepth) {
    throw FileError(source, line,
                    "nested deeper than " + std::to_string(kMaxDocumentDepth) + " levels");
  }
  doc.lines[path] = line;
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
        array.push_back(
            convert(item, path + "[" + std::to_string(i++) + "]", doc, source, depth + 1, budget));
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
        object[key] = convert(item.second, child, doc, source, depth + 1, budget);
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

void RobotDocument::fail(const std::string& source, const std::string& path,
                         const std::string& message) const {
  throw FileError(source, line_of(path), (path.empty() ? "" : path + ": ") + message);
}

RobotDocument parse_robot_json(const std::string& text, const std::string& source) {
  RobotDocument doc;
  doc.root = parse_json_document(text, source, "robot file");
  return doc;
}

RobotDocument parse_robot_yaml(const std::string& text, const std::string& source) {
  RobotDocument doc;
  try {
    const YAML::Node node = YAML::Load(text);
    Budget budget;
    doc.root = convert(node, "", doc, source, 0, budget);
  } catch (const YAML::Exception& e) {
    throw FileError(source, e.mark.is_null() ? 0 : static_cast<std::size_t>(e.mark.line + 1),
                    "invalid YAML: " + e.msg);
  }
  return doc;
}

}  // namespace vrreg::io::detail
