// The files of a batch's output directory: each part's record (NAME.result.json) and the
// summary (summary.json, summary.csv).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "batch.h"

namespace gvm::batch {

inline std::string plan_file(const std::string& name) { return name + ".plan.json"; }
inline std::string analysis_file(const std::string& name) { return name + ".analysis.json"; }
inline std::string record_file(const std::string& name) { return name + ".result.json"; }

// The record a previous run left, if it can be read.
std::optional<v1::BatchResult> read_record(const std::filesystem::path& out, const std::string& name);
bool write_record(const std::filesystem::path& out, const v1::BatchResult& result);

// What the plan of this part depends on, hashed (see BatchResult.input_hash).
std::string input_hash(const BatchItem& item, std::string_view part_bytes, std::string_view groups_bytes);

// "done", "failed", ...: the status as the summary and the progress lines say it.
std::string status_word(v1::BatchStatus status);

}  // namespace gvm::batch
