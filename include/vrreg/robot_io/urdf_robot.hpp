// SPDX-License-Identifier: Apache-2.0
#pragma once
// Robots from URDF (urdfdom): the chain of joints from a base link to a tip link, as the DH chain
// every kinematics function works on (kinematics/joint_chain.hpp). Revolute, continuous (as
// revolute within +-360 deg) and prismatic joints move; fixed joints are folded into the next
// joint's origin or into the tool; floating and planar joints on the chain are errors.
// A mimic joint (<mimic joint="S" multiplier="m" offset="o"/>) moves as q = m q_S + o: the
// chain's joint variables are its joints that mimic none plus each S that joints on the chain
// mimic, also from off the chain (a side branch: S gives its variable, not its transform), at the
// place of its first follower (SerialChain::couplings). A mimic of a mimic, a cycle, a missing or
// fixed S, and a zero or non-finite multiplier are errors naming the file and the joint.
#include <string>

#include "vrreg/kinematics/serial_chain.hpp"

namespace vrreg::io {

/// Which part of the URDF's tree is the chain.
struct UrdfChainOptions {
  /// Link whose frame poses are given in; empty: the tree's root. It may hang off the chain by
  /// fixed joints (a ROS-Industrial "base" frame beside "base_link").
  std::string base_link{};
  /// Link the TCP is on; empty: the leaf reached through the most moving joints (an error when
  /// several are).
  std::string tip_link{};
  /// The links are defaults (e.g. those a saved model's robot was taken between): a robot file
  /// that names its own links keeps them, and a robot that is no URDF ignores them.
  bool defaults_only = false;
};

/// Reads the URDF file at `path`; throws FileError naming it.
kinematics::SerialChain read_urdf_robot(const std::string& path,
                                        const UrdfChainOptions& options = {});

/// Parses URDF `xml`; `source` names it in messages. Throws FileError naming `source`.
kinematics::SerialChain parse_urdf_robot(const std::string& xml, const std::string& source,
                                         const UrdfChainOptions& options = {});

}  // namespace vrreg::io
