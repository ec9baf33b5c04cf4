// SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the URDF robot reader (src/robot_io/urdf_robot.cpp, urdfdom underneath), with the
// default chain and with a named base and tip link.
#include "fuzz_support.hpp"
#include "vrreg/robot_io/urdf_robot.hpp"

namespace vrreg::fuzz {

int urdf(const std::uint8_t* data, std::size_t size) {
  const std::string text = as_text(data, size);
  reads_or_refuses("URDF", [&] { (void)io::parse_urdf_robot(text, "fuzz.urdf"); });
  reads_or_refuses("URDF", [&] {
    (void)io::parse_urdf_robot(text, "fuzz.urdf", {"base", "tool0"});
  });
  return 0;
}

}  // namespace vrreg::fuzz

VRREG_FUZZ_ENTRY(vrreg::fuzz::urdf)
