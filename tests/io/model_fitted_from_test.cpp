// SPDX-License-Identifier: Apache-2.0
// A saved corrector carries what it was fitted from (its method, a fingerprint of the fiducials
// and of its own state) and is refused when read back otherwise: a kriging model relabelled rbf
// or joint, a table scaled by hand, fiducials edited after the fit, a negative length scale. Each
// refusal is one FileError naming the model file and the key; files written before the
// fingerprint read as before.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "io_test_helpers.hpp"
#include "vrreg/io/measurement_csv.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::io {
namespace {

using json = nlohmann::ordered_json;
using vrreg::testing::throws_file_error;

const std::string kCell = std::string(VRREG_SOURCE_DIR) + "/examples/data/example-cell.csv";

// The example cell registered with `method`, as model JSON (fitted once per method).
const json& model_doc(InterpolationMethod method) {
  static std::map<InterpolationMethod, json> docs;
  auto it = docs.find(method);
  if (it == docs.end()) {
    RegisterOptions options;
    options.interpolation.method = method;
    options.interpolation.cube_edge_m = 0.05;  // octuplet's
    const RegistrationModel model = register_fiducials(read_measurement_csv(kCell), options).model;
    it = docs.emplace(method, json::parse(format_model_json(model))).first;
  }
  return it->second;
}

::testing::AssertionResult refused(const json& doc, const std::string& fragment) {
  return throws_file_error([&] { (void)parse_model_json(doc.dump(), "cell.json"); }, "cell.json", 0,
                           fragment);
}

TEST(ModelFittedFrom, WrittenAndVerified) {
  const json& doc = model_doc(InterpolationMethod::kKriging);
  ASSERT_TRUE(doc["corrector"].contains("fitted_from"));
  const json& from = doc["corrector"]["fitted_from"];
  EXPECT_EQ(from["method"], "kriging");
  EXPECT_EQ(from["fiducials_fnv1a64"].get<std::string>().size(), 16u);
  EXPECT_EQ(from["state_fnv1a64"].get<std::string>().size(), 16u);
  const RegistrationModel read = parse_model_json(doc.dump(), "cell.json");
  ASSERT_TRUE(read.corrector.has_value());
  EXPECT_EQ(read.corrector->method(), InterpolationMethod::kKriging);
  // Written again (the state's keys in another order), the same fingerprints: they are of
  // values, not of their spelling or order.
  EXPECT_EQ(json::parse(format_model_json(read))["corrector"]["fitted_from"], from);
}

TEST(ModelFittedFrom, MethodsThatKeepNoStateWriteNone) {
  // Octuplet, scattered, trilinear are rebuilt from the fiducials when read: nothing to verify.
  const json& doc = model_doc(InterpolationMethod::kOctuplet);
  ASSERT_TRUE(doc.contains("corrector"));
  EXPECT_FALSE(doc["corrector"].contains("fitted_from"));
}

TEST(ModelFittedFrom, ARelabelledMethodIsRefused) {
  for (const bool with_fingerprint : {true, false}) {
    json doc = model_doc(InterpolationMethod::kKriging);
    if (!with_fingerprint) doc["corrector"].erase("fitted_from");
    for (const char* label : {"rbf", "joint", "grid"}) {
      doc["corrector"]["method"] = label;
      EXPECT_TRUE(refused(doc, "'corrector.method': says " + std::string(label)))
          << with_fingerprint;
    }
  }
  json doc = model_doc(InterpolationMethod::kRbf);
  doc["corrector"]["method"] = "kriging";
  EXPECT_TRUE(refused(doc, "'corrector.method': says kriging but the saved state lacks 'kernel'"));
  // Relabelled in both places the state still tells.
  doc["corrector"]["fitted_from"]["method"] = "kriging";
  EXPECT_TRUE(refused(doc, "'corrector.method'"));
}

TEST(ModelFittedFrom, AnEditedStateIsRefused) {
  json doc = model_doc(InterpolationMethod::kKriging);
  json& state = doc["corrector"]["state"];
  ASSERT_TRUE(state.contains("x.signal_sd_m"));
  state["x.signal_sd_m"] = state["x.signal_sd_m"].get<double>() * 1000.0;
  EXPECT_TRUE(refused(doc, "'corrector.state': changed since it was fitted"));
  // The table, when written as numbers, scaled by 1000.
  doc = model_doc(InterpolationMethod::kKriging);
  ASSERT_TRUE(doc["corrector"]["state"].contains("table.values_m"));
  json& table = doc["corrector"]["state"]["table.values_m"];
  if (table.contains("values")) {
    for (json& v : table["values"]) v = v.get<double>() * 1000.0;
  } else {
    std::string& text = table["f64le_base64"].get_ref<std::string&>();
    text[text.size() / 2] = text[text.size() / 2] == 'A' ? 'B' : 'A';
  }
  EXPECT_TRUE(refused(doc, "'corrector.state': changed since it was fitted"));
}

TEST(ModelFittedFrom, EditedFiducialsAreRefused) {
  json doc = model_doc(InterpolationMethod::kKriging);
  json& c = doc["fiducials"][3]["correction_m"][0];
  c = c.get<double>() + 1e-4;
  EXPECT_TRUE(refused(doc, "'fiducials': changed since the corrector was fitted on them"));
}

TEST(ModelFittedFrom, ANegativeLengthScaleIsRefusedNamingTheKey) {
  for (const bool with_fingerprint : {true, false}) {
    json doc = model_doc(InterpolationMethod::kKriging);
    if (!with_fingerprint) doc["corrector"].erase("fitted_from");
    json& length = doc["corrector"]["state"]["y.length_m"];
    ASSERT_TRUE(length.contains("values"));
    length["values"][1] = -0.05;
    EXPECT_TRUE(refused(doc, "'corrector.state.y.length_m': a length scale must be a positive"));
    length["values"][1] = 0.0;
    EXPECT_TRUE(refused(doc, "'corrector.state.y.length_m'"));
  }
}

TEST(ModelFittedFrom, FilesWithoutTheFingerprintStillRead) {
  for (const auto method : {InterpolationMethod::kKriging, InterpolationMethod::kRbf}) {
    json doc = model_doc(method);
    doc["corrector"].erase("fitted_from");
    const RegistrationModel read = parse_model_json(doc.dump(), "old.json");
    ASSERT_TRUE(read.corrector.has_value());
    EXPECT_EQ(read.corrector->method(), method);
  }
}

}  // namespace
}  // namespace vrreg::io
