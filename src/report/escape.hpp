// SPDX-License-Identifier: Apache-2.0
#pragma once
// Escaping for the report's HTML: text into elements and attributes, JSON and JavaScript into
// <script> elements, so that no label from a user's file can close a tag or a script.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace vrreg::report {

/// Text safe inside an HTML element or a quoted attribute: & < > " ' as character references.
std::string html_escape(std::string_view text);

/// JSON text safe inside <script type="application/json">: '<', '>', '&' and U+2028/U+2029 as
/// \u escapes (only ever inside strings, so JSON.parse reads the same value); invalid UTF-8 in
/// strings becomes U+FFFD instead of throwing.
std::string json_for_script(const nlohmann::json& value);

/// JavaScript source safe inside <script>: "</script" (any case) becomes "<\/script" and "<!--"
/// becomes "\x3C!--", which mean the same in the strings, regexes and comments they can be in.
std::string js_for_script(std::string_view source);

}  // namespace vrreg::report
