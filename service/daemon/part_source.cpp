#include "part_source.h"

#include "common/sha256.h"

#include <fstream>
#include <algorithm>
#include <memory>
#include <optional>
#include <system_error>

namespace gvm::daemon {
namespace {

namespace fs = std::filesystem;

std::optional<MeshFormat> format_of(v1::PartFormat f) {
  switch (f) {
    case v1::PART_FORMAT_STL: return MeshFormat::kStl;
    case v1::PART_FORMAT_OFF: return MeshFormat::kOff;
    case v1::PART_FORMAT_OBJ: return MeshFormat::kObj;
    case v1::PART_FORMAT_PLY: return MeshFormat::kPly;
    case v1::PART_FORMAT_STEP: return MeshFormat::kStep;
    default: return std::nullopt;
  }
}

std::string too_big(size_t bytes, size_t limit) {
  return "the part is " + std::to_string(bytes) + " bytes, over the daemon's limit of " + std::to_string(limit) +
         " (gvmd --max-request-mb)";
}

// The canonical path when it lies under one of the served directories.
StatusOr<fs::path> served_path(const std::string& requested, const Limits& limits) {
  if (limits.allowed_paths.empty()) {
    return Status(StatusCode::kPermissionDenied,
                  "part.path: this daemon serves no directories (start it with --allow-path DIR); send the bytes in part.data");
  }
  std::error_code ec;
  const fs::path path = fs::canonical(fs::path(requested), ec);
  if (ec) return NotFound("part.path '" + requested + "': " + ec.message());
  for (const fs::path& dir : limits.allowed_paths) {
    auto [d, p] = std::mismatch(dir.begin(), dir.end(), path.begin(), path.end());
    if (d == dir.end()) return path;
  }
  return Status(StatusCode::kPermissionDenied,
                "part.path '" + requested + "' is not under a directory this daemon serves (--allow-path)");
}

StatusOr<std::string> read_file(const fs::path& path, const Limits& limits) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return InvalidArgument("part.path '" + path.string() + "' is not a regular file");
  const uintmax_t size = fs::file_size(path, ec);
  if (ec) return NotFound("part.path '" + path.string() + "': " + ec.message());
  if (size > limits.max_request_bytes) return ResourceExhausted(too_big(size, limits.max_request_bytes));
  std::ifstream in(path, std::ios::binary);
  std::string bytes(size, '\0');
  if (!in.read(bytes.data(), static_cast<std::streamsize>(size))) {
    return NotFound("part.path '" + path.string() + "' cannot be read");
  }
  return bytes;
}

}  // namespace


StatusOr<PartBytes> load_part(const v1::Part& part, const Limits& limits) {
  PartBytes out;
  std::optional<MeshFormat> format = format_of(part.format());
  switch (part.source_case()) {
    case v1::Part::kData:
      if (part.data().size() > limits.max_request_bytes) {
        return ResourceExhausted(too_big(part.data().size(), limits.max_request_bytes));
      }
      if (!format) return InvalidArgument("part.format: set it (stl, off, obj, ply or step) when sending part.data");
      out.bytes = part.data();
      out.name = part.name().empty() ? "part" : part.name();
      break;
    case v1::Part::kPath: {
      StatusOr<fs::path> path = served_path(part.path(), limits);
      if (!path.ok()) return path.status();
      StatusOr<std::string> bytes = read_file(*path, limits);
      if (!bytes.ok()) return bytes.status();
      if (!format) format = parse_mesh_format(path->extension().string());
      if (!format) {
        return InvalidArgument("part.format: set it, or give the path an extension .stl, .off, .obj, .ply, .stp or .step ('" +
                               part.path() + "')");
      }
      out.bytes = std::move(*bytes);
      out.name = part.name().empty() ? part.path() : part.name();
      break;
    }
    default:
      return InvalidArgument("part: no part given (set part.data with part.format, or part.path)");
  }
  out.format = *format;
  out.groups_json = part.groups_json();
  out.hash = sha256_hex({out.bytes, std::to_string(static_cast<int>(out.format)), out.groups_json});
  return out;
}

}  // namespace gvm::daemon
