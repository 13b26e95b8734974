#include "csv.h"

namespace gvm::batch {
namespace {

bool blank(const CsvRow& row) { return row.cells.size() == 1 && row.cells[0].empty(); }

}  // namespace

StatusOr<std::vector<CsvRow>> parse_csv(const std::string& text) {
  std::vector<CsvRow> rows;
  CsvRow row{1, {""}};
  int line = 1;
  bool quoted = false, after_quote = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        row.cells.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
        after_quote = true;
      } else {
        if (c == '\n') ++line;
        row.cells.back() += c;
      }
    } else if (c == ',') {
      row.cells.emplace_back();
      after_quote = false;
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      if (!blank(row)) rows.push_back(std::move(row));
      row = CsvRow{++line, {""}};
      after_quote = false;
    } else if (after_quote) {
      return InvalidArgument("manifest line " + std::to_string(line) + ": text after a closing quote");
    } else if (c == '"' && row.cells.back().empty()) {
      quoted = true;
    } else {
      row.cells.back() += c;
    }
  }
  if (quoted) return InvalidArgument("manifest line " + std::to_string(row.line) + ": a quote is never closed");
  if (!blank(row)) rows.push_back(std::move(row));
  return rows;
}

std::string csv_cell(const std::string& value) {
  if (value.find_first_of(",\"\r\n") == std::string::npos) return value;
  std::string out = "\"";
  for (char c : value) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace gvm::batch
