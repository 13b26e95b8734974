// What the fuzz targets (tests/fuzz/) found, kept: every input of
// tests/fuzz/regressions/<target>/ replayed exactly as its target runs it must end in a
// clean error (kInvalidArgument or kResourceExhausted, with a message) or a result, and
// each finding has its own test of the answer. Also the rule the fuzzers check everywhere:
// non-finite coordinates are refused by the readers, named, before any geometry.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "fuzz/fuzz_inputs.h"
#include "gvm/analysis.h"
#include "gvm/analysis_proto.h"
#include "gvm/mesh.h"
#include "gvm/part.h"
#include "gvm/step.h"

namespace gvm {
namespace {

namespace fs = std::filesystem;

fs::path regressions() { return fs::path(GVM_TEST_DATA_DIR).parent_path() / "fuzz" / "regressions"; }

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// fuzz_mesh_reader_<format>: the reader, then validation.
Status read_and_validate(const std::string& bytes, MeshFormat format) {
  auto raw = read_raw_mesh(bytes, format, "regression");
  if (!raw.ok()) return raw.status();
  auto solid = build_solid(*raw);
  return solid.ok() ? Status::Ok() : solid.status();
}

// fuzz_analysis_<format> and fuzz_groups: the whole analysis.
StatusOr<Analysis> analyze_part(std::string_view part, MeshFormat format, const std::string& groups_json = "",
                                uint32_t max_faces = fuzz::kAnalysisMaxFaces) {
  AnalyzeRequest request;
  request.part_bytes = part;
  request.part_format = format;
  request.part_name = "regression";
  request.groups_json = groups_json;
  request.max_faces = max_faces;
  request.options.set_threads(1);
  return analyze(request);
}

Status replay(const std::string& target, const std::string& bytes) {
  for (const auto& [name, format] : {std::pair{"off", MeshFormat::kOff}, std::pair{"obj", MeshFormat::kObj},
                                     std::pair{"stl", MeshFormat::kStl}, std::pair{"ply", MeshFormat::kPly}}) {
    if (target == std::string("fuzz_mesh_reader_") + name) return read_and_validate(bytes, format);
  }
  if (target == "fuzz_analysis_off") return analyze_part(bytes, MeshFormat::kOff).status();
  if (target == "fuzz_analysis_stl") {
    return analyze_part(fuzz::binary_stl_of_facets(bytes), MeshFormat::kStl).status();
  }
  if (target == "fuzz_groups") {
    auto groups = parse_face_groups(bytes, fuzz::kCubeFaces, "regression");
    if (!groups.ok() || bytes.empty()) return groups.status();
    return analyze_part(fuzz::kCube, MeshFormat::kOff, bytes, 0).status();
  }
  if (target == "fuzz_step") {  // through the STEP worker, as every program reads STEP
    StepOptions options;
    options.max_triangles = 20000;  // as fuzz_step
    auto part = read_step(std::string_view(bytes), options, "regression.stp");
    if (!part.ok()) return part.status();
    part->mesh.source = "regression.stp";
    auto solid = build_solid(part->mesh);
    return solid.ok() ? Status::Ok() : solid.status();
  }
  ADD_FAILURE() << "no fuzz target " << target;
  return Status::Ok();
}

TEST(FuzzRegression, EveryCheckedInInputEndsCleanly) {
  int inputs = 0;
  for (const auto& dir : fs::directory_iterator(regressions())) {
    for (const auto& file : fs::directory_iterator(dir.path())) {
      ++inputs;
      const std::string where = dir.path().filename().string() + "/" + file.path().filename().string();
      const Status st = replay(dir.path().filename().string(), slurp(file.path()));
      if (st.ok()) continue;
      EXPECT_TRUE(st.code() == StatusCode::kInvalidArgument || st.code() == StatusCode::kResourceExhausted)
          << where << ": " << st.message();
      EXPECT_FALSE(st.message().empty()) << where;
    }
  }
  EXPECT_GT(inputs, 0);
}

Status regression(const std::string& target, const std::string& name) {
  return replay(target, slurp(regressions() / target / name));
}

// The self-intersection search cast the number of grid cells (span / cell) to an integer:
// a vertex at z = 1e308 made the mean box extent overflow, the cell size fall back to 1
// and the cast overflow (undefined; UBSan: float-cast-overflow in find_self_intersection).
// The part itself is a valid solid: a cube with one corner pulled out to 1e308.
TEST(FuzzRegression, GridOfTheSelfIntersectionSearchAtTheEndOfTheDoubleRange) {
  const Status st = regression("fuzz_mesh_reader_stl", "grid_cell_overflow_1e308.stl");
  EXPECT_TRUE(st.ok()) << st.message();
}

// The same search must still find intersections when the span of the part overflows a
// double (-1e308 to 1e308): two overlapping cubes.
TEST(FuzzRegression, SelfIntersectionFoundWhenTheSpanOverflows) {
  auto cube = [](double lo, double hi, uint32_t first, RawMesh& m) {
    for (int i = 0; i < 8; ++i) m.points.push_back({i & 1 ? hi : lo, i & 2 ? hi : lo, i & 4 ? hi : lo});
    const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) m.faces.push_back({first + q[0], first + q[1], first + q[2], first + q[3]});
  };
  RawMesh m;
  m.source = "overlapping";
  cube(-1e308, 0.5e308, 0, m);
  cube(-0.5e308, 1e308, 8, m);
  auto solid = build_solid(m);
  ASSERT_FALSE(solid.ok());
  EXPECT_NE(solid.status().message().find("self-intersection"), std::string::npos) << solid.status().message();
}

// A face index of 3e30 in the groups JSON: the message cast it to uint64_t (undefined;
// UBSan: float-cast-overflow in parse_face_groups, engine/part/part.cpp). Refused, named.
TEST(FuzzRegression, GroupFaceIndexBeyondEveryInteger) {
  const Status st = regression("fuzz_groups", "face_index_3e30.json");
  EXPECT_EQ(st.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(st.message().find("does not exist (the part has 6 faces)"), std::string::npos) << st.message();
}

// A corrupted plate (fuzz_step) whose welded points made the edge splits of the faithful
// tessellation refer to each other in a cycle: fan_split cut its triangles without end,
// past the worker's 2 GiB in 5 s. Each triangle now splits at most three times, and the
// part is refused cleanly by validation.
TEST(FuzzRegression, EdgeSplitsThatReferToEachOtherEnd) {
  const Status st = regression("fuzz_step", "fan_split_cycle.stp");
  EXPECT_EQ(st.code(), StatusCode::kInvalidArgument) << st.message();
  EXPECT_NE(st.message().find("has zero area"), std::string::npos) << st.message();
}

// Non-finite coordinates never reach a predicate: the readers refuse them, naming the
// vertex, the coordinate and a face using it, in every format.
TEST(FuzzRegression, NonFiniteCoordinatesRefusedByEveryReader) {
  const std::string off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 nan\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  auto r = read_raw_mesh(off, MeshFormat::kOff, "t.off");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().message(), "t.off: vertex 3 has a non-finite coordinate (z = nan, in face 1)");

  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 -inf 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  r = read_raw_mesh(obj, MeshFormat::kObj, "t.obj");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().message(), "t.obj: vertex 2 has a non-finite coordinate (y = -inf, in face 0)");

  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 infinity\n3 0 1 2\n";
  r = read_raw_mesh(ply, MeshFormat::kPly, "t.ply");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().message(), "t.ply: vertex 2 has a non-finite coordinate (z = inf, in face 0)");

  // Binary STL: float32 NaN in the second vertex of the first facet (vertex 1).
  std::string stl(80, '\0');
  const uint32_t one = 1;
  stl.append(reinterpret_cast<const char*>(&one), 4);
  const float coords[12] = {0, 0, 0, 0, 0, 0, 1, std::numeric_limits<float>::quiet_NaN(), 0, 0, 1, 0};
  stl.append(reinterpret_cast<const char*>(coords), sizeof coords);
  stl.append(2, '\0');
  r = read_raw_mesh(stl, MeshFormat::kStl, "t.stl");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().message(), "t.stl: vertex 1 has a non-finite coordinate (y = nan, in face 0)");
}

// Finite extremes are not refused by the readers: huge, tiny and subnormal coordinates are
// exact doubles the analysis decides on (analyze() scales the part exactly). Without that
// scaling, the LVM of a cube of side 1e100 came out as a hemisphere around (0, 0, 0), that
// of a cube of side 2^996 as a great circle around NaN, and comparing its maps looped for
// ever (the fuzz_analysis_off seeds, replayed on an engine built mid-change).
TEST(FuzzRegression, ExtremeFiniteCoordinatesAnalyzed) {
  for (const char* scale : {"1e308", "1e300", "1e150", "1e-300", "4e-323", "5e-324", "1e-12"}) {
    std::string off = "OFF\n4 4 0\n0 0 0\nS 0 0\n0 S 0\n0 0 S\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    for (size_t p; (p = off.find('S')) != std::string::npos;) off.replace(p, 1, scale);
    auto analysis = analyze_part(off, MeshFormat::kOff);
    ASSERT_TRUE(analysis.ok()) << scale << ": " << analysis.status().message();
    EXPECT_EQ(analysis->part().input_faces, 4u) << scale;
    const std::string json = to_json(to_proto(*analysis));
    EXPECT_EQ(json.find("NaN"), std::string::npos) << scale;
    EXPECT_EQ(json.find("Infinity"), std::string::npos) << scale;
    for (const Surface& f : analysis->features()) {
      ASSERT_TRUE(f.maps.gvm.has_value()) << scale;
      EXPECT_TRUE(f.maps.gvm->is_subset_of(f.maps.lvm)) << scale;
      EXPECT_EQ(f.maps.lvm.dimension(), 2) << scale << ": " << f.maps.lvm.description();
    }
  }
}

}  // namespace
}  // namespace gvm
