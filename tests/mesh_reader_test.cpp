// Reading meshes: exact coordinates in every format, groups, welding, reader errors.
#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "gvm/mesh.h"
#include "support/assertions.h"
#include "support/openmesh_recording_importer.h"
#include "support/scratch_dir.h"

namespace gvm {
namespace {

namespace fs = std::filesystem;
using test::Has;

std::string write(const std::string& name, const std::string& text) {
  fs::path p = test::scratch_dir() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

// A box with the corner coordinates below; every value must come back bit-exactly.
const double X0 = 1e-300, X1 = 0.1, Y0 = 1e-12, Y1 = 1.000000000001, Z0 = 0, Z1 = 1e12;
const char* kX0 = "1e-300";
const char* kX1 = "0.1000000000000000055511151231257827";
const char* kY0 = "1e-12";
const char* kY1 = "1.000000000001";
const char* kZ0 = "0";
const char* kZ1 = "1e12";

// Vertices 0..7: bit 0 -> x, bit 1 -> y, bit 2 -> z. Outward quads.
const int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                          {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};

std::string vtx(int i) {
  return std::string(i & 1 ? kX1 : kX0) + " " + (i & 2 ? kY1 : kY0) + " " + (i & 4 ? kZ1 : kZ0);
}
Point3 pt(int i) { return {i & 1 ? X1 : X0, i & 2 ? Y1 : Y0, i & 4 ? Z1 : Z0}; }

void expect_box_points(const std::vector<Point3>& p) {
  ASSERT_EQ(p.size(), 8u);
  for (int i = 0; i < 8; ++i) {
    // bit-exact comparison (operator== would also accept -0 for 0)
    EXPECT_EQ(std::bit_cast<uint64_t>(p[i].x), std::bit_cast<uint64_t>(pt(i).x)) << i;
    EXPECT_EQ(std::bit_cast<uint64_t>(p[i].y), std::bit_cast<uint64_t>(pt(i).y)) << i;
    EXPECT_EQ(std::bit_cast<uint64_t>(p[i].z), std::bit_cast<uint64_t>(pt(i).z)) << i;
  }
}

std::string box_off() {
  std::string s = "OFF\n# a box\n8 6 0\n";
  for (int i = 0; i < 8; ++i) s += vtx(i) + "\n";
  for (auto& q : kQuads) s += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " +
                              std::to_string(q[2]) + " " + std::to_string(q[3]) + "\n";
  return s;
}

TEST(MeshReader, OffQuadsExactCoordinates) {
  auto path = write("box.off", box_off());
  auto raw = read_raw_mesh(path);
  ASSERT_TRUE(raw.ok()) << raw.status().message();
  expect_box_points(raw->points);
  ASSERT_EQ(raw->faces.size(), 6u);
  EXPECT_EQ(raw->faces[0], (std::vector<uint32_t>{0, 2, 3, 1}));
  auto solid = load_solid(path);
  ASSERT_TRUE(solid.ok()) << solid.status().message();
  EXPECT_EQ(solid->triangles.size(), 12u);
  EXPECT_EQ(solid->input_face_count, 6u);
  for (uint32_t t = 0; t < 12; ++t) EXPECT_EQ(solid->triangle_face[t], t / 2);
}

TEST(MeshReader, ObjGroupsAndExactCoordinates) {
  std::string s = "# box\n";
  for (int i = 0; i < 8; ++i) s += "v " + vtx(i) + "\n";
  s += "g bottom\n";
  auto face = [&](int k) {
    std::string f = "f";
    for (int v : kQuads[k]) f.append(" ").append(std::to_string(v + 1)).append("//1");
    return f + "\n";
  };
  s += face(0);
  s += "g top\n" + face(1);
  s += "g sides walls\n" + face(2) + face(3) + face(4);
  s += "g\n";
  // negative (relative) indices
  s += "f -7 -5 -1 -3\n";
  auto path = write("box.obj", s);
  auto raw = read_raw_mesh(path);
  ASSERT_TRUE(raw.ok()) << raw.status().message();
  expect_box_points(raw->points);
  ASSERT_EQ(raw->faces.size(), 6u);
  EXPECT_EQ(raw->faces[5], (std::vector<uint32_t>{1, 3, 7, 5}));
  EXPECT_EQ(raw->groups.at("bottom"), (std::vector<uint32_t>{0}));
  EXPECT_EQ(raw->groups.at("top"), (std::vector<uint32_t>{1}));
  EXPECT_EQ(raw->groups.at("sides"), (std::vector<uint32_t>{2, 3, 4}));
  EXPECT_EQ(raw->groups.at("walls"), (std::vector<uint32_t>{2, 3, 4}));
  EXPECT_EQ(raw->groups.size(), 4u);
  auto solid = build_solid(*raw);
  ASSERT_TRUE(solid.ok()) << solid.status().message();
  EXPECT_EQ(solid->groups, raw->groups);
}

TEST(MeshReader, AsciiStlWeldsAndKeepsDoubles) {
  std::string s = "solid box\n";
  for (auto& q : kQuads) {
    for (int tri = 0; tri < 2; ++tri) {
      int v[3] = {q[0], q[1 + tri], q[2 + tri]};
      s += "  facet normal 0 0 0\n    outer loop\n";
      for (int k : v) s += "      vertex " + vtx(k) + "\n";
      s += "    endloop\n  endfacet\n";
    }
  }
  s += "endsolid box\n";
  auto path = write("box.stl", s);
  auto raw = read_raw_mesh(path);
  ASSERT_TRUE(raw.ok()) << raw.status().message();
  ASSERT_EQ(raw->faces.size(), 12u);
  ASSERT_EQ(raw->points.size(), 8u);  // 36 facet corners welded to 8 points
  // First-occurrence order: 0 2 3 1 from the first quad, then 4 5 7 6.
  const int order[8] = {0, 2, 3, 1, 4, 5, 7, 6};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(raw->points[i], pt(order[i]));
  EXPECT_EQ(std::bit_cast<uint64_t>(raw->points[0].x), std::bit_cast<uint64_t>(1e-300));
  auto solid = build_solid(*raw);
  ASSERT_TRUE(solid.ok()) << solid.status().message();
}

TEST(MeshReader, BinaryStlWithSolidHeader) {
  auto raw = read_raw_mesh(GVM_SHARED_DIR "/data/parts/trimesh_plate_holes.STL");
  ASSERT_TRUE(raw.ok()) << raw.status().message();
  EXPECT_EQ(raw->faces.size(), 1252u);
  EXPECT_EQ(raw->points.size(), 618u);
}

TEST(MeshReader, PlyAsciiAndBinaryExact) {
  std::string head =
      "ply\nformat %s 1.0\ncomment box\nelement vertex 8\nproperty double x\n"
      "property double y\nproperty double z\nproperty uchar red\nelement face 6\n"
      "property list uchar int vertex_indices\nend_header\n";
  auto header = [&](const char* fmt) {
    std::string h = head;
    h.replace(h.find("%s"), 2, fmt);
    return h;
  };
  std::string a = header("ascii");
  for (int i = 0; i < 8; ++i) a += vtx(i) + " 255\n";
  for (auto& q : kQuads) a += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " +
                              std::to_string(q[2]) + " " + std::to_string(q[3]) + "\n";
  std::string b = header("binary_little_endian");
  for (int i = 0; i < 8; ++i) {
    Point3 p = pt(i);
    double c[3] = {p.x, p.y, p.z};
    b.append(reinterpret_cast<const char*>(c), 24);
    b.push_back(char(7));
  }
  for (auto& q : kQuads) {
    b.push_back(char(4));
    for (int v : q) {
      int32_t x = v;
      b.append(reinterpret_cast<const char*>(&x), 4);
    }
  }
  for (auto [name, text] : {std::pair{"a.ply", a}, std::pair{"b.ply", b}}) {
    auto path = write(name, text);
    auto raw = read_raw_mesh(path);
    ASSERT_TRUE(raw.ok()) << raw.status().message();
    expect_box_points(raw->points);
    ASSERT_EQ(raw->faces.size(), 6u);
    EXPECT_EQ(raw->faces[5], (std::vector<uint32_t>{1, 3, 7, 5}));
    EXPECT_TRUE(load_solid(path).ok()) << name;
  }
}

TEST(MeshReader, OffWeldsEqualVertices) {
  // Vertex 8 repeats vertex 0: faces are renumbered onto the first occurrence.
  std::string s = box_off();
  s.replace(s.find("8 6 0"), 5, "9 6 0");
  s.insert(s.find("4 0 2 3 1"), vtx(0) + "\n");
  s.replace(s.find("4 0 2 3 1"), 9, "4 8 2 3 1");
  auto raw = read_raw_mesh(write("weld.off", s));
  ASSERT_TRUE(raw.ok()) << raw.status().message();
  EXPECT_EQ(raw->points.size(), 8u);
  EXPECT_EQ(raw->faces[0], (std::vector<uint32_t>{0, 2, 3, 1}));
}

TEST(MeshReader, Errors) {
  auto missing = read_raw_mesh("/nonexistent/dir/part.stl");
  EXPECT_EQ(missing.status().code(), StatusCode::kNotFound);
  EXPECT_TRUE(Has(missing.status().message(), "/nonexistent/dir/part.stl"));

  auto ext = read_raw_mesh(write("part.xyz", "hello"));
  EXPECT_EQ(ext.status().code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Has(ext.status().message(), "unknown mesh file extension"));
  EXPECT_TRUE(Has(ext.status().message(), "part.xyz"));

  auto empty = read_raw_mesh(write("empty.off", ""));
  EXPECT_EQ(empty.status().code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Has(empty.status().message(), "empty file"));

  auto noface = read_raw_mesh(write("noface.obj", "v 0 0 0\nv 1 0 0\n"));
  EXPECT_EQ(noface.status().code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Has(noface.status().message(), "no faces"));

  auto garbage = read_raw_mesh(write("garbage.stl", "this is not an stl file"));
  EXPECT_EQ(garbage.status().code(), StatusCode::kInvalidArgument);

  std::string nan = box_off();
  nan.replace(nan.find(vtx(3)), vtx(3).size(), "nan 0 1");
  auto n = read_raw_mesh(write("nan.off", nan));
  EXPECT_EQ(n.status().code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Has(n.status().message(), "vertex 3 has a non-finite coordinate"));

  std::string inf = box_off();
  inf.replace(inf.find(vtx(5)), vtx(5).size(), "0 inf 1");
  EXPECT_EQ(read_raw_mesh(write("inf.off", inf)).status().code(), StatusCode::kInvalidArgument);

  // A count the bytes cannot hold is an inconsistent file (kResourceExhausted is for a
  // well-formed part above the limit).
  auto huge = read_raw_mesh(write("huge.off", "OFF\n3 60000000 0\n0 0 0\n1 0 0\n0 1 0\n"));
  EXPECT_EQ(huge.status().code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Has(huge.status().message(), "declares 3 vertices and 60000000 faces"));

  auto range = read_raw_mesh(write("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"));
  EXPECT_EQ(range.status().code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(Has(range.status().message(), "face 0 refers to vertex 7"));

  // Binary STL claiming more facets than the file holds is not binary and not ASCII.
  std::string bin(84, '\0');
  uint32_t cnt = 1000;
  std::memcpy(bin.data() + 80, &cnt, 4);
  EXPECT_EQ(read_raw_mesh(write("short.stl", bin)).status().code(), StatusCode::kInvalidArgument);
}

// Documents why the readers are our own: OpenMesh 9 hands every ASCII format to the
// importer as floats (and drops faces). If this starts failing, OpenMesh changed.
TEST(MeshReader, OpenMeshReadersDeliverFloatsOnly) {
  auto path = write("om.off", "OFF\n3 2 0\n0.1 1e-300 1e12\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 1\n");
  mesh_internal::RawImporter imp;
  OpenMesh::IO::Options opt;
  ASSERT_TRUE(OpenMesh::IO::IOManager().read(path, imp, opt));
  ASSERT_EQ(imp.points.size(), 3u);
  EXPECT_TRUE(imp.float_vertex_seen);
  EXPECT_EQ(imp.points[0].x, double(0.1f));
  EXPECT_NE(imp.points[0].x, 0.1);
  EXPECT_EQ(imp.points[0].y, 0.0);
  auto ours = read_raw_mesh(path);
  ASSERT_TRUE(ours.ok());
  EXPECT_EQ(ours->points[0].x, 0.1);
  EXPECT_EQ(ours->points[0].y, 1e-300);
  EXPECT_EQ(ours->faces.size(), 2u);  // the repeated-index face is kept for validation
}

}  // namespace
}  // namespace gvm
