// SPDX-License-Identifier: Apache-2.0
#pragma once
// The HTTP/JSON requests and replies of the service (docs/serve.md), apart from the transport:
//   POST /v1/correct  {"model": NAME, "sensor_mm": [x,y,z], "joints_rad": [...], "config": n,
//                      "extrapolate": bool}                      -> one answer
//                     {"model": NAME, "points": [{"sensor_mm": [...], ...}, ...], "extrapolate": bool}
//                                                                -> {"results": [answer, ...]}
//   GET  /v1/health   which models answer (file, sha256, file time, load time, method)
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "request.hpp"
#include "served_model.hpp"

namespace vrreg::serve {

/// A parsed correction body: one point or a batch.
struct HttpCorrectRequest {
  bool batch = false;
  std::vector<PointRequest> points;
};

/// Parses a POST /v1/correct body; on failure returns the refusal (code kMalformed or kLimit).
/// Never throws.
std::variant<HttpCorrectRequest, PointAnswer> parse_http_correct(std::string_view body,
                                                                std::size_t max_batch);

/// The HTTP status of a reply code (200, 400, 401, 404, 413, 422, 500).
int http_status(ReplyCode code);

/// One answer as a JSON object (mm; numbers in the shortest form that reads back exactly).
std::string answer_json(const PointAnswer& answer, const ModelIdentity* model);

/// A batch's answers as {"model":..., "sha256":..., "results": [...]}.
std::string batch_json(const std::vector<PointAnswer>& answers, const ModelIdentity& model);

struct ServiceStats;

/// The health document: every served model and the last reload error of each (null when none),
/// and the service's counters (corrections, refusals, refused requests by kind, connections).
std::string health_json(const std::vector<std::shared_ptr<const ServedModel>>& models,
                        const std::vector<std::string>& reload_errors,
                        const std::string& audit_error, const ServiceStats& stats);

}  // namespace vrreg::serve
