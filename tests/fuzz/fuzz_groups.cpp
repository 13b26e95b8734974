// libFuzzer target: the face groups JSON (`--groups`, AnalyzeRequest::groups_json). The
// text is parsed for a part of 6 faces; when it parses, the groups must name existing
// faces at most once each, and the whole analysis of a unit cube with those groups as its
// features must succeed with exactly those features.
#include <spdlog/sinks/null_sink.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_inputs.h"
#include "fuzz_support.h"
#include "gvm/analysis.h"
#include "gvm/part.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto logger =
      std::make_shared<spdlog::logger>("fuzz", std::make_shared<spdlog::sinks::null_sink_st>());
  const std::string json(reinterpret_cast<const char*>(data), size);
  auto groups = gvm::parse_face_groups(json, gvm::fuzz::kCubeFaces, "fuzz groups");
  if (!groups.ok()) {
    gvm::fuzz::expect_clean_error(groups.status());
    return 0;
  }
  std::set<uint32_t> seen;
  for (const auto& [name, faces] : *groups) {
    if (faces.empty()) gvm::fuzz::broken("an empty group was accepted");
    for (uint32_t f : faces)
      if (f >= gvm::fuzz::kCubeFaces || !seen.insert(f).second) gvm::fuzz::broken("a face out of range or in two groups");
  }
  if (json.empty()) return 0;  // analyze() reads an empty groups_json as "no groups"

  gvm::AnalyzeRequest request;
  request.part_bytes = gvm::fuzz::kCube;
  request.part_format = gvm::MeshFormat::kOff;
  request.part_name = "cube.off";
  request.groups_json = json;
  request.options.set_threads(1);
  request.logger = logger;
  auto analysis = gvm::analyze(request);
  if (!analysis.ok()) {
    gvm::fuzz::expect_clean_error(analysis.status());
    gvm::fuzz::broken("a cube with valid groups was refused");
  }
  // Named groups become features by those names (faces outside every group form
  // automatic features of their own).
  for (const auto& [name, faces] : *groups) {
    std::vector<uint32_t> ascending = faces;
    std::sort(ascending.begin(), ascending.end());
    bool found = false;
    for (const gvm::Surface& f : analysis->features())
      if (f.name == name && f.faces == ascending) found = true;
    if (!found) gvm::fuzz::broken("a group is not a feature of the analysis");
  }
  return 0;
}
