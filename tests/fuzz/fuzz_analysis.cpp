// libFuzzer target: the whole pipeline on tiny parts, so that validation, the part
// (hull, regions, features, occluders) and the exact kernel see hostile geometry --
// subnormal and huge coordinates, zero-area and collinear faces, coincident and crossing
// faces -- and not only the readers. GVM_FUZZ_FORMAT picks how the bytes become a part:
//   "off": the bytes are an OFF file;
//   "stl": the bytes are the facets of a binary STL (3 vertices of 3 float32 each, 36
//          bytes a facet), wrapped in a well-formed header so that mutations reach the
//          geometry rather than the reader's size check (fuzz_mesh_reader_stl has that).
// Every analysis: at most 48 faces, one thread, global occlusion on. A result must be
// consistent (every GVM inside its LVM) and its message free of NaN and infinities.
#include <spdlog/sinks/null_sink.h>
#include <spdlog/spdlog.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_inputs.h"
#include "fuzz_support.h"
#include "gvm/analysis.h"
#include "gvm/analysis_proto.h"

#ifndef GVM_FUZZ_FORMAT
#error "define GVM_FUZZ_FORMAT as \"off\" or \"stl\""
#endif

namespace {

void check(const gvm::Analysis& analysis) {
  for (const auto* surfaces : {&analysis.regions(), &analysis.features()}) {
    for (const gvm::Surface& s : *surfaces) {
      if (s.faces.empty()) gvm::fuzz::broken("a surface without faces");
      if (s.maps.gvm && !s.maps.gvm->is_subset_of(s.maps.lvm)) gvm::fuzz::broken("a GVM outside its LVM");
    }
  }
  const std::string json = gvm::to_json(gvm::to_proto(analysis));
  if (json.find("NaN") != std::string::npos || json.find("Infinity") != std::string::npos)
    gvm::fuzz::broken("a non-finite number in the analysis message");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const auto logger =
      std::make_shared<spdlog::logger>("fuzz", std::make_shared<spdlog::sinks::null_sink_st>());
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const bool stl = std::string_view(GVM_FUZZ_FORMAT) == "stl";
  const std::string bytes = stl ? gvm::fuzz::binary_stl_of_facets(input) : std::string(input);

  gvm::AnalyzeRequest request;
  request.part_bytes = bytes;
  request.part_format = stl ? gvm::MeshFormat::kStl : gvm::MeshFormat::kOff;
  request.part_name = "fuzz." GVM_FUZZ_FORMAT;
  request.max_faces = gvm::fuzz::kAnalysisMaxFaces;
  request.options.set_threads(1);
  request.options.set_lvm_only(false);
  request.logger = logger;
  auto analysis = gvm::analyze(request);
  if (!analysis.ok()) {
    gvm::fuzz::expect_clean_error(analysis.status());
    return 0;
  }
  check(*analysis);
  return 0;
}
