// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a fitted correction method saves so that it corrects again without fitting: named arrays
// of numbers and texts, which io writes into the model file as one JSON object. Keys carry their
// unit (`length_m`, `_rad`); numbers are written so that they read back to the bit.
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace vrreg {

/// A method's saved state: named arrays (a 1 x 1 array is a number) and texts, in the order put.
class MethodState {
 public:
  MethodState() = default;
  /// `method`: the name of the method the state belongs to (it names the state in errors).
  explicit MethodState(std::string method) : method_(std::move(method)) {}

  void put(const std::string& key, Eigen::MatrixXd value);
  void put(const std::string& key, double value);
  void put_text(const std::string& key, std::string value);

  [[nodiscard]] bool has(const std::string& key) const;
  /// The array under `key`; throws InputError naming the method and the key when it is missing,
  /// has another shape (rows or cols >= 0 are checked) or holds a non-finite value.
  [[nodiscard]] const Eigen::MatrixXd& array(const std::string& key, Eigen::Index rows = -1,
                                             Eigen::Index cols = -1) const;
  /// A 1 x 1 array as a number (checked as array() does).
  [[nodiscard]] double number(const std::string& key) const;
  /// A number that must be a whole number in [lo, hi] (counts, indices, flags).
  [[nodiscard]] long long integer(const std::string& key, long long lo, long long hi) const;
  /// The text under `key`; throws InputError when it is missing.
  [[nodiscard]] const std::string& text(const std::string& key) const;

  [[nodiscard]] const std::string& method() const { return method_; }
  [[nodiscard]] const std::vector<std::pair<std::string, Eigen::MatrixXd>>& arrays() const {
    return arrays_;
  }
  [[nodiscard]] const std::vector<std::pair<std::string, std::string>>& texts() const {
    return texts_;
  }

 private:
  std::string method_{};
  std::vector<std::pair<std::string, Eigen::MatrixXd>> arrays_{};
  std::vector<std::pair<std::string, std::string>> texts_{};
};

}  // namespace vrreg
