// SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the parts CSV reader (vrreg plan --parts).
#include <sstream>

#include "fuzz_support.hpp"
#include "vrreg/io/parts_csv.hpp"

namespace vrreg::fuzz {

int parts_csv(const std::uint8_t* data, std::size_t size) {
  std::vector<io::PartRecord> parts;
  if (!reads_or_refuses("parts CSV", [&] {
        std::istringstream in(as_text(data, size));
        parts = io::parse_parts_csv(in, "fuzz-parts.csv");
      })) {
    return 0;
  }
  require(!parts.empty(), "parts CSV: accepted a file without part points");
  for (const io::PartRecord& p : parts) {
    require(!p.point.empty() && p.robot_m.allFinite(), "parts CSV: accepted a bad record");
  }
  return 0;
}

}  // namespace vrreg::fuzz

VRREG_FUZZ_ENTRY(vrreg::fuzz::parts_csv)
