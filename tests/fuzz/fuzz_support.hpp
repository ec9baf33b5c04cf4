// SPDX-License-Identifier: Apache-2.0
#pragma once
// Shared by the fuzz harnesses (tests/fuzz/fuzz_*.cpp): under libFuzzer (scripts/fuzz.sh) each
// file is its own fuzzer; in the test suite (corpus_replay_test.cpp) the seed corpora and the
// regression inputs run through the same functions. A reader may refuse any input, but only with
// the documented FileError and a one-line message; anything else is a Finding (a bug).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <typeinfo>

#include "vrreg/core/file_error.hpp"

namespace vrreg::fuzz {

/// A bug found by a harness: an undocumented exception, a multi-line message, a broken property.
class Finding : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// The input bytes as text (the readers take any bytes, NUL included).
inline std::string as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Runs `read` (one reader call); true when it returned, false when it refused with a one-line
/// FileError; throws Finding for anything else.
template <class Read>
bool reads_or_refuses(const char* what, Read&& read) {
  try {
    read();
    return true;
  } catch (const FileError& e) {
    const std::string message = e.what();
    if (message.empty() || message.find('\n') != std::string::npos) {
      throw Finding(std::string(what) + ": FileError message is not one line: " + message);
    }
    return false;
  } catch (const Finding&) {
    throw;
  } catch (const std::exception& e) {
    throw Finding(std::string(what) + ": undocumented exception " + typeid(e).name() + ": " +
                  e.what());
  }
}

/// Throws Finding unless `condition` holds (a property of an accepted input).
inline void require(bool condition, const std::string& what) {
  if (!condition) throw Finding(what);
}

// The harnesses (one per reader).
int measurement_csv(const std::uint8_t* data, std::size_t size);
int model_json(const std::uint8_t* data, std::size_t size);
int robot_file(const std::uint8_t* data, std::size_t size);
int error_model(const std::uint8_t* data, std::size_t size);
int plan_csv(const std::uint8_t* data, std::size_t size);
int parts_csv(const std::uint8_t* data, std::size_t size);
int urdf(const std::uint8_t* data, std::size_t size);
int serve_line(const std::uint8_t* data, std::size_t size);
int serve_http(const std::uint8_t* data, std::size_t size);
int serve_line_handler(const std::uint8_t* data, std::size_t size);
int serve_http_handler(const std::uint8_t* data, std::size_t size);

}  // namespace vrreg::fuzz

#ifdef VRREG_LIBFUZZER
#include <cstdio>
#include <cstdlib>
/// libFuzzer's entry point for harness `fn`: a Finding is printed and aborts (a crash input).
#define VRREG_FUZZ_ENTRY(fn)                                                          \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
    try {                                                                             \
      return fn(data, size);                                                          \
    } catch (const ::vrreg::fuzz::Finding& finding) {                                 \
      std::fprintf(stderr, "vrreg fuzz finding: %s\n", finding.what());               \
      std::abort();                                                                   \
    }                                                                                 \
  }
#else
#define VRREG_FUZZ_ENTRY(fn)
#endif
