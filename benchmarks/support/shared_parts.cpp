#include "support/shared_parts.h"

#include <google/protobuf/util/json_util.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "gvm/mesh.h"

namespace gvm::bench {

std::vector<std::string> shared_parts() {
  namespace fs = std::filesystem;
  const char* env = std::getenv("GVM_SHARED_DIR");
  const fs::path dir = fs::path(env ? env : "../shared") / "data" / "parts";
  std::vector<std::string> parts;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const auto format = parse_mesh_format(e.path().extension().string());
    if (format && *format != MeshFormat::kStep) parts.push_back(e.path().string());
  }
  std::sort(parts.begin(), parts.end());
  return parts;
}

bool write_json(const google::protobuf::Message& message, const std::string& path) {
  std::string text;
  google::protobuf::util::JsonPrintOptions options;
  options.add_whitespace = true;
  (void)google::protobuf::util::MessageToJsonString(message, &text, options);
  std::ofstream file(path);
  file << text;
  if (!file) std::fprintf(stderr, "cannot write %s\n", path.c_str());
  return static_cast<bool>(file);
}

bool read_json(const std::string& path, google::protobuf::Message& message) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "cannot read %s\n", path.c_str());
    return false;
  }
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto status = google::protobuf::util::JsonStringToMessage(text, &message);
  if (!status.ok()) {
    std::fprintf(stderr, "%s is not a %s: %s\n", path.c_str(), message.GetTypeName().c_str(),
                 std::string(status.message()).c_str());
    return false;
  }
  return true;
}

}  // namespace gvm::bench
