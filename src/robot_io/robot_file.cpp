// SPDX-License-Identifier: Apache-2.0
#include "vrreg/robot_io/robot_file.hpp"

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <vector>

#include "robot_file_document.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/file_error.hpp"
#include "vrreg/io/input_file.hpp"
#include "vrreg/io/json_text.hpp"
#include "vrreg/kinematics/pose.hpp"
#include "vrreg/kinematics/robots.hpp"
#include "vrreg/robot_io/urdf_robot.hpp"

namespace vrreg::io {
namespace {

using kinematics::DhRow;
using kinematics::JointLimits;
using nlohmann::json;

// Validating reader over a RobotDocument: every error names the file, line and key path.
class RobotReader {
 public:
  RobotReader(const detail::RobotDocument& doc, std::string source)
      : doc_(doc), source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& message) const {
    doc_.fail(source_, path, message);
  }

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

  void require_object(const json& value, const std::string& path) const {
    if (!value.is_object())
      fail(path, "expected an object with named keys, got " + quote_value(value));
  }

  void allow_keys(const json& object, const std::string& path,
                  const std::set<std::string>& allowed) const {
    for (const auto& item : object.items()) {
      if (allowed.count(item.key()) == 0) {
        std::string list;
        for (const std::string& k : allowed) list += (list.empty() ? "" : ", ") + k;
        fail(join(path, item.key()), "unknown key (allowed here: " + list + ")");
      }
    }
  }

  double number(const json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, "expected a number, got " + quote_value(value));
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(path, "not a finite number");
    return x;
  }

  // The value of `base_m` / `base_mm` (or `base_rad` / `base_deg`) converted to SI, if present.
  std::optional<double> unit_number(const json& object, const std::string& path,
                                    const std::string& base, bool angle) const {
    const std::string si = base + (angle ? "_rad" : "_m");
    const std::string other = base + (angle ? "_deg" : "_mm");
    const bool has_si = object.contains(si), has_other = object.contains(other);
    if (has_si && has_other) fail(join(path, other), "give either " + si + " or " + other);
    if (has_si) return number(object.at(si), join(path, si));
    if (has_other) {
      const double v = number(object.at(other), join(path, other));
      return angle ? units::deg_to_rad(v) : units::mm_to_m(v);
    }
    return std::nullopt;
  }

  std::vector<double> numbers(const json& value, const std::string& path, std::size_t n) const {
    if (!value.is_array() || value.size() != n) {
      fail(path, "expected a list of " + std::to_string(n) + " numbers, got " + quote_value(value));
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) {
      out.push_back(number(value[i], path + "[" + std::to_string(i) + "]"));
    }
    return out;
  }

  Eigen::Isometry3d transform(const json& value, const std::string& path) const {
    require_object(value, path);
    allow_keys(value, path, {"xyz_m", "xyz_mm", "rpy_rad", "rpy_deg", "rotation"});
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    const bool m = value.contains("xyz_m"), mm = value.contains("xyz_mm");
    if (m && mm) fail(join(path, "xyz_mm"), "give either xyz_m or xyz_mm");
    if (m || mm) {
      const std::string key = m ? "xyz_m" : "xyz_mm";
      const std::vector<double> xyz = numbers(value.at(key), join(path, key), 3);
      for (int i = 0; i < 3; ++i) t.translation()(i) = m ? xyz[i] : units::mm_to_m(xyz[i]);
    }
    const int n_rotations = static_cast<int>(value.contains("rpy_rad")) +
                            static_cast<int>(value.contains("rpy_deg")) +
                            static_cast<int>(value.contains("rotation"));
    if (n_rotations > 1) fail(path, "give one of rpy_rad, rpy_deg or rotation");
    for (const char* key : {"rpy_rad", "rpy_deg"}) {
      if (!value.contains(key)) continue;
      std::vector<double> rpy = numbers(value.at(key), join(path, key), 3);
      if (std::string(key) == "rpy_deg") {
        for (double& a : rpy) a = units::deg_to_rad(a);
      }
      t.linear() = kinematics::rotation_from_rpy(rpy[0], rpy[1], rpy[2]);
    }
    if (value.contains("rotation")) {
      const std::string rpath = join(path, "rotation");
      const json& rows = value.at("rotation");
      if (!rows.is_array() || rows.size() != 3) fail(rpath, "expected 3 rows of 3 numbers");
      Eigen::Matrix3d r;
      for (std::size_t i = 0; i < 3; ++i) {
        const std::vector<double> row = numbers(rows[i], rpath + "[" + std::to_string(i) + "]", 3);
        for (std::size_t j = 0; j < 3; ++j) {
          r(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = row[j];
        }
      }
      const double error = kinematics::rotation_error(r);
      if (!(error <= 1e-6)) {
        std::ostringstream msg;
        msg << "not a rotation matrix (max |R^T R - I| = " << error << ", det = " << r.determinant()
            << ")";
        fail(rpath, msg.str());
      }
      t.linear() = r;
    }
    return t;
  }

  DhRow dh_row(const json& value, const std::string& path) const {
    require_object(value, path);
    allow_keys(value, path,
               {"a_m", "a_mm", "alpha_rad", "alpha_deg", "d_m", "d_mm", "theta_offset_rad",
                "theta_offset_deg", "joint"});
    DhRow row;
    if (value.contains("joint")) {
      const json& joint = value.at("joint");
      if (joint != "revolute" && joint != "prismatic") {
        fail(join(path, "joint"), "expected \"revolute\" or \"prismatic\", got " +
                                      quote_value(joint));
      }
      if (joint == "prismatic") row.type = kinematics::JointType::kPrismatic;
    }
    const auto required = [&](const std::string& base, bool angle) {
      const std::optional<double> v = unit_number(value, path, base, angle);
      if (!v) {
        fail(path,
             "missing " + base + (angle ? "_rad or " + base + "_deg" : "_m or " + base + "_mm"));
      }
      return *v;
    };
    row.a_m = required("a", false);
    row.alpha_rad = required("alpha", true);
    row.d_m = required("d", false);
    row.theta_offset_rad = unit_number(value, path, "theta_offset", true).value_or(0.0);
    return row;
  }

  // Limits per row; a prismatic row's are metres under either key (degrees do not apply).
  std::vector<JointLimits> limits(const json& object, const std::vector<DhRow>& rows) const {
    const std::size_t n = rows.size();
    const bool rad = object.contains("joint_limits_rad"), deg = object.contains("joint_limits_deg");
    if (rad && deg) fail("joint_limits_deg", "give either joint_limits_rad or joint_limits_deg");
    if (!rad && !deg) return std::vector<JointLimits>(n);
    const std::string key = rad ? "joint_limits_rad" : "joint_limits_deg";
    const json& list = object.at(key);
    if (!list.is_array() || list.size() != n) {
      fail(key, "expected " + std::to_string(n) + " [lower, upper] pairs, one per DH row");
    }
    std::vector<JointLimits> out;
    for (std::size_t i = 0; i < n; ++i) {
      const std::string path = key + "[" + std::to_string(i) + "]";
      const std::vector<double> pair = numbers(list[i], path, 2);
      JointLimits l{pair[0], pair[1]};
      if (deg && !rows[i].prismatic()) l = {units::deg_to_rad(pair[0]), units::deg_to_rad(pair[1])};
      if (!(l.lower_rad < l.upper_rad)) fail(path, "lower limit must be below upper limit");
      out.push_back(l);
    }
    return out;
  }

 private:
  const detail::RobotDocument& doc_;
  std::string source_;
};

// A declared "family" must be the one the chain has.
void check_family(const RobotReader& r, const json& root, const kinematics::SerialChain& chain) {
  if (!root.contains("family")) return;
  const json& family = root.at("family");
  if (!family.is_string() || (family != "ur" && family != "lwr" && family != "generic")) {
    r.fail("family", "expected \"ur\", \"lwr\" or \"generic\", got " + quote_value(family));
  }
  if (family.get<std::string>() != kinematics::to_string(chain.family())) {
    r.fail("family", "declared " + quote_value(family) + " but the DH table has the structure of " +
                         kinematics::to_string(chain.family()) +
                         " (see the analytic IK headers for the required twists and offsets)");
  }
}

std::string string_value(const RobotReader& r, const json& root, const std::string& key) {
  if (!root.at(key).is_string() || root.at(key).get<std::string>().empty()) {
    r.fail(key, "expected a non-empty string");
  }
  return root.at(key).get<std::string>();
}

// The refusal of links given for a robot that is `what`, not a URDF.
std::string not_a_urdf(const UrdfChainOptions& links, const std::string& what) {
  const std::string link = !links.tip_link.empty() ? "tip link '" + links.tip_link + "'"
                                                   : "base link '" + links.base_link + "'";
  return link + " given, but the robot is " + what +
         ": tip and base links name links of a URDF (a .urdf file, or a robot file with \"urdf\")";
}

// A robot file that names a URDF: its chain from base_link to tip_link, with the file's tool
// (in the tip link's frame) and base (the base link's frame in the robot frame) on top.
kinematics::SerialChain urdf_chain(const RobotReader& r, const json& root,
                                   const std::string& source, const UrdfChainOptions& given) {
  for (const char* key : {"dh", "joint_limits_rad", "joint_limits_deg"}) {
    if (root.contains(key)) r.fail(key, "give either \"urdf\" or a DH table, not both");
  }
  std::filesystem::path urdf = string_value(r, root, "urdf");
  if (urdf.is_relative()) urdf = std::filesystem::path(source).parent_path() / urdf;
  UrdfChainOptions options = given;
  // A link given besides the file's must be the file's: two names for one robot is a mistake.
  const auto link = [&](const char* key, std::string& value) {
    if (!root.contains(key)) return;
    const std::string in_file = string_value(r, root, key);
    if (!value.empty() && value != in_file && !given.defaults_only) {
      r.fail(key, "'" + in_file + "' here, '" + value + "' given besides: name one " + key);
    }
    value = in_file;
  };
  link("base_link", options.base_link);
  link("tip_link", options.tip_link);
  kinematics::SerialChain chain = read_urdf_robot(urdf.string(), options);
  if (root.contains("tool")) {
    chain = chain.with_tool(chain.T_flange_tcp() * r.transform(root.at("tool"), "tool"));
  }
  if (root.contains("base")) {
    chain = chain.with_base(r.transform(root.at("base"), "base") * chain.T_base_dh0());
  }
  return chain;
}

kinematics::SerialChain build_chain(const detail::RobotDocument& doc, const std::string& source,
                                    const UrdfChainOptions& links) {
  const RobotReader r(doc, source);
  const json& root = doc.root;
  if (root.is_null()) r.fail("", "empty robot file (expected a DH table under \"dh\")");
  r.require_object(root, "");
  r.allow_keys(root, "",
               {"format", "name", "family", "dh", "joint_limits_rad", "joint_limits_deg", "tool",
                "base", "urdf", "base_link", "tip_link"});
  if (root.contains("urdf")) {
    kinematics::SerialChain chain = urdf_chain(r, root, source, links);
    if (root.contains("name")) chain = chain.with_name(string_value(r, root, "name"));
    check_family(r, root, chain);
    return chain;
  }
  for (const char* key : {"base_link", "tip_link"}) {
    if (root.contains(key)) r.fail(key, "goes with \"urdf\"");
  }
  if ((!links.base_link.empty() || !links.tip_link.empty()) && !links.defaults_only) {
    r.fail("", not_a_urdf(links, "a DH table"));
  }
  if (root.contains("format") && root.at("format") != "vrreg-robot") {
    r.fail("format", "expected \"vrreg-robot\", got " + quote_value(root.at("format")));
  }
  std::string name = std::filesystem::path(source).stem().string();
  if (root.contains("name")) {
    if (!root.at("name").is_string() || root.at("name").get<std::string>().empty()) {
      r.fail("name", "expected a non-empty string");
    }
    name = root.at("name").get<std::string>();
  }
  if (!root.contains("dh")) r.fail("", "missing \"dh\": the DH table, one row per joint");
  const json& dh = root.at("dh");
  if (!dh.is_array() || dh.empty() ||
      dh.size() > static_cast<std::size_t>(kinematics::kMaxJoints)) {
    r.fail("dh", "expected a list of 1 to " + std::to_string(kinematics::kMaxJoints) +
                     " rows like {a_m, alpha_deg, d_m, theta_offset_deg}");
  }
  std::vector<DhRow> rows;
  for (std::size_t i = 0; i < dh.size(); ++i) {
    rows.push_back(r.dh_row(dh[i], "dh[" + std::to_string(i) + "]"));
  }
  std::vector<JointLimits> limits = r.limits(root, rows);
  const Eigen::Isometry3d tool =
      root.contains("tool") ? r.transform(root.at("tool"), "tool") : Eigen::Isometry3d::Identity();
  const Eigen::Isometry3d base =
      root.contains("base") ? r.transform(root.at("base"), "base") : Eigen::Isometry3d::Identity();
  try {
    kinematics::SerialChain chain(name, std::move(rows), std::move(limits), base, tool);
    check_family(r, root, chain);
    return chain;
  } catch (const FileError&) {
    throw;
  } catch (const InputError& e) {
    throw FileError(source, 0, e.what());
  }
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

kinematics::SerialChain parse_robot_file(const std::string& text, const std::string& source,
                                         RobotFileSyntax syntax, const UrdfChainOptions& links) {
  if (syntax == RobotFileSyntax::kAuto) {
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    syntax = first != std::string::npos && text[first] == '{' ? RobotFileSyntax::kJson
                                                              : RobotFileSyntax::kYaml;
  }
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw FileError(source, 0, "empty robot file (expected a DH table under \"dh\")");
  }
  const detail::RobotDocument doc = syntax == RobotFileSyntax::kJson
                                        ? detail::parse_robot_json(text, source)
                                        : detail::parse_robot_yaml(text, source);
  return build_chain(doc, source, links);
}

kinematics::SerialChain read_robot_file(const std::string& path, const UrdfChainOptions& links) {
  const std::string text = read_input_file(path);
  std::string lower = path;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (ends_with(lower, ".urdf") || (first != std::string::npos && text[first] == '<')) {
    return parse_urdf_robot(text, path, links);
  }
  RobotFileSyntax syntax = RobotFileSyntax::kAuto;
  if (ends_with(lower, ".json")) syntax = RobotFileSyntax::kJson;
  if (ends_with(lower, ".yaml") || ends_with(lower, ".yml")) syntax = RobotFileSyntax::kYaml;
  return parse_robot_file(text, path, syntax, links);
}

kinematics::SerialChain load_robot(const std::string& name_or_path, const UrdfChainOptions& links) {
  if (std::optional<kinematics::SerialChain> builtin = kinematics::robot_by_name(name_or_path)) {
    VRREG_THROW_UNLESS((links.base_link.empty() && links.tip_link.empty()) || links.defaults_only,
                       not_a_urdf(links, "the built-in " + builtin->name()));
    return *std::move(builtin);
  }
  // Anything by that name (a FIFO, a directory) is read as the file it was meant to be, and
  // refused as what it is.
  std::error_code ec;
  if (!std::filesystem::exists(name_or_path, ec)) {
    std::string names;
    for (const std::string& n : kinematics::builtin_robot_names()) {
      names += (names.empty() ? "" : ", ") + n;
    }
    VRREG_THROW_UNLESS(false, "unknown robot '" << name_or_path << "': not one of " << names
                                                << ", and no robot file by that name");
  }
  return read_robot_file(name_or_path, links);
}

}  // namespace vrreg::io
