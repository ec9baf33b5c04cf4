// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reads a text file line by line with a bound on the line length, so that memory stays bounded
// whatever the file holds. Accepts LF and CRLF endings, a UTF-8 BOM, a missing final newline.
#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace vrreg::io::detail {

/// Line reader over a stream: every line is checked to be text (see text_checks.hpp).
class LineReader {
 public:
  /// `source` names the stream in errors; a line longer than `max_line_bytes` throws FileError.
  LineReader(std::istream& in, std::string source, std::size_t max_line_bytes);

  /// Next line without its terminator into `line`; false at the end of the input.
  bool next(std::string& line);
  /// 1-based number of the line last returned (0 before the first).
  [[nodiscard]] std::size_t line_number() const { return line_number_; }

 private:
  bool fill();

  std::istream& in_;
  std::string source_;
  std::size_t max_line_bytes_;
  std::vector<char> buffer_;
  std::size_t pos_ = 0;
  std::size_t end_ = 0;
  std::size_t line_number_ = 0;
  bool at_end_ = false;
};

}  // namespace vrreg::io::detail
