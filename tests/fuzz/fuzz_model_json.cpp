// SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the model JSON reader; an accepted model must write and read back unchanged.
#include "fuzz_support.hpp"
#include "vrreg/io/model_json.hpp"

namespace vrreg::fuzz {

int model_json(const std::uint8_t* data, std::size_t size) {
  RegistrationModel model;
  if (!reads_or_refuses("model JSON",
                        [&] { model = io::parse_model_json(as_text(data, size), "fuzz.json"); })) {
    return 0;
  }
  std::string written;
  try {
    written = io::format_model_json(model);
  } catch (const std::exception& e) {
    throw Finding(std::string("model JSON: an accepted model cannot be written: ") + e.what());
  }
  RegistrationModel again;
  require(reads_or_refuses("model JSON (written back)",
                           [&] { again = io::parse_model_json(written, "written.json"); }),
          "model JSON: the written model does not read back");
  require(io::format_model_json(again) == written, "model JSON: write/read/write changes the text");
  return 0;
}

}  // namespace vrreg::fuzz

VRREG_FUZZ_ENTRY(vrreg::fuzz::model_json)
