// The engine's entry point: a part file in, every concave region and feature with its
// visibility maps out, as the protobuf message gvm.v1.Analysis.
#pragma once

#include <functional>
#include <string>

#include "gvm/status.h"
#include "gvm/v1/gvm.pb.h"

namespace gvm {

struct AnalyzeRequest {
  std::string part_path;
  std::string groups_path;          // optional JSON of named face groups
  v1::AnalyzeOptions options;
  // Called now and then from the computing threads with (surfaces done, surfaces total);
  // returning false cancels the analysis (kCancelled).
  std::function<bool(size_t, size_t)> progress;
};

StatusOr<v1::Analysis> analyze(const AnalyzeRequest& request);

// Protobuf's JSON mapping of an analysis (lowerCamelCase names, every field printed).
std::string to_json(const v1::Analysis& analysis);

}  // namespace gvm
