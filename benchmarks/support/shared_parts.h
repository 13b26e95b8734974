// What every whole-part benchmark needs: the shared parts, and its rows written as
// protobuf's JSON.
#pragma once

#include <google/protobuf/message.h>

#include <string>
#include <vector>

namespace gvm::bench {

// The meshes of $GVM_SHARED_DIR/data/parts (default ../shared), sorted.
std::vector<std::string> shared_parts();

// `message` as protobuf's JSON mapping, indented; false (and a line on stderr) when
// `path` cannot be written.
bool write_json(const google::protobuf::Message& message, const std::string& path);

// The rows of an earlier run; false (and a line on stderr) when `path` cannot be read or
// is not such a message.
bool read_json(const std::string& path, google::protobuf::Message& message);

}  // namespace gvm::bench
