#include "records.h"

#include <google/protobuf/util/json_util.h>

#include <sstream>

#include "common/files.h"
#include "common/sha256.h"
#include "csv.h"
#include "gvm/analysis_proto.h"

namespace gvm::batch {

namespace fs = std::filesystem;

std::optional<v1::BatchResult> read_record(const fs::path& out, const std::string& name) {
  const std::optional<std::string> text = read_whole_file(out / record_file(name));
  if (!text) return std::nullopt;
  v1::BatchResult result;
  google::protobuf::util::JsonParseOptions lenient;
  lenient.ignore_unknown_fields = true;  // a record of a later version still resumes
  if (!google::protobuf::util::JsonStringToMessage(*text, &result, lenient).ok()) return std::nullopt;
  return result;
}

bool write_record(const fs::path& out, const v1::BatchResult& result) {
  return write_file_atomically(out / record_file(result.name()), to_json(result));
}

std::string input_hash(const BatchItem& item, std::string_view part_bytes, std::string_view groups_bytes) {
  // Threads never change a plan; everything else in the options may.
  v1::AnalyzeOptions analyze = item.analyze;
  v1::PlanOptions plan = item.plan;
  analyze.clear_threads();
  plan.clear_threads();
  std::string a, p;
  google::protobuf::io::StringOutputStream as(&a), ps(&p);
  {
    google::protobuf::io::CodedOutputStream ac(&as), pc(&ps);
    ac.SetSerializationDeterministic(true);
    pc.SetSerializationDeterministic(true);
    analyze.SerializeToCodedStream(&ac);
    plan.SerializeToCodedStream(&pc);
  }
  // The extension says how the bytes are read (mesh format, STEP).
  return sha256_hex({GVM_VERSION, item.part.extension().string(), part_bytes, groups_bytes, a, p});
}

std::string status_word(v1::BatchStatus status) {
  switch (status) {
    case v1::BATCH_STATUS_RUNNING: return "running";
    case v1::BATCH_STATUS_DONE: return "done";
    case v1::BATCH_STATUS_FAILED: return "failed";
    case v1::BATCH_STATUS_TIMED_OUT: return "timed out";
    case v1::BATCH_STATUS_INTERRUPTED: return "interrupted";
    default: return "not run";
  }
}

namespace {

std::string summary_csv(const v1::BatchSummary& summary) {
  std::ostringstream csv;
  csv << "name,part,status,faces,features,surfaces,setups,unreachable,optimal,seconds,attempts,host,error\n";
  for (const v1::BatchResult& r : summary.parts()) {
    csv << csv_cell(r.name()) << ',' << csv_cell(r.part()) << ',' << csv_cell(status_word(r.status())) << ','
        << r.faces() << ',' << r.features() << ',' << r.surfaces() << ',' << r.setups() << ','
        << r.unreachable() << ',' << (r.optimal() ? "true" : "false") << ',' << r.seconds() << ','
        << r.attempts() << ',' << csv_cell(r.host()) << ',' << csv_cell(r.error()) << '\n';
  }
  return csv.str();
}

}  // namespace

Status write_summary(const BatchOptions& options, const v1::BatchSummary& summary) {
  for (const auto& [file, text] : {std::pair{"summary.json", to_json(summary)}, std::pair{"summary.csv", summary_csv(summary)}}) {
    if (!write_file_atomically(options.out / file, text)) {
      return Internal("cannot write " + (options.out / file).string());
    }
  }
  return {};
}

}  // namespace gvm::batch
