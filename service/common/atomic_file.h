// Files that are either whole or absent: written beside the target and renamed over it.
#pragma once

#include <filesystem>
#include <string_view>

namespace gvm {

// Writes `content` to `path` through a temporary file in the same directory and renames
// it, so a crash or a full disk never leaves half a file; false when it could not.
bool write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace gvm
