// SPDX-License-Identifier: Apache-2.0
#include "line_reader.hpp"

#include <cstring>
#include <optional>
#include <utility>

#include "text_checks.hpp"
#include "vrreg/io/file_error.hpp"

namespace vrreg::io::detail {
namespace {

constexpr std::size_t kChunkBytes = 64 * 1024;
constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

}  // namespace

LineReader::LineReader(std::istream& in, std::string source, std::size_t max_line_bytes)
    : in_(in), source_(std::move(source)), max_line_bytes_(max_line_bytes), buffer_(kChunkBytes) {}

bool LineReader::fill() {
  if (at_end_) return false;
  in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  if (in_.bad()) throw FileError(source_, line_number_ + 1, "read error");
  pos_ = 0;
  end_ = static_cast<std::size_t>(in_.gcount());
  if (end_ == 0) at_end_ = true;
  return end_ > 0;
}

bool LineReader::next(std::string& line) {
  line.clear();
  bool any = false;
  for (;;) {
    if (pos_ == end_ && !fill()) break;
    any = true;
    const char* begin = buffer_.data() + pos_;
    const std::size_t available = end_ - pos_;
    const auto* newline = static_cast<const char*>(std::memchr(begin, '\n', available));
    const std::size_t take =
        newline != nullptr ? static_cast<std::size_t>(newline - begin) : available;
    // A CR just before the LF does not count towards the limit.
    if (line.size() + take > max_line_bytes_ + 1) {
      throw FileError(source_, line_number_ + 1,
                      "line longer than " + std::to_string(max_line_bytes_) +
                          " bytes (not a measurement file?)");
    }
    line.append(begin, take);
    if (newline != nullptr) {
      pos_ += take + 1;
      break;
    }
    pos_ = end_;
  }
  if (!any) return false;
  ++line_number_;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line.size() > max_line_bytes_) {
    throw FileError(
        source_, line_number_,
        "line longer than " + std::to_string(max_line_bytes_) + " bytes (not a measurement file?)");
  }
  if (line_number_ == 1 && line.starts_with(kUtf8Bom)) line.erase(0, kUtf8Bom.size());
  if (const std::optional<std::string> problem = find_non_text(line)) {
    throw FileError(source_, line_number_, *problem);
  }
  return true;
}

}  // namespace vrreg::io::detail
