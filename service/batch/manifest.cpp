// The three manifest formats, read into BatchParts, then resolved and checked alike.
#include <google/protobuf/util/json_util.h>

#include <algorithm>
#include <map>
#include <sstream>

#include "batch.h"
#include "common/files.h"
#include "csv.h"
#include "gvm/analysis.h"
#include "gvm/planner/plan.h"
#include "option_fields.h"

namespace gvm::batch {
namespace {

namespace fs = std::filesystem;

struct Entry {
  std::string where;
  v1::BatchPart part;
};

std::string trimmed(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// One path a line; blank lines and '#' comments skipped.
std::vector<Entry> read_lines(const std::string& text) {
  std::vector<Entry> out;
  std::istringstream in(text);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    const std::string path = trimmed(line);
    if (path.empty() || path[0] == '#') continue;
    Entry e{"line " + std::to_string(number), {}};
    e.part.set_part(path);
    out.push_back(std::move(e));
  }
  return out;
}

StatusOr<std::vector<Entry>> read_json(const std::string& text) {
  v1::BatchManifest manifest;
  const auto parsed = google::protobuf::util::JsonStringToMessage(text, &manifest);
  if (!parsed.ok()) return InvalidArgument("manifest: not a BatchManifest in JSON: " + std::string(parsed.message()));
  std::vector<Entry> out;
  for (int i = 0; i < manifest.parts_size(); ++i) {
    out.push_back({"parts[" + std::to_string(i) + "]", manifest.parts(i)});
  }
  return out;
}

// A header naming the columns, then one part a row; an empty cell leaves its field unset.
StatusOr<std::vector<Entry>> read_csv(const std::string& text) {
  StatusOr<std::vector<CsvRow>> rows = parse_csv(text);
  if (!rows.ok()) return rows.status();
  if (rows->empty()) return std::vector<Entry>{};
  const CsvRow& header = rows->front();
  if (std::find(header.cells.begin(), header.cells.end(), "part") == header.cells.end()) {
    return InvalidArgument("manifest: the CSV header (line " + std::to_string(header.line) + ") has no column 'part'");
  }
  std::vector<Entry> out;
  for (size_t r = 1; r < rows->size(); ++r) {
    const CsvRow& row = (*rows)[r];
    const std::string where = "line " + std::to_string(row.line);
    if (row.cells.size() != header.cells.size()) {
      return InvalidArgument("manifest " + where + ": " + std::to_string(row.cells.size()) + " cells, the header has " +
                             std::to_string(header.cells.size()));
    }
    Entry e{where, {}};
    for (size_t c = 0; c < row.cells.size(); ++c) {
      if (row.cells[c].empty()) continue;
      if (Status s = set_column(e.part, header.cells[c], row.cells[c]); !s.ok()) {
        return InvalidArgument("manifest " + where + ": " + s.message());
      }
    }
    out.push_back(std::move(e));
  }
  return out;
}

StatusOr<std::vector<Entry>> read_entries(const fs::path& manifest) {
  if (fs::is_directory(manifest)) return InvalidArgument("manifest '" + manifest.string() + "' is a directory, not a file");
  const std::optional<std::string> text = read_whole_file(manifest);
  if (!text) return NotFound("manifest '" + manifest.string() + "' cannot be opened");
  const std::string ext = manifest.extension().string();
  if (ext == ".json") return read_json(*text);
  if (ext == ".csv") return read_csv(*text);
  return read_lines(*text);
}

// A name that is one plain file name in the output directory.
bool usable_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos &&
         name.find('\0') == std::string::npos;
}

StatusOr<BatchItem> resolve(const Entry& e, const fs::path& base, const v1::AnalyzeOptions& analyze,
                            const v1::PlanOptions& plan) {
  const std::string where = "manifest " + e.where;
  if (e.part.part().empty()) return InvalidArgument(where + ": no part path");
  BatchItem item;
  item.where = e.where;
  item.part = (base / e.part.part()).lexically_normal();
  if (!e.part.groups().empty()) item.groups = (base / e.part.groups()).lexically_normal();
  item.name = e.part.name().empty() ? item.part.stem().string() : e.part.name();
  if (!usable_name(item.name)) return InvalidArgument(where + ": name '" + item.name + "' is not a plain file name");
  item.analyze = analyze;
  item.analyze.MergeFrom(e.part.analyze());
  item.plan = plan;
  item.plan.MergeFrom(e.part.plan());
  if (Status s = validate(item.analyze); !s.ok()) return InvalidArgument(where + ": " + s.message());
  if (Status s = planner::validate(item.plan); !s.ok()) return InvalidArgument(where + ": " + s.message());
  std::error_code ec;
  const uintmax_t size = fs::file_size(item.part, ec);
  item.input_bytes = ec ? 0 : size;
  return item;
}

}  // namespace

StatusOr<std::vector<BatchItem>> read_manifest(const fs::path& manifest, const v1::AnalyzeOptions& analyze,
                                              const v1::PlanOptions& plan) {
  StatusOr<std::vector<Entry>> entries = read_entries(manifest);
  if (!entries.ok()) return entries.status();
  if (entries->empty()) return InvalidArgument("manifest '" + manifest.string() + "' lists no parts");
  const fs::path base = manifest.parent_path();
  std::vector<BatchItem> items;
  std::map<std::string, std::string> taken;  // output name -> where
  for (const Entry& e : *entries) {
    StatusOr<BatchItem> item = resolve(e, base, analyze, plan);
    if (!item.ok()) return item.status();
    const auto [it, fresh] = taken.emplace(item->name, e.where);
    if (!fresh) {
      return InvalidArgument("manifest " + it->second + " and " + e.where + " both write '" + item->name +
                             "': give one of them a name (the column or field 'name' of a CSV or JSON manifest)");
    }
    item->index = items.size();
    items.push_back(std::move(*item));
  }
  return items;
}

std::vector<size_t> largest_first(const std::vector<BatchItem>& items) {
  std::vector<size_t> order(items.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return items[a].input_bytes > items[b].input_bytes; });
  return order;
}

}  // namespace gvm::batch
