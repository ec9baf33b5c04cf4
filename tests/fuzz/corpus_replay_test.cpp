// SPDX-License-Identifier: Apache-2.0
// Replays the fuzz harnesses' seed corpora and every input a fuzz run found (regressions/) through
// the same harness functions scripts/fuzz.sh fuzzes, in the ordinary test suite (any compiler).
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_support.hpp"

namespace vrreg::fuzz {
namespace {

namespace fs = std::filesystem;
using Harness = int (*)(const std::uint8_t*, std::size_t);

struct Case {
  const char* name;  ///< tests/fuzz/corpus/<name>, tests/fuzz/regressions/<name>
  Harness harness;
};

const Case kCases[] = {
    {"measurement_csv", measurement_csv}, {"model_json", model_json}, {"robot_file", robot_file},
    {"error_model", error_model},         {"plan_csv", plan_csv},     {"parts_csv", parts_csv},
    {"urdf", urdf},
    {"serve_line", serve_line},           {"serve_http", serve_http},
    {"serve_line_handler", serve_line_handler},
    {"serve_http_handler", serve_http_handler}};

std::vector<fs::path> inputs_of(const std::string& name) {
  std::vector<fs::path> out;
  for (const char* dir : {"corpus", "regressions"}) {
    const fs::path root = fs::path(VRREG_SOURCE_DIR) / "tests" / "fuzz" / dir / name;
    if (!fs::is_directory(root)) continue;
    for (const auto& entry : fs::directory_iterator(root)) {
      if (entry.is_regular_file()) out.push_back(entry.path());
    }
  }
  return out;
}

class CorpusReplay : public ::testing::TestWithParam<Case> {};

TEST_P(CorpusReplay, EveryInputIsReadOrRefusedWithAFileError) {
  const Case& c = GetParam();
  const std::vector<fs::path> inputs = inputs_of(c.name);
  EXPECT_GE(inputs.size(), 3U) << "seed corpus of " << c.name << " missing";
  for (const fs::path& path : inputs) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    try {
      c.harness(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    } catch (const Finding& finding) {
      ADD_FAILURE() << path << ": " << finding.what();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Harnesses, CorpusReplay, ::testing::ValuesIn(kCases),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace vrreg::fuzz
