// RFC 4180 CSV, enough for manifests: commas, double-quoted cells (with "" for a quote and
// line breaks inside), CRLF or LF.
#pragma once

#include <string>
#include <vector>

#include "gvm/status.h"

namespace gvm::batch {

struct CsvRow {
  int line = 0;                     // where the row starts, from 1
  std::vector<std::string> cells;   // unquoted, not trimmed
};

// Blank lines are skipped. kInvalidArgument names the line of an unterminated quote or
// of text after a closing quote.
StatusOr<std::vector<CsvRow>> parse_csv(const std::string& text);

// One cell as CSV writes it: quoted when it holds a comma, a quote or a line break.
std::string csv_cell(const std::string& value);

}  // namespace gvm::batch
