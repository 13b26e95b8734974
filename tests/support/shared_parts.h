// The shared real parts (../shared/data/parts), read and analysed as the tests use them.
#pragma once

#include <filesystem>
#include <string>

#include "gvm/part.h"

namespace gvm::test {

inline std::string shared_part_path(const std::string& name) {
  return std::string(GVM_SHARED_DIR) + "/data/parts/" + name;
}

inline bool has_shared_part(const std::string& name) { return std::filesystem::exists(shared_part_path(name)); }

// The part read, validated and analysed with the given options.
inline StatusOr<Part> analyze_shared_part(const std::string& name, const PartOptions& options = {}) {
  StatusOr<SolidMesh> solid = load_solid(shared_part_path(name));
  if (!solid.ok()) return solid.status();
  return Part::analyze(std::move(*solid), options);
}

}  // namespace gvm::test
