// SPDX-License-Identifier: Apache-2.0
#pragma once
// Helpers for the io tests: a scratch directory per test and checks on FileError messages.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "vrreg/io/file_error.hpp"

namespace vrreg::testing {

/// A fresh directory under the system temp dir, removed with everything in it at scope exit.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = std::string("vrreg_io_") + (info ? info->test_suite_name() : "x") +
                             "_" + (info ? info->name() : "y") + "_" + std::to_string(::getpid()) +
                             "_" + std::to_string(reinterpret_cast<std::uintptr_t>(this));
    path_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  /// Full path of `name` inside the directory.
  [[nodiscard]] std::string file(const std::string& name) const { return (path_ / name).string(); }
  /// Writes `content` byte for byte to `name` and returns its full path.
  std::string write(const std::string& name, const std::string& content) const {
    const std::string p = file(name);
    std::ofstream out(p, std::ios::binary);
    out << content;
    return p;
  }

 private:
  std::filesystem::path path_;
};

/// Whole content of a file.
inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Checks that `action` throws FileError for `path` at `line` whose message contains `fragment`
/// and reads "path:line: ..." (or "path: ..." for line 0) on one line.
inline ::testing::AssertionResult throws_file_error(const std::function<void()>& action,
                                                    const std::string& path, std::size_t line,
                                                    const std::string& fragment) {
  try {
    action();
  } catch (const io::FileError& e) {
    const std::string what = e.what();
    const std::string prefix = line == 0 ? path + ": " : path + ":" + std::to_string(line) + ": ";
    if (e.path() != path || e.line() != line || !what.starts_with(prefix) ||
        what.find(fragment) == std::string::npos || what.find('\n') != std::string::npos) {
      return ::testing::AssertionFailure()
             << "got FileError(line " << e.line() << "): " << what << "\nexpected prefix '"
             << prefix << "' and fragment '" << fragment << "'";
    }
    return ::testing::AssertionSuccess() << what;
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "threw another exception: " << e.what();
  }
  return ::testing::AssertionFailure() << "did not throw";
}

/// Number of entries in a directory: a write that left a temporary file behind shows up here.
inline std::size_t directory_entries(const std::filesystem::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace vrreg::testing
