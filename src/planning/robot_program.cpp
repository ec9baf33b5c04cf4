// SPDX-License-Identifier: Apache-2.0
#include "vrreg/planning/robot_program.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "vrreg/core/check.hpp"

namespace vrreg::planning {
namespace {

double deg(double rad) { return rad * 180.0 / std::numbers::pi; }

const char* role_name(Role role) { return to_string(role); }

// " visit N" for points read in rounds (the measurement CSV's visit column), else nothing.
std::string visit_text(const ProgramLocation& l) {
  return l.visit >= 0 ? " visit " + std::to_string(l.visit) : std::string();
}

// Labels go into comments and strings: keep them printable, without quotes.
std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    out += (u >= 32 && u < 127 && c != '"' && c != '\\') ? c : '_';
  }
  return out;
}

void check_locations(const std::vector<ProgramLocation>& locations) {
  VRREG_THROW_UNLESS(!locations.empty(), "robot program: the plan has no locations");
  const Eigen::Index n = locations.front().q_rad.size();
  for (const ProgramLocation& l : locations) {
    VRREG_THROW_UNLESS(l.q_rad.size() == n && n > 0 && l.q_rad.allFinite(),
                       "robot program: location '" << l.point << "' has no finite joints");
    VRREG_THROW_UNLESS(!l.via_q_rad || (l.via_q_rad->size() == n && l.via_q_rad->allFinite()),
                       "robot program: the via point of location '" << l.point
                                                                    << "' has no finite joints");
  }
}

std::string urscript(const std::vector<ProgramLocation>& locations, const ProgramOptions& o) {
  VRREG_THROW_UNLESS(locations.front().q_rad.size() == 6,
                     "URScript is for 6-joint UR arms; the plan has "
                         << locations.front().q_rad.size() << " joints (use `export` krl or csv)");
  std::string s;
  s += fmt::format(
      "# {} locations in visiting order; at each: movej, settle {} s, then a blocking\n",
      locations.size(), o.settle_s);
  s += fmt::format(
      "# popup: take {} tracker readings (repeat 0..{}), write one CSV row each, "
      "press Continue.\n",
      o.repeats, o.repeats - 1);
  s += "# Joints in rad, as in the plan CSV. Written by vrreg plan --export urscript.\n";
  s += fmt::format("def {}():\n", o.name);
  const std::size_t n = locations.size();
  for (std::size_t k = 0; k < n; ++k) {
    const ProgramLocation& l = locations[k];
    const std::string label = printable(l.point);
    s += fmt::format("  # {}/{} {} {}{}{}\n", k + 1, n, label, role_name(l.role),
                     l.config.empty() ? "" : " config " + printable(l.config), visit_text(l));
    s += fmt::format("  textmsg(\"vrreg {}/{} {}\")\n", k + 1, n, label);
    if (l.via_q_rad) {
      s += "  # via: every joint arrives from its approach direction\n  movej([";
      for (Eigen::Index j = 0; j < 6; ++j) {
        s += fmt::format("{}{:.12g}", j ? ", " : "", (*l.via_q_rad)(j));
      }
      s += fmt::format("], a={:.6g}, v={:.6g})\n", o.joint_accel_rad_s2, o.joint_speed_rad_s);
    }
    s += "  movej([";
    for (Eigen::Index j = 0; j < 6; ++j) {
      s += fmt::format("{}{:.12g}", j ? ", " : "", l.q_rad(j));
    }
    s += fmt::format("], a={:.6g}, v={:.6g})\n", o.joint_accel_rad_s2, o.joint_speed_rad_s);
    s += fmt::format("  sleep({:.6g})\n", o.settle_s);
    s += fmt::format(
        "  popup(\"{}/{} {}: take {} tracker readings, then Continue\", \"vrreg\", False, False, "
        "blocking=True)\n",
        k + 1, n, label, o.repeats);
  }
  s += "  textmsg(\"vrreg: plan done\")\n";
  s += "end\n";
  s += fmt::format("{}()\n", o.name);
  return s;
}

std::string krl(const std::vector<ProgramLocation>& locations, const ProgramOptions& o) {
  const Eigen::Index joints = locations.front().q_rad.size();
  VRREG_THROW_UNLESS(
      joints == 6 || joints == 7,
      "KRL takes 6 joints (A1-A6) or 7 (LWR 4+: A1 A2 E1 A3 A4 A5 A6); the plan has " << joints);
  // The LWR 4+'s third joint (the redundant one) is the external axis E1 on its controller.
  const std::vector<std::string> axes =
      joints == 7 ? std::vector<std::string>{"A1", "A2", "E1", "A3", "A4", "A5", "A6"}
                  : std::vector<std::string>{"A1", "A2", "A3", "A4", "A5", "A6"};
  std::string s;
  s += "&ACCESS RVP\n";
  s += fmt::format("DEF {}( )\n", o.name);
  s +=
      fmt::format("; {} locations in visiting order; at each: PTP, WAIT {} s, then HALT: take {}\n",
                  locations.size(), o.settle_s, o.repeats);
  s += "; tracker readings, write one CSV row each, press Start. Joints in deg (plan CSV: rad).\n";
  s += "; Written by vrreg plan --export krl.\n";
  s += "  BAS(#INITMOV, 0)\n";
  s += fmt::format("  BAS(#VEL_PTP, {})\n", o.krl_velocity_percent);
  const std::size_t n = locations.size();
  for (std::size_t k = 0; k < n; ++k) {
    const ProgramLocation& l = locations[k];
    s += fmt::format("  ; {}/{} {} {}{}{}\n", k + 1, n, printable(l.point), role_name(l.role),
                     l.config.empty() ? "" : " config " + printable(l.config), visit_text(l));
    if (l.via_q_rad) {
      s += "  ; via: every joint arrives from its approach direction\n  PTP {";
      for (Eigen::Index j = 0; j < joints; ++j) {
        s += fmt::format("{}{} {:.9f}", j ? ", " : "", axes[static_cast<std::size_t>(j)],
                         deg((*l.via_q_rad)(j)));
      }
      s += "}\n";
    }
    s += "  PTP {";
    for (Eigen::Index j = 0; j < joints; ++j) {
      s += fmt::format("{}{} {:.9f}", j ? ", " : "", axes[static_cast<std::size_t>(j)],
                       deg(l.q_rad(j)));
    }
    s += "}\n";
    s += fmt::format("  WAIT SEC {:.6g}\n", o.settle_s);
    s += "  HALT\n";
  }
  s += "END\n";
  return s;
}

std::string joint_csv(const std::vector<ProgramLocation>& locations, const ProgramOptions& o) {
  const Eigen::Index joints = locations.front().q_rad.size();
  std::string s = fmt::format(
      "# vrreg plan --export csv: visit in order, settle {} s, take `repeats` tracker readings\n",
      o.settle_s);
  s += "order,point,role,config";
  for (Eigen::Index j = 0; j < joints; ++j) s += fmt::format(",q{}_rad", j + 1);
  for (Eigen::Index j = 0; j < joints; ++j) s += fmt::format(",q{}_deg", j + 1);
  s += ",repeats";
  const bool visits = std::any_of(locations.begin(), locations.end(),
                                  [](const ProgramLocation& l) { return l.visit >= 0; });
  s += visits ? ",visit\n" : "\n";
  std::size_t order = 0;
  for (std::size_t k = 0; k < locations.size(); ++k) {
    const ProgramLocation& l = locations[k];
    if (l.via_q_rad) {  // moved to, never read: repeats 0
      s += fmt::format("{},{},via,{}", ++order, l.point, l.config);
      for (Eigen::Index j = 0; j < joints; ++j) s += fmt::format(",{:.17g}", (*l.via_q_rad)(j));
      for (Eigen::Index j = 0; j < joints; ++j) {
        s += fmt::format(",{:.12g}", deg((*l.via_q_rad)(j)));
      }
      s += ",0";
      s += visits ? fmt::format(",{}\n", std::max(l.visit, 0)) : "\n";
    }
    s += fmt::format("{},{},{},{}", ++order, l.point, role_name(l.role), l.config);
    for (Eigen::Index j = 0; j < joints; ++j) s += fmt::format(",{:.17g}", l.q_rad(j));
    for (Eigen::Index j = 0; j < joints; ++j) s += fmt::format(",{:.12g}", deg(l.q_rad(j)));
    s += fmt::format(",{}", o.repeats);
    s += visits ? fmt::format(",{}\n", std::max(l.visit, 0)) : "\n";
  }
  return s;
}

}  // namespace

ProgramFormat parse_program_format(const std::string& text) {
  if (text == "urscript") return ProgramFormat::kUrScript;
  if (text == "krl") return ProgramFormat::kKrl;
  if (text == "csv") return ProgramFormat::kJointCsv;
  VRREG_THROW_UNLESS(false, "unknown program format '" << text << "' (urscript, krl or csv)");
  return ProgramFormat::kJointCsv;  // not reached
}

void ProgramOptions::validate() const {
  VRREG_THROW_UNLESS(repeats >= 1 && repeats <= 1000, "repeats must be 1..1000, got " << repeats);
  VRREG_THROW_UNLESS(std::isfinite(settle_s) && settle_s >= 0.0 && settle_s <= 60.0,
                     "settle time must be 0..60 s, got " << settle_s);
  VRREG_THROW_UNLESS(std::isfinite(joint_speed_rad_s) && joint_speed_rad_s > 0.0 &&
                         std::isfinite(joint_accel_rad_s2) && joint_accel_rad_s2 > 0.0,
                     "joint speed and acceleration must be positive");
  VRREG_THROW_UNLESS(krl_velocity_percent >= 1 && krl_velocity_percent <= 100,
                     "KRL velocity must be 1..100 %, got " << krl_velocity_percent);
  bool valid =
      !name.empty() && name.size() <= 24 && std::isalpha(static_cast<unsigned char>(name[0]));
  for (const char c : name)
    valid = valid && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  VRREG_THROW_UNLESS(valid, "program name '" << name
                                             << "': letters, digits, underscores, "
                                                "starting with a letter, at most 24");
}

std::string robot_program(const std::vector<ProgramLocation>& locations, ProgramFormat format,
                          const ProgramOptions& options) {
  options.validate();
  check_locations(locations);
  switch (format) {
    case ProgramFormat::kUrScript:
      return urscript(locations, options);
    case ProgramFormat::kKrl:
      return krl(locations, options);
    case ProgramFormat::kJointCsv:
      return joint_csv(locations, options);
  }
  return {};
}

}  // namespace vrreg::planning
