// `gvm batch` on one machine: parts run concurrently on this process's TBB pool, largest
// first, within a memory bound.
#pragma once

#include <vector>

#include "batch.h"

namespace gvm::batch {

// The memory a part's analysis and plan are expected to need at their peak, estimated
// from its file size (measured on the shared parts, see docs/batches.md).
uint64_t estimated_memory(const BatchItem& item);

// Runs every item (until SIGINT or SIGTERM), shows progress on standard output, writes
// the summary; returns the exit status: 0 every part done, 1 some part not done, 130
// stopped by a signal.
int run_local(const std::vector<BatchItem>& items, const BatchOptions& options, bool quiet);

}  // namespace gvm::batch
