// SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the correction service's line-protocol request parser (vrreg serve --listen).
#include <cmath>

#include "fuzz_support.hpp"
#include "serve/line_protocol.hpp"

namespace vrreg::fuzz {

int serve_line(const std::uint8_t* data, std::size_t size) {
  const std::string text = as_text(data, size);
  serve::LineRequest request;
  try {
    request = serve::parse_line_request(text);
  } catch (const std::exception& e) {
    throw Finding(std::string("line protocol: the parser threw: ") + e.what());
  }
  if (const auto* p = std::get_if<serve::PointRequest>(&request)) {
    require(p->sensor_mm.allFinite() && p->sensor_mm.cwiseAbs().maxCoeff() <= 1e9,
            "line protocol: accepted a coordinate that is not finite or beyond 1e9 mm");
    require(!p->model.empty() && p->model.size() <= 64, "line protocol: accepted a bad model name");
    require(p->joints_rad.size() <= 16, "line protocol: accepted more than 16 joints");
    for (const double q : p->joints_rad) require(std::isfinite(q), "line protocol: joint not finite");
    require(p->from_rad.empty() || p->from_rad.size() == p->joints_rad.size(),
            "line protocol: accepted from without as many joints");
    require(p->approach_sign.size() <= 16 &&
                (p->joints_rad.empty() || p->approach_sign.empty() ||
                 p->approach_sign.size() == p->joints_rad.size()),
            "line protocol: accepted approach signs that do not match the joints");
    for (const double s : p->approach_sign) {
      require(s == -1.0 || s == 0.0 || s == 1.0, "line protocol: an approach sign not -1, 0, 1");
    }
    serve::PointAnswer a;
    a.robot_mm = p->sensor_mm;
    const std::string reply = serve::format_line_reply(a);
    require(reply.front() == '(' && reply.find('\n') == reply.size() - 1,
            "line protocol: a reply that is not one parenthesised line");
  } else if (const auto* bad = std::get_if<serve::BadRequest>(&request)) {
    require(!bad->reason.empty() && bad->reason.find('\n') == std::string::npos,
            "line protocol: a refusal without a one-line reason");
  }
  return 0;
}

}  // namespace vrreg::fuzz

VRREG_FUZZ_ENTRY(vrreg::fuzz::serve_line)
