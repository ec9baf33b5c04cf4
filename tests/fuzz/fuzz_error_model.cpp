// SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the error-model file reader (src/robot_io); an accepted model must write and
// read back.
#include "fuzz_support.hpp"
#include "vrreg/robot_io/error_model_file.hpp"

namespace vrreg::fuzz {

int error_model(const std::uint8_t* data, std::size_t size) {
  static const simulation::Testbed testbed = simulation::ur5_testbed();
  simulation::TestbedErrorModel model;
  if (!reads_or_refuses("error model", [&] {
        model = io::parse_error_model(as_text(data, size), "fuzz-errors", testbed);
      })) {
    return 0;
  }
  std::string written;
  try {
    written = io::format_error_model(model, testbed.name);
  } catch (const std::exception& e) {
    throw Finding(std::string("error model: an accepted model cannot be written: ") + e.what());
  }
  require(reads_or_refuses("error model (written back)",
                           [&] { (void)io::parse_error_model(written, "written", testbed); }),
          "error model: the written model does not read back");
  return 0;
}

}  // namespace vrreg::fuzz

VRREG_FUZZ_ENTRY(vrreg::fuzz::error_model)
