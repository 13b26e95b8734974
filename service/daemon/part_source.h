// A request's part as the engine reads it: bytes in memory with their format, from the
// request's data or from a file under a directory the daemon serves.
#pragma once

#include <string>
#include <string_view>

#include "gvm/mesh.h"
#include "gvm/status.h"
#include "gvm/v1/service.pb.h"
#include "daemon_limits.h"

namespace gvm::daemon {

struct PartBytes {
  std::string bytes;
  MeshFormat format = MeshFormat::kStl;
  std::string name;         // for messages, logs and the analysis's source
  std::string groups_json;
  std::string hash;         // SHA-256 of bytes, format and groups, hex: the cache's key part
};

// Fails with INVALID_ARGUMENT (no part, no or wrong format), PERMISSION_DENIED (a path
// outside the served directories), NOT_FOUND, or RESOURCE_EXHAUSTED (over the size limit).
StatusOr<PartBytes> load_part(const v1::Part& part, const Limits& limits);

}  // namespace gvm::daemon
