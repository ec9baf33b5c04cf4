// SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the correction service's HTTP/JSON body parser (vrreg serve --http).
#include <cmath>

#include "fuzz_support.hpp"
#include "serve/http_api.hpp"

namespace vrreg::fuzz {

int serve_http(const std::uint8_t* data, std::size_t size) {
  const std::string text = as_text(data, size);
  std::variant<serve::HttpCorrectRequest, serve::PointAnswer> parsed;
  try {
    parsed = serve::parse_http_correct(text, 64);
  } catch (const std::exception& e) {
    throw Finding(std::string("HTTP body: the parser threw: ") + e.what());
  }
  if (const auto* r = std::get_if<serve::HttpCorrectRequest>(&parsed)) {
    require(!r->points.empty() && r->points.size() <= 64, "HTTP body: a batch beyond its bound");
    require(r->batch || r->points.size() == 1, "HTTP body: a single request with several points");
    for (const serve::PointRequest& p : r->points) {
      require(p.sensor_mm.allFinite() && p.sensor_mm.cwiseAbs().maxCoeff() <= 1e9,
              "HTTP body: accepted a coordinate that is not finite or beyond 1e9 mm");
      for (const double q : p.joints_rad) require(std::isfinite(q), "HTTP body: joint not finite");
    }
  } else {
    const serve::PointAnswer& a = std::get<serve::PointAnswer>(parsed);
    require(a.code != serve::ReplyCode::kOk && !a.reason.empty(), "HTTP body: a refusal without a reason");
    const std::string json = serve::answer_json(a, nullptr);
    require(json.find('\n') == std::string::npos, "HTTP body: a refusal that is not one line");
  }
  return 0;
}

}  // namespace vrreg::fuzz

VRREG_FUZZ_ENTRY(vrreg::fuzz::serve_http)
