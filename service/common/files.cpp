#include "files.h"

#include <fstream>
#include <sstream>
#include <system_error>

namespace gvm {

bool write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  // One temporary per target: parts write different files, never the same one at once.
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  std::error_code ec;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out || !out.write(content.data(), static_cast<std::streamsize>(content.size())) || !out.flush()) {
      std::filesystem::remove(tmp, ec);
      return false;
    }
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) std::filesystem::remove(tmp, ec);
  return !ec;
}

std::optional<std::string> read_whole_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream bytes;
  if (!(bytes << in.rdbuf()) && in.peek() != std::ifstream::traits_type::eof()) return std::nullopt;
  return bytes.str();
}

}  // namespace gvm
