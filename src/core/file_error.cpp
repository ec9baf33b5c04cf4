#include "vrreg/core/file_error.hpp"

#include <string>

namespace vrreg {
namespace {

std::string format_message(const std::string& path, std::size_t line, const std::string& message) {
  if (line == 0) return path + ": " + message;
  return path + ":" + std::to_string(line) + ": " + message;
}

}  // namespace

FileError::FileError(const std::string& path, std::size_t line, const std::string& message)
    : InputError(format_message(path, line, message)), path_(path), line_(line) {}

}  // namespace vrreg
