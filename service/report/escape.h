// Text made safe for the places a report puts it.
#pragma once

#include <string>
#include <string_view>

namespace gvm::report {

std::string html_escape(std::string_view s);  // element text and quoted attribute values
std::string json_string(std::string_view s);  // a quoted JSON string

}  // namespace gvm::report
