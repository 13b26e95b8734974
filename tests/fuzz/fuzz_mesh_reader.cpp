// libFuzzer target: one mesh reader (the format from the compile definition
// GVM_FUZZ_FORMAT: "off", "obj", "stl" or "ply") on any bytes, then validation of whatever
// it reads. The reader must refuse cleanly or hand over a RawMesh whose indices are in
// range and whose coordinates are finite; validation must refuse cleanly or build a solid
// whose triangles and neighbours are consistent.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_support.h"
#include "gvm/mesh.h"

#ifndef GVM_FUZZ_FORMAT
#error "define GVM_FUZZ_FORMAT as \"off\", \"obj\", \"stl\" or \"ply\""
#endif

namespace {

// Validation is exact geometry (self-intersections among others): on larger inputs it
// would dominate the run without reaching more of the reader.
constexpr size_t kMaxValidatedFaces = 256;

void check_raw(const gvm::RawMesh& raw) {
  if (raw.faces.empty()) gvm::fuzz::broken("a mesh without faces was accepted");
  for (const auto& p : raw.points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      gvm::fuzz::broken("a non-finite coordinate was accepted");
  for (const auto& f : raw.faces)
    for (uint32_t v : f)
      if (v >= raw.points.size()) gvm::fuzz::broken("a vertex index out of range was accepted");
  for (const auto& [name, faces] : raw.groups)
    for (uint32_t f : faces)
      if (f >= raw.faces.size()) gvm::fuzz::broken("a group names a face out of range");
}

void check_solid(const gvm::SolidMesh& solid) {
  const size_t n = solid.triangles.size();
  if (n == 0 || solid.triangle_face.size() != n || solid.neighbor.size() != n || solid.shell.size() != n)
    gvm::fuzz::broken("solid arrays of different sizes");
  for (size_t t = 0; t < n; ++t) {
    for (int i = 0; i < 3; ++i) {
      if (solid.triangles[t][i] >= solid.points.size()) gvm::fuzz::broken("triangle vertex out of range");
      if (solid.neighbor[t][i] >= n) gvm::fuzz::broken("neighbour out of range");
    }
    if (solid.triangle_face[t] >= solid.input_face_count) gvm::fuzz::broken("input face out of range");
    if (solid.shell[t] >= solid.shell_is_void.size()) gvm::fuzz::broken("shell out of range");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const gvm::MeshFormat format = *gvm::parse_mesh_format(GVM_FUZZ_FORMAT);
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  auto raw = gvm::read_raw_mesh(bytes, format, "fuzz." GVM_FUZZ_FORMAT);
  if (!raw.ok()) {
    gvm::fuzz::expect_clean_error(raw.status());
    return 0;
  }
  check_raw(*raw);
  if (raw->faces.size() > kMaxValidatedFaces) return 0;
  auto solid = gvm::build_solid(*raw);
  if (!solid.ok()) {
    gvm::fuzz::expect_clean_error(solid.status());
    return 0;
  }
  check_solid(*solid);
  return 0;
}
