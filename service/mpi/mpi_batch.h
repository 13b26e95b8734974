// `gvm-mpi batch`: the parts of a manifest handed out by rank 0, one at a time and largest
// first, to every rank (rank 0 too, in a thread of its own); each rank runs them as
// `gvm batch` does, on its own TBB pool, and writes the same files to the shared output
// directory. Only rank 0's main thread calls MPI (MPI_THREAD_FUNNELED).
#pragma once

#include <vector>

#include "batch/batch.h"
#include "batch/signal_stop.h"

namespace gvm::mpi {

// Every rank calls it with the same items and options; `signals` must have been made
// before MPI_Init, so that no thread of MPI's takes SIGTERM. Returns this rank's exit
// status (rank 0's says whether every part is done, as gvm batch's).
int run_mpi_batch(const std::vector<batch::BatchItem>& items, const batch::BatchOptions& options, bool quiet,
                  const batch::SignalStop& signals);

}  // namespace gvm::mpi
