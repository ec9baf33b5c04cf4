// SPDX-License-Identifier: Apache-2.0
#include "request.hpp"

#include <Eigen/Core>
#include <utility>

#include "vrreg/core/measurement.hpp"

namespace vrreg::serve {

const char* to_string(ReplyCode code) {
  switch (code) {
    case ReplyCode::kOk: return "ok";
    case ReplyCode::kMalformed: return "malformed";
    case ReplyCode::kUnknownModel: return "unknown model";
    case ReplyCode::kNotCorrectable: return "not correctable";
    case ReplyCode::kInput: return "missing input";
    case ReplyCode::kUnauthorized: return "unauthorized";
    case ReplyCode::kLimit: return "limit";
    case ReplyCode::kInternal: return "internal error";
    case ReplyCode::kTooFar: return "too far to extrapolate";
  }
  return "internal error";
}

int orientation_numbers(OrientationForm form) {
  switch (form) {
    case OrientationForm::kNone:
      return 0;
    case OrientationForm::kQuaternion:
      return 4;
    case OrientationForm::kRotationVector:
    case OrientationForm::kKukaAbc:
      return 3;
  }
  return 0;
}

std::vector<double> approach_sign_of_move(const std::vector<double>& from_rad,
                                          const std::vector<double>& joints_rad) {
  const auto n = static_cast<Eigen::Index>(joints_rad.size());
  Eigen::VectorXd sign = Eigen::VectorXd::Zero(n);
  update_approach_sign(Eigen::Map<const Eigen::VectorXd>(
                           from_rad.data(), static_cast<Eigen::Index>(from_rad.size())),
                       Eigen::Map<const Eigen::VectorXd>(joints_rad.data(), n), sign);
  return {sign.data(), sign.data() + n};
}

PointAnswer PointAnswer::refusal(ReplyCode code, std::string reason) {
  PointAnswer a;
  a.code = code;
  a.status = to_string(code);
  a.reason = std::move(reason);
  return a;
}

}  // namespace vrreg::serve
