// Batches of parts, on one machine (`gvm batch`) or across MPI ranks (`gvm-mpi batch`):
// the same manifest, the same part runs and the same files in the output directory.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stop_token>
#include <string>
#include <vector>

#include "gvm/status.h"
#include "gvm/v1/batch.pb.h"

namespace gvm::batch {

// A part of the manifest with its paths resolved and its options merged.
struct BatchItem {
  size_t index = 0;                 // in the manifest
  std::string where;                // "line 3", "parts[2]": for messages
  std::string name;                 // base name of its outputs
  std::filesystem::path part, groups;
  v1::AnalyzeOptions analyze;       // the command line's, merged with the manifest's
  v1::PlanOptions plan;
  uint64_t input_bytes = 0;         // the part file's size (0 if it cannot be read)
};

struct BatchOptions {
  std::filesystem::path out;        // the output directory (created)
  bool write_analysis = false;      // NAME.analysis.json too
  bool resume = false;
  unsigned threads = 1;             // TBB threads of this process
  unsigned jobs = 0;                // parts at once in this process; 0: the runner's default
  uint64_t max_memory = 0;          // bytes; 0: no bound
  double part_timeout_seconds = 0;  // 0: none
  std::string host;                 // recorded in each result
};

// Reads a manifest: one part path a line ('#' starts a comment), a CSV with a header
// (columns part, groups, name and any field of PlanOptions or AnalyzeOptions, e.g. mode,
// min_clearance_degrees, step.solid), or a JSON BatchManifest (by the extension .csv or
// .json). Relative paths are read from the manifest's directory. Fails with
// kInvalidArgument naming the line (or parts[i]) and the field for anything that would
// make a part fail whatever its mesh: bad syntax, an unknown column, a bad option value,
// two parts with the same output name. A part file that does not exist is not an error
// here: that part fails, the others run.
StatusOr<std::vector<BatchItem>> read_manifest(const std::filesystem::path& manifest,
                                              const v1::AnalyzeOptions& analyze,
                                              const v1::PlanOptions& plan);

// The order parts are started in: largest file first (ties: manifest order), so that the
// long parts do not start last and leave the other cores idle at the end.
std::vector<size_t> largest_first(const std::vector<BatchItem>& items);

struct PartOutcome {
  v1::BatchResult result;
  bool skipped = false;             // done before, with the same input (--resume)
};

// Runs one part to its record: NAME.result.json says RUNNING before any work and the
// outcome after it; NAME.plan.json (and NAME.analysis.json) are written atomically
// before the record says DONE. A stop request interrupts it within about a second.
PartOutcome run_part(const BatchItem& item, const BatchOptions& options, std::stop_token stop);

// summary.json and summary.csv in the output directory, the parts in manifest order.
Status write_summary(const BatchOptions& options, const v1::BatchSummary& summary);

}  // namespace gvm::batch
