// SPDX-License-Identifier: Apache-2.0
// The numbers `vrreg snippet urscript` sends: the program's bytes (vrreg_text and the request
// expressions), and, with the controller's 32-bit arithmetic emulated, that what the service
// parses is the program's float to 0.05 um (mm) and 0.15 urad (rotation vector), where str_cat
// alone moved a coordinate at 1.3 m by up to 5 um.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "serve/snippets.hpp"
#include "urscript_text.hpp"
#include "vrreg/core/random.hpp"

namespace vrreg::serve::urscript_precision {
namespace {

using ::testing::HasSubstr;
using vrreg::testing::urscript_str_cat_float;
using vrreg::testing::urscript_vrreg_text;

SnippetOptions cell() {
  SnippetOptions s;
  s.model = "cell";
  s.port = 30401;
  return s;
}

TEST(UrscriptPrecision, TheProgramWritesNumbersWithItsOwnFunction) {
  const std::string program = urscript_client(cell());
  EXPECT_THAT(program, HasSubstr("def vrreg_text(v, scale):\n"
                                 "  sign = \"\"\n"
                                 "  a = v\n"
                                 "  if v < 0:\n"
                                 "    sign = \"-\"\n"
                                 "    a = -v\n"
                                 "  end\n"
                                 "  whole = floor(a)\n"
                                 "  fraction = floor((a - whole) * scale + 0.5)\n"
                                 "  if fraction >= scale:\n"
                                 "    whole = whole + 1\n"
                                 "    fraction = fraction - scale\n"
                                 "  end\n"
                                 "  digits = str_cat(\"\", fraction)\n"
                                 "  place = 10\n"
                                 "  while place < scale:\n"
                                 "    if fraction < place:\n"
                                 "      digits = str_cat(\"0\", digits)\n"
                                 "    end\n"
                                 "    place = place * 10\n"
                                 "  end\n"
                                 "  return str_cat(str_cat(sign, whole), str_cat(\".\", digits))\n"
                                 "end\n"));
  EXPECT_THAT(program, HasSubstr("  reply = vrreg_ask(str_cat(str_cat(str_cat(\"cell \", "
                                 "vrreg_text(p_sensor_mm[0], 10000)), str_cat(\" \", "
                                 "vrreg_text(p_sensor_mm[1], 10000))), str_cat(\" \", "
                                 "vrreg_text(p_sensor_mm[2], 10000))), 4)\n"));
  EXPECT_THAT(program, HasSubstr("  reply = vrreg_ask(str_cat(str_cat(str_cat(str_cat(\"cell \", "
                                 "vrreg_text(p_sensor_mm[0], 10000)), str_cat(\" \", "
                                 "vrreg_text(p_sensor_mm[1], 10000))), str_cat(str_cat(\" \", "
                                 "vrreg_text(p_sensor_mm[2], 10000)), str_cat(\" rotvec \", "
                                 "vrreg_text(p_sensor_mm[3], 10000000)))), str_cat(str_cat(\" \", "
                                 "vrreg_text(p_sensor_mm[4], 10000000)), str_cat(\" \", "
                                 "vrreg_text(p_sensor_mm[5], 10000000)))), 8)\n"));
  // A float printed by str_cat alone is in no request any more.
  EXPECT_THAT(program, ::testing::Not(HasSubstr("\", p_sensor_mm[")));
  EXPECT_EQ(kUrscriptMmDecimals, 4);
  EXPECT_EQ(kUrscriptRadDecimals, 7);
}

TEST(UrscriptPrecision, EmulatedTextOfKnownValues) {
  EXPECT_EQ(urscript_vrreg_text(412.5f, 10000), "412.5000");
  EXPECT_EQ(urscript_vrreg_text(-90.0f, 10000), "-90.0000");
  EXPECT_EQ(urscript_vrreg_text(0.00004f, 10000), "0.0000");
  EXPECT_EQ(urscript_vrreg_text(0.00006f, 10000), "0.0001");
  EXPECT_EQ(urscript_vrreg_text(-0.05f, 10000), "-0.0500");
  EXPECT_EQ(urscript_vrreg_text(0.99996f, 10000), "1.0000");  // the fraction carries
  EXPECT_EQ(urscript_vrreg_text(3.14159265f, 10000000), "3.1415927");
  EXPECT_EQ(urscript_str_cat_float(1300.1234f), "1300.12");
}

// Over a cell out to 3 m from the base: the text the service parses is the program's float to
// half a unit of the last decimal (and float rounding of the product, far below); str_cat alone
// is off by up to half a unit of its sixth digit.
TEST(UrscriptPrecision, ParsedValuesKeepTheProgramsFloatToTheStatedPrecision) {
  Random rng(5);
  double worst_mm = 0.0, worst_rad = 0.0, worst_str_cat_at_1300_mm = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const float mm = static_cast<float>(rng.uniform(-3000.0, 3000.0));
    const float rad = static_cast<float>(rng.uniform(-3.1415, 3.1415));
    worst_mm =
        std::max(worst_mm, std::abs(std::strtod(urscript_vrreg_text(mm, 10000).c_str(), nullptr) -
                                    static_cast<double>(mm)));
    worst_rad = std::max(worst_rad,
                         std::abs(std::strtod(urscript_vrreg_text(rad, 10000000).c_str(), nullptr) -
                                  static_cast<double>(rad)));
    const float at_1300 = static_cast<float>(rng.uniform(1000.0, 1300.0));
    worst_str_cat_at_1300_mm =
        std::max(worst_str_cat_at_1300_mm,
                 std::abs(std::strtod(urscript_str_cat_float(at_1300).c_str(), nullptr) - at_1300));
  }
  RecordProperty("worst_mm", std::to_string(worst_mm));
  RecordProperty("worst_rad", std::to_string(worst_rad));
  RecordProperty("worst_str_cat_mm", std::to_string(worst_str_cat_at_1300_mm));
  // Half a unit of the last decimal, plus the float32 rounding of (a - whole) * scale and of
  // + 0.5: 2^-10 of a unit below 10^4 (mm), up to one unit between 2^23 and 10^7 (rad).
  EXPECT_LE(worst_mm, 0.5e-4 + 1e-7);           // 0.05 um
  EXPECT_LE(worst_rad, 1.5e-7 + 1e-12);         // 0.15 urad; a float's spacing at pi is 0.24 urad
  EXPECT_GT(worst_rad, 0.5e-7);                 // the float32 rounding is there: the bound is tight
  EXPECT_GT(worst_str_cat_at_1300_mm, 4.9e-3);  // 6 significant digits: 5 um
}

}  // namespace
}  // namespace vrreg::serve::urscript_precision
