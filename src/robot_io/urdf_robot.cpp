// SPDX-License-Identifier: Apache-2.0
// URDF -> joint list -> DH chain (with couplings for mimic joints). urdfdom parses the XML and
// links the tree (it refuses a missing link, a joint without limits where URDF requires them); it
// reports why through console_bridge, which is captured here so that the error is one line naming
// the file. What urdfdom lets through is refused here: XML nested deeper than TinyXML's recursion
// survives, and a link with two parents (urdfdom keeps the last joint in name order).
#include "vrreg/robot_io/urdf_robot.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <map>
#include <mutex>
#include <set>
#include <string_view>
#include <vector>

#include "vrreg/core/check.hpp"
#include "vrreg/core/file_error.hpp"
#include "vrreg/io/input_file.hpp"
#include "vrreg/kinematics/joint_chain.hpp"

namespace vrreg::io {
namespace {

using kinematics::ChainJoint;
using kinematics::JointType;

// Element nesting a URDF may have (one has about 5: robot, link, visual, geometry, mesh); TinyXML
// overflowed an 8 MB stack between 20 000 and 60 000 levels.
constexpr int kMaxUrdfNesting = 256;

// Keeps urdfdom's last error message instead of printing it.
class CapturingHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) last_error = text;
  }
  std::string last_error;
};

// console_bridge's handler is process-wide: one parse at a time.
std::mutex& parse_mutex() {
  static std::mutex m;
  return m;
}

bool starts_with_at(const std::string& text, std::size_t i, std::string_view prefix) {
  return text.compare(i, prefix.size(), prefix) == 0;
}

bool starts_with_xml_declaration(const std::string& text, std::size_t i) {
  if (text.size() - i < 5 || text.compare(i, 2, "<?") != 0) return false;
  for (std::size_t k = 0; k < 3; ++k) {
    if (std::tolower(static_cast<unsigned char>(text[i + 2 + k])) != "xml"[k]) return false;
  }
  return true;
}

// The deepest element nesting TinyXML would recurse into, read as TinyXML reads the markup
// (an element starts at '<' and a letter, '_' or a non-ASCII byte; attribute values are quoted
// only right after '='; comments, CDATA, declarations and other <! or <? run to their end).
// Never below TinyXML's depth: what it would misread the other way is refused instead.
void check_nesting(const std::string& text, const std::string& source) {
  const auto fail = [&](const std::string& why) { throw FileError(source, 0, why); };
  const std::size_t n = text.size();
  int depth = 0;
  std::size_t i = 0;
  const auto skip_past = [&](std::string_view end) {
    const std::size_t at = text.find(end, i);
    i = at == std::string::npos ? n : at + end.size();
  };
  while ((i = text.find('<', i)) != std::string::npos) {
    if (starts_with_at(text, i, "<!--")) {
      i += 4;
      skip_past("-->");
    } else if (starts_with_at(text, i, "<![CDATA[")) {
      i += 9;
      skip_past("]]>");
    } else if (starts_with_at(text, i, "</")) {
      depth = std::max(depth - 1, 0);
      skip_past(">");
    } else if (i + 1 < n &&
               (std::isalpha(static_cast<unsigned char>(text[i + 1])) != 0 || text[i + 1] == '_' ||
                static_cast<unsigned char>(text[i + 1]) >= 127)) {
      // A start tag: to its '>' outside quoted attribute values.
      bool after_equals = false;
      char previous = '<';
      for (++i; i < n && text[i] != '>'; ++i) {
        const char c = text[i];
        if ((c == '"' || c == '\'') && after_equals) {
          const std::size_t close = text.find(c, i + 1);
          i = close == std::string::npos ? n - 1 : close;
          after_equals = false;
          previous = c;
          continue;
        }
        if (c == '=') {
          after_equals = true;
        } else if (c != ' ' && c != '\t' && c != '\r' && c != '\n') {
          after_equals = false;
        }
        previous = c;
      }
      if (i >= n) break;
      ++i;
      if (previous != '/' && ++depth > kMaxUrdfNesting) {
        fail("XML elements nest deeper than " + std::to_string(kMaxUrdfNesting) +
             " levels; a URDF needs a few");
      }
    } else {
      // A declaration inside an element could hide an end tag in a quoted value that TinyXML
      // skips; no URDF has one there.
      if (depth > 0 && starts_with_xml_declaration(text, i)) {
        fail("an <?xml ...?> declaration inside an element");
      }
      skip_past(">");
    }
  }
}

urdf::ModelInterfaceSharedPtr parse_model(const std::string& xml, const std::string& source) {
  // urdfdom's TinyXML recurses once per nesting level, in parsing and in freeing: a deep
  // enough file overflows the stack.
  check_nesting(xml, source);
  const std::lock_guard<std::mutex> lock(parse_mutex());
  CapturingHandler handler;
  console_bridge::useOutputHandler(&handler);
  urdf::ModelInterfaceSharedPtr model;
  std::string thrown;
  try {
    model = urdf::parseURDF(xml);
  } catch (const std::exception& e) {
    thrown = e.what();
  }
  console_bridge::restorePreviousOutputHandler();
  if (!model) {
    std::string why = !thrown.empty() ? thrown : handler.last_error;
    for (char& c : why) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    throw FileError(source, 0,
                    "not a valid URDF (urdfdom: " + (why.empty() ? "no reason given" : why) + ")");
  }
  return model;
}

Eigen::Isometry3d isometry(const urdf::Pose& pose) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  const urdf::Rotation& r = pose.rotation;
  t.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  t.translation() << pose.position.x, pose.position.y, pose.position.z;
  return t;
}

class ChainBuilder {
 public:
  ChainBuilder(const urdf::ModelInterface& model, std::string source)
      : model_(model), source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& message) const { throw FileError(source_, 0, message); }

  urdf::LinkConstSharedPtr link(const std::string& name, const char* role) const {
    urdf::LinkConstSharedPtr l = model_.getLink(name);
    if (!l) fail(std::string(role) + " link '" + name + "' is not in the URDF");
    return l;
  }

  // Moving joints from the root down to `link`.
  static int depth(urdf::LinkConstSharedPtr link) {
    int n = 0;
    for (; link && link->parent_joint; link = link->getParent()) {
      if (link->parent_joint->type != urdf::Joint::FIXED) ++n;
    }
    return n;
  }

  urdf::LinkConstSharedPtr default_tip() const {
    std::vector<urdf::LinkSharedPtr> links;
    model_.getLinks(links);
    int best = -1;
    std::vector<std::string> tied;
    for (const urdf::LinkSharedPtr& l : links) {
      if (!l->child_joints.empty()) continue;
      const int d = depth(l);
      if (d > best) {
        best = d;
        tied.assign(1, l->name);
      } else if (d == best) {
        tied.push_back(l->name);
      }
    }
    if (tied.size() != 1) {
      std::string names;
      for (const std::string& n : tied) names += (names.empty() ? "" : ", ") + n;
      fail("several leaf links end " + std::to_string(best) + " moving joints from the root (" +
           names +
           "): name the tip link (--tip-link NAME on the command line, or tip_link in a "
           "robot YAML file that names this URDF)");
    }
    return model_.getLink(tied.front());
  }

  ChainJoint moving_joint(const urdf::Joint& j, const Eigen::Isometry3d& origin) const {
    ChainJoint c;
    c.name = j.name;
    c.T_parent_joint = origin;
    c.axis = Eigen::Vector3d(j.axis.x, j.axis.y, j.axis.z);
    c.type = joint_type(j);
    c.limits = joint_limits(j);
    return c;
  }

  static JointType joint_type(const urdf::Joint& j) {
    return j.type == urdf::Joint::PRISMATIC ? JointType::kPrismatic : JointType::kRevolute;
  }

  // A continuous joint turns within the default +-360 deg: every angle has a turn inside.
  kinematics::JointLimits joint_limits(const urdf::Joint& j) const {
    if (j.type == urdf::Joint::CONTINUOUS) return {};
    if (!j.limits) fail("joint '" + j.name + "' has no <limit>");
    if (!(j.limits->lower < j.limits->upper)) {
      fail("joint '" + j.name + "': lower limit " + std::to_string(j.limits->lower) +
           " is not below upper limit " + std::to_string(j.limits->upper));
    }
    return {j.limits->lower, j.limits->upper};
  }

  // The joint `j` mimics (<mimic joint="S" multiplier="m" offset="o"/>: q_j = m q_S + o), checked:
  // S exists, moves, and is no mimic itself (one level: what a controller drives).
  const urdf::Joint& mimic_source(const urdf::Joint& j) const {
    const urdf::JointMimic& m = *j.mimic;
    const urdf::JointConstSharedPtr source = model_.getJoint(m.joint_name);
    if (!source) {
      fail("joint '" + j.name + "' mimics joint '" + m.joint_name + "', which is not in the URDF");
    }
    if (!std::isfinite(m.multiplier) || m.multiplier == 0.0 || !std::isfinite(m.offset)) {
      fail("joint '" + j.name + "' mimics '" + m.joint_name + "' with multiplier " +
           std::to_string(m.multiplier) + " and offset " + std::to_string(m.offset) +
           ": the multiplier must be finite and non-zero, the offset finite");
    }
    if (source->mimic) {
      // Follow the mimics from j: back at j is a cycle, else a mimic of a mimic.
      std::string path = j.name + " -> " + source->name;
      std::set<std::string> seen{j.name, source->name};
      for (urdf::JointConstSharedPtr k = source; k && k->mimic;) {
        k = model_.getJoint(k->mimic->joint_name);
        if (!k) break;
        path += " -> " + k->name;
        if (!seen.insert(k->name).second) {
          fail("joint '" + j.name + "': its mimic tags form a cycle (" + path + ")");
        }
      }
      fail("joint '" + j.name + "' mimics '" + source->name + "', which mimics '" +
           source->mimic->joint_name + "': a mimic joint must follow a joint that is no mimic");
    }
    if (source->type != urdf::Joint::REVOLUTE && source->type != urdf::Joint::CONTINUOUS &&
        source->type != urdf::Joint::PRISMATIC) {
      fail("joint '" + j.name + "' mimics '" + source->name +
           "', which is not a revolute, continuous or prismatic joint");
    }
    return *source;
  }

  // The joint variables of the chain `joints` (urdf joints `on_chain`, same order): each chain
  // joint that mimics none is its own variable at its place; a joint that others on the chain
  // mimic from off the chain (a side branch) is a variable at the place of its first follower.
  kinematics::JointCouplings couplings(const std::vector<const urdf::Joint*>& on_chain) const {
    struct Variable {
      std::size_t place;
      kinematics::JointVariable variable;
    };
    std::map<std::string, Variable> by_name;
    const auto variable = [&](const urdf::Joint& j) {
      return kinematics::JointVariable{j.name, joint_type(j), joint_limits(j)};
    };
    for (std::size_t r = 0; r < on_chain.size(); ++r) {
      const urdf::Joint& j = *on_chain[r];
      if (j.mimic) {
        const urdf::Joint& source = mimic_source(j);
        by_name.try_emplace(source.name, Variable{r, variable(source)});
      } else {
        by_name.insert_or_assign(j.name, Variable{r, variable(j)});
      }
    }
    std::vector<const Variable*> order;
    for (const auto& [name, v] : by_name) order.push_back(&v);
    std::sort(order.begin(), order.end(),
              [](const Variable* a, const Variable* b) { return a->place < b->place; });
    kinematics::JointCouplings out;
    std::map<std::string, int> index;
    for (const Variable* v : order) {
      index[v->variable.name] = static_cast<int>(out.variables.size());
      out.variables.push_back(v->variable);
    }
    for (const urdf::Joint* j : on_chain) {
      if (j->mimic) {
        out.rows.push_back(
            {index.at(j->mimic->joint_name), j->mimic->multiplier, j->mimic->offset});
      } else {
        out.rows.push_back({index.at(j->name), 1.0, 0.0});
      }
    }
    return out;
  }

  // urdfdom links a child to the last of its parent joints (in name order) and drops the others.
  void check_single_parents() const {
    std::map<std::string, std::string> parent_joint_of;
    for (const auto& [name, joint] : model_.joints_) {
      const auto [it, first] = parent_joint_of.emplace(joint->child_link_name, name);
      if (!first) {
        fail("link '" + joint->child_link_name + "' is the child of two joints ('" + it->second +
             "' and '" + name + "'): a link has one parent in a URDF tree");
      }
    }
  }

  kinematics::SerialChain build(const UrdfChainOptions& options) const {
    check_single_parents();
    const urdf::LinkConstSharedPtr root = model_.getRoot();
    if (!root) fail("the URDF has no root link");
    const urdf::LinkConstSharedPtr tip =
        options.tip_link.empty() ? default_tip() : link(options.tip_link, "tip");
    const urdf::LinkConstSharedPtr base =
        options.base_link.empty() ? root : link(options.base_link, "base");
    // The tip's ancestors, tip first.
    std::vector<urdf::LinkConstSharedPtr> up_from_tip;
    std::set<std::string> on_tip_path;
    for (urdf::LinkConstSharedPtr l = tip; l; l = l->getParent()) {
      up_from_tip.push_back(l);
      on_tip_path.insert(l->name);
    }
    // From the base up to the first ancestor of the tip: fixed joints only.
    Eigen::Isometry3d T_common_base = Eigen::Isometry3d::Identity();
    urdf::LinkConstSharedPtr common = base;
    while (on_tip_path.count(common->name) == 0) {
      const urdf::JointConstSharedPtr j = common->parent_joint;
      if (j->type != urdf::Joint::FIXED) {
        fail("base link '" + base->name + "' is not above tip link '" + tip->name +
             "', and the way up from it passes moving joint '" + j->name + "'");
      }
      T_common_base = isometry(j->parent_to_joint_origin_transform) * T_common_base;
      common = common->getParent();
    }
    // Down from the common link to the tip.
    std::vector<ChainJoint> joints;
    std::vector<const urdf::Joint*> on_chain;
    Eigen::Isometry3d pending = T_common_base.inverse(Eigen::Isometry);
    bool below = false;
    for (auto it = up_from_tip.rbegin(); it != up_from_tip.rend(); ++it) {
      if (!below) {
        below = (*it)->name == common->name;
        continue;
      }
      const urdf::Joint& j = *(*it)->parent_joint;
      const Eigen::Isometry3d origin = pending * isometry(j.parent_to_joint_origin_transform);
      switch (j.type) {
        case urdf::Joint::FIXED:
          pending = origin;
          break;
        case urdf::Joint::REVOLUTE:
        case urdf::Joint::CONTINUOUS:
        case urdf::Joint::PRISMATIC:
          joints.push_back(moving_joint(j, origin));
          on_chain.push_back(&j);
          pending = Eigen::Isometry3d::Identity();
          break;
        default:
          fail("joint '" + j.name +
               "' is floating or planar: a chain takes revolute, continuous, prismatic and fixed "
               "joints");
      }
    }
    if (joints.empty()) {
      fail("no moving joint between base link '" + base->name + "' and tip link '" + tip->name +
           "'");
    }
    if (joints.size() > static_cast<std::size_t>(kinematics::kMaxJoints)) {
      fail(std::to_string(joints.size()) + " moving joints between '" + base->name + "' and '" +
           tip->name + "'; at most " + std::to_string(kinematics::kMaxJoints));
    }
    const std::string name = model_.getName().empty() ? "urdf" : model_.getName();
    try {
      kinematics::SerialChain chain = kinematics::chain_from_joints(name, joints, pending);
      const bool mimics = std::any_of(on_chain.begin(), on_chain.end(),
                                      [](const urdf::Joint* j) { return j->mimic != nullptr; });
      if (mimics) chain = chain.with_couplings(couplings(on_chain));
      return chain.with_urdf_links(base->name, tip->name);
    } catch (const FileError&) {
      throw;
    } catch (const InputError& e) {
      fail(e.what());
    }
  }

 private:
  const urdf::ModelInterface& model_;
  std::string source_;
};

}  // namespace

kinematics::SerialChain parse_urdf_robot(const std::string& xml, const std::string& source,
                                         const UrdfChainOptions& options) {
  const urdf::ModelInterfaceSharedPtr model = parse_model(xml, source);
  return ChainBuilder(*model, source).build(options);
}

kinematics::SerialChain read_urdf_robot(const std::string& path, const UrdfChainOptions& options) {
  return parse_urdf_robot(read_input_file(path), path, options);
}

}  // namespace vrreg::io
