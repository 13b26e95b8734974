// What the daemon accepts and how much it runs at once (gvmd's flags).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace gvm::daemon {

struct Limits {
  size_t max_request_bytes = size_t{256} << 20;  // gRPC's own receive limit is set to match
  uint32_t max_faces = 5'000'000;                // 0: no limit
  unsigned max_jobs = 2;                         // requests computing at once
  unsigned max_queue = 64;                       // requests waiting behind them
  size_t cache_entries = 32;                     // analyses kept (0: no cache)
  std::vector<std::filesystem::path> allowed_paths;  // part paths served (canonical)
};

}  // namespace gvm::daemon
