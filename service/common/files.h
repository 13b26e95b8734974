// Whole files: read at once, and written so that they are either whole or absent.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace gvm {

// Writes `content` to `path` through a temporary file in the same directory and renames
// it, so a crash or a full disk never leaves half a file; false when it could not.
bool write_file_atomically(const std::filesystem::path& path, std::string_view content);

// The file's bytes, or nothing when it cannot be opened or read.
std::optional<std::string> read_whole_file(const std::filesystem::path& path);

}  // namespace gvm
