// SPDX-License-Identifier: Apache-2.0
#include "vrreg/correction/method_state.hpp"

#include <cmath>

#include "vrreg/core/check.hpp"

namespace vrreg {

void MethodState::put(const std::string& key, Eigen::MatrixXd value) {
  VRREG_THROW_UNLESS(!has(key), method_ << " state: '" << key << "' put twice");
  arrays_.emplace_back(key, std::move(value));
}

void MethodState::put(const std::string& key, double value) {
  put(key, Eigen::MatrixXd::Constant(1, 1, value));
}

void MethodState::put_text(const std::string& key, std::string value) {
  VRREG_THROW_UNLESS(!has(key), method_ << " state: '" << key << "' put twice");
  texts_.emplace_back(key, std::move(value));
}

bool MethodState::has(const std::string& key) const {
  for (const auto& [k, v] : arrays_) {
    if (k == key) return true;
  }
  for (const auto& [k, v] : texts_) {
    if (k == key) return true;
  }
  return false;
}

const Eigen::MatrixXd& MethodState::array(const std::string& key, Eigen::Index rows,
                                          Eigen::Index cols) const {
  for (const auto& [k, v] : arrays_) {
    if (k != key) continue;
    VRREG_THROW_UNLESS((rows < 0 || v.rows() == rows) && (cols < 0 || v.cols() == cols),
                       "the saved " << method_ << " corrector's '" << key << "' is "
                                    << v.rows() << " x " << v.cols() << ", expected "
                                    << (rows < 0 ? std::string("any") : std::to_string(rows))
                                    << " x "
                                    << (cols < 0 ? std::string("any") : std::to_string(cols)));
    VRREG_THROW_UNLESS(v.allFinite(), "the saved " << method_ << " corrector's '" << key
                                                   << "' holds a value that is not finite");
    return v;
  }
  VRREG_THROW_UNLESS(false, "the saved " << method_ << " corrector has no '" << key << "'");
}

double MethodState::number(const std::string& key) const { return array(key, 1, 1)(0, 0); }

long long MethodState::integer(const std::string& key, long long lo, long long hi) const {
  const double v = number(key);
  VRREG_THROW_UNLESS(v == std::floor(v) && v >= static_cast<double>(lo) &&
                         v <= static_cast<double>(hi),
                     "the saved " << method_ << " corrector's '" << key << "' is " << v
                                  << ", expected a whole number in [" << lo << ", " << hi << "]");
  return static_cast<long long>(v);
}

const std::string& MethodState::text(const std::string& key) const {
  for (const auto& [k, v] : texts_) {
    if (k == key) return v;
  }
  VRREG_THROW_UNLESS(false, "the saved " << method_ << " corrector has no '" << key << "'");
}

}  // namespace vrreg
