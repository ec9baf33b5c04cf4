// SPDX-License-Identifier: Apache-2.0
#pragma once
// Robot files: a serial chain (calibrated DH table, joint limits, tool and base offsets) in JSON
// or YAML. Units are part of every key (_m / _mm, _rad / _deg); unknown keys are errors.
//
//   {"format": "vrreg-robot",                  // optional
//    "name": "ur5-cell-3",                     // optional, default: the file name
//    "family": "ur",                           // optional: ur | lwr | generic, checked
//    "dh": [{"a_m": 0, "alpha_deg": 90, "d_m": 0.089159, "theta_offset_deg": 0}, ...],
//    "joint_limits_deg": [[-360, 360], ...],   // optional (or _rad), default +-360 deg
//    "tool": {"xyz_mm": [0, 0, 45.5], "rpy_deg": [0, 0, 0]},  // optional flange -> TCP
//    "base": {"xyz_m": [0, 0, 0], "rotation": [[1,0,0],[0,1,0],[0,0,1]]}}  // optional
#include <string>

#include "vrreg/kinematics/serial_chain.hpp"
#include "vrreg/robot_io/urdf_robot.hpp"

namespace vrreg::io {

/// Syntax of a robot file.
enum class RobotFileSyntax { kAuto, kJson, kYaml };

//
// Or a URDF's chain: {"urdf": "ur5.urdf", "base_link": "base", "tip_link": "tool0"} (the path
// relative to the robot file; name, family, tool and base as above, on top of the URDF's).

/// Reads the robot file at `path`: URDF if it ends in .urdf or starts with '<' (its chain from
/// `links` base to tip, by default the root to the deepest leaf, urdf_robot.hpp), YAML if it ends
/// in .yaml/.yml, JSON if .json, else sniffed. Links apply to a URDF or a robot file that names
/// one (where they must agree with the file's base_link and tip_link); given for a DH table, they
/// are an error. Throws FileError naming the file (and the line, where the syntax gives one).
kinematics::SerialChain read_robot_file(const std::string& path,
                                        const UrdfChainOptions& links = {});

/// Parses robot-file `text`; `source` names it in messages and is the default robot name.
kinematics::SerialChain parse_robot_file(const std::string& text, const std::string& source,
                                         RobotFileSyntax syntax = RobotFileSyntax::kAuto,
                                         const UrdfChainOptions& links = {});

/// A built-in robot (ur3, ur5, ur10, ur5e, lwr4) by name, else the robot file at that path (with
/// `links` as in read_robot_file). Throws InputError for an unknown name that is not a file or
/// for links given with a built-in name, FileError for a bad file.
kinematics::SerialChain load_robot(const std::string& name_or_path,
                                   const UrdfChainOptions& links = {});

}  // namespace vrreg::io
