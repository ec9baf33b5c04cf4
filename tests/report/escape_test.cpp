// SPDX-License-Identifier: Apache-2.0
// The report's escaping: no text from a user's file can close a tag or a script, and JSON read
// back by the page's JSON.parse is the value that was written.
#include "report/escape.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace vrreg::report {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

TEST(ReportEscape, HtmlEscapesTheFiveSpecialCharacters) {
  EXPECT_EQ(html_escape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(html_escape("σ_L = 0.626 mm"), "σ_L = 0.626 mm");
  EXPECT_EQ(html_escape(""), "");
}

TEST(ReportEscape, JsonForScriptCannotCloseTheScriptAndReadsBackTheSame) {
  const nlohmann::json value = {{"point", "</script><script>alert(1)</script>"},
                                {"other", "<!-- & -->"},
                                {"separators", "a\u2028b\u2029c"},
                                {"numbers", {1.5, -2, 0.001}}};
  const std::string text = json_for_script(value);
  EXPECT_EQ(text.find('<'), std::string::npos) << text;
  EXPECT_EQ(text.find('>'), std::string::npos) << text;
  EXPECT_EQ(text.find('&'), std::string::npos) << text;
  EXPECT_EQ(text.find("\xE2\x80\xA8"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(text), value);
}

TEST(ReportEscape, JsonForScriptReplacesInvalidUtf8InsteadOfThrowing) {
  const nlohmann::json value = {{"point", std::string("T\xff\xfe")}};
  std::string text;
  ASSERT_NO_THROW(text = json_for_script(value));
  EXPECT_NE(text.find("T\xEF\xBF\xBD"), std::string::npos) << text;  // U+FFFD
}

TEST(ReportEscape, JsForScriptDefusesScriptEndsAndCommentOpeners) {
  const std::string js = "var a = \"</script>\", b = '</SCRIPT >', c = /<!--x-->/; // </Script";
  const std::string out = js_for_script(js);
  EXPECT_EQ(lower(out).find("</script"), std::string::npos) << out;
  EXPECT_EQ(out.find("<!--"), std::string::npos) << out;
  EXPECT_NE(out.find("<\\/script>"), std::string::npos) << out;
  EXPECT_NE(out.find("\\x3C!--x-->"), std::string::npos) << out;
  EXPECT_EQ(js_for_script("if (a < b) { c = d; }"), "if (a < b) { c = d; }");
}

}  // namespace
}  // namespace vrreg::report
