// Binary data as text, for data: URLs and other payloads inlined into reports.
#pragma once

#include <string>
#include <string_view>

namespace gvm::report {

// RFC 4648 base64: the standard alphabet, '=' padding, no line breaks.
std::string base64(std::string_view bytes);

}  // namespace gvm::report
