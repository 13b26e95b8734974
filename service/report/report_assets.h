// The browser side of the report, built at build time from service/report/web (three.js
// and d3-geo bundled by esbuild) and compiled into the program, so reports need no files
// beside the binary.
#pragma once

#include <string_view>

namespace gvm::report {

std::string_view page_template();  // report.html with @GVM_...@ placeholders
std::string_view page_script();    // the bundled JavaScript
std::string_view page_style();     // the bundled CSS

}  // namespace gvm::report
