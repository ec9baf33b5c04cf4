// SPDX-License-Identifier: Apache-2.0
// register --robust as a user runs it: the bad fiducial named with its deviation, the grid kept
// (its correction filled from the neighbours), the JSON object; robust-study's table.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_runner.hpp"

namespace vrreg::testing {
namespace {

namespace fs = std::filesystem;

// The example cell with fiducial F2-2-2 (a node of the every-2nd grid) read 1.5 mm off in
// sensor x, every repeat.
std::string displaced_cell() {
  std::istringstream in(read_text(fs::path(VRREG_SOURCE_DIR) / "examples/data/example-cell.csv"));
  std::string out, line;
  while (std::getline(in, line)) {
    if (line.rfind("F2-2-2,", 0) == 0) {
      std::vector<std::string> fields;
      std::stringstream ss(line);
      for (std::string f; std::getline(ss, f, ',');) fields.push_back(f);
      fields[5] = std::to_string(std::stod(fields[5]) + 1.5);
      line.clear();
      for (std::size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + fields[i];
    }
    out += line + "\n";
  }
  return out;
}

class RobustCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    write_text(dir_ / "bad.csv", displaced_cell());
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(RobustCli, NamesTheDisplacedFiducialAndKeepsTheGrid) {
  const CliResult r = run_vrreg_in(dir_, "register --fiducials bad.csv --robust -o m.json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("robust check                  1 outlier of"), std::string::npos) << r.out;
  const auto at = r.out.find("    F2-2-2 ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::string row = r.out.substr(at, r.out.find('\n', at) - at);
  EXPECT_NE(row.find(" mm = "), std::string::npos) << row;
  EXPECT_NE(row.find("correction filled from neighbours"), std::string::npos) << row;
  const CliResult e = run_vrreg_in(dir_, "evaluate --model m.json --targets bad.csv");
  ASSERT_EQ(e.status, 0) << e.err;
  EXPECT_NE(e.out.find("interpolation                 grid"), std::string::npos) << e.out;

  const CliResult j = run_vrreg_in(dir_, "register --fiducials bad.csv --robust --json");
  ASSERT_EQ(j.status, 0) << j.err;
  const nlohmann::json doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["rejected"], nlohmann::json::array({"F2-2-2"}));
  const nlohmann::json& o = doc["robust"]["outliers"][0];
  EXPECT_EQ(o["point"], "F2-2-2");
  EXPECT_NEAR(o["deviation_mm"].get<double>(), 1.5, 0.3);
  EXPECT_GT(o["sigmas"].get<double>(), doc["robust"]["threshold_sigmas"].get<double>());
  EXPECT_EQ(o["handling"], "filled from neighbours");
}

TEST_F(RobustCli, StudyPrintsTheRateTable) {
  const CliResult r = run_vrreg("robust-study --seeds 1 --seed 4");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* row : {"clean", "1 mm displaced", "2 mm displaced", "2 swapped", "bound"}) {
    EXPECT_NE(r.out.find(row), std::string::npos) << row << "\n" << r.out;
  }
  EXPECT_NE(run_vrreg("robust-study --seeds 0").status, 0);
}

}  // namespace
}  // namespace vrreg::testing
