// SPDX-License-Identifier: Apache-2.0
#pragma once
// Plain-text tables with aligned columns, for the reproduction's printed output.
#include <string>
#include <vector>

namespace vrreg::experiments::text {

/// Rows of cells: column 0 left-aligned, the others right-aligned.
class TextTable {
 public:
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  /// The table, each line indented by `indent` spaces, columns two spaces apart.
  [[nodiscard]] std::string str(int indent = 2) const;

 private:
  std::vector<std::vector<std::string>> rows_;
};

/// `value` with `decimals` places ("-" for NaN).
std::string decimal_text(double value, int decimals);

}  // namespace vrreg::experiments::text
