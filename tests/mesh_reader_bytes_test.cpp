// Reading parts from memory: the same RawMesh as from the file in every format, and
// hostile bytes (truncated, random, inconsistent counts, non-finite coordinates) refused
// with kInvalidArgument and a message, never a crash, a hang or a giant allocation (these
// also run under the asan preset).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "gvm/mesh.h"
#include "support/scratch_dir.h"
#include "support/test_parts.h"

namespace gvm {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string write(const std::string& name, const std::string& bytes) {
  const fs::path p = test::scratch_dir() / name;
  std::ofstream(p, std::ios::binary) << bytes;
  return p.string();
}

std::string shared_part(const std::string& name) {
  return std::string(GVM_SHARED_DIR) + "/data/parts/" + name;
}

// A small exact part in every format (each face a triangle, so that STL can hold it).
RawMesh triangulated(RawMesh raw) {
  std::vector<std::vector<uint32_t>> faces;
  for (const auto& f : raw.faces) {
    for (size_t k = 1; k + 1 < f.size(); ++k) faces.push_back({f[0], f[k], f[k + 1]});
  }
  raw.faces = std::move(faces);
  raw.groups.clear();
  return raw;
}

std::string as_off(const RawMesh& m) {
  std::ostringstream o;
  o.precision(17);
  o << "OFF\n" << m.points.size() << " " << m.faces.size() << " 0\n";
  for (const Point3& p : m.points) o << p.x << " " << p.y << " " << p.z << "\n";
  for (const auto& f : m.faces) {
    o << f.size();
    for (uint32_t v : f) o << " " << v;
    o << "\n";
  }
  return o.str();
}

std::string as_obj(const RawMesh& m) {
  std::ostringstream o;
  o.precision(17);
  for (const Point3& p : m.points) o << "v " << p.x << " " << p.y << " " << p.z << "\n";
  o << "g part\n";
  for (const auto& f : m.faces) {
    o << "f";
    for (uint32_t v : f) o << " " << v + 1;
    o << "\n";
  }
  return o.str();
}

std::string as_ascii_stl(const RawMesh& m) {
  std::ostringstream o;
  o.precision(9);
  o << "solid part\n";
  for (const auto& f : m.faces) {
    o << "facet normal 0 0 0\nouter loop\n";
    for (uint32_t v : f) o << "vertex " << float(m.points[v].x) << " " << float(m.points[v].y) << " " << float(m.points[v].z) << "\n";
    o << "endloop\nendfacet\n";
  }
  o << "endsolid part\n";
  return o.str();
}

std::string as_ply(const RawMesh& m, bool binary) {
  std::ostringstream o;
  o.precision(17);
  o << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
    << "element vertex " << m.points.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
    << "element face " << m.faces.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Point3& p : m.points) {
    if (binary) {
      o.write(reinterpret_cast<const char*>(&p.x), 8);
      o.write(reinterpret_cast<const char*>(&p.y), 8);
      o.write(reinterpret_cast<const char*>(&p.z), 8);
    } else {
      o << p.x << " " << p.y << " " << p.z << "\n";
    }
  }
  for (const auto& f : m.faces) {
    if (binary) {
      const auto n = static_cast<unsigned char>(f.size());
      o.write(reinterpret_cast<const char*>(&n), 1);
      for (uint32_t v : f) {
        const auto i = static_cast<int32_t>(v);
        o.write(reinterpret_cast<const char*>(&i), 4);
      }
    } else {
      o << f.size();
      for (uint32_t v : f) o << " " << v;
      o << "\n";
    }
  }
  return o.str();
}

struct Sample {
  std::string path;
  MeshFormat format;
};

// Files of every format: shared parts as they are, and a test part written out.
const std::vector<Sample>& samples() {
  static const std::vector<Sample> out = [] {
    const RawMesh pocket = triangulated(test::pocket_part());
    return std::vector<Sample>{
        {shared_part("trimesh_7_8ths_cube.stl"), MeshFormat::kStl},  // binary STL
        {shared_part("prusa_plug-aligner.stl"), MeshFormat::kStl},
        {shared_part("occt_brep_mal_tige.off"), MeshFormat::kOff},
        {std::string(GVM_TEST_DATA_DIR) + "/featuretype.off", MeshFormat::kOff},
        {write("pocket.off", as_off(pocket)), MeshFormat::kOff},
        {write("pocket.obj", as_obj(pocket)), MeshFormat::kObj},
        {write("pocket.stl", as_ascii_stl(pocket)), MeshFormat::kStl},
        {write("pocket.ply", as_ply(pocket, false)), MeshFormat::kPly},
        {write("pocket_binary.PLY", as_ply(pocket, true)), MeshFormat::kPly},
    };
  }();
  return out;
}

void expect_same(const RawMesh& a, const RawMesh& b) {
  EXPECT_EQ(a.source, b.source);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(std::memcmp(&a.points[i], &b.points[i], sizeof(Point3)), 0) << "vertex " << i;
  }
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.groups, b.groups);
}

TEST(MeshReaderBytes, ParseMeshFormat) {
  EXPECT_EQ(parse_mesh_format("off"), MeshFormat::kOff);
  EXPECT_EQ(parse_mesh_format(".OBJ"), MeshFormat::kObj);
  EXPECT_EQ(parse_mesh_format("Stl"), MeshFormat::kStl);
  EXPECT_EQ(parse_mesh_format(".ply"), MeshFormat::kPly);
  EXPECT_EQ(parse_mesh_format("step"), MeshFormat::kStep);
  EXPECT_EQ(parse_mesh_format(".STP"), MeshFormat::kStep);
  for (const char* bad : {"", ".", "st", "stla", "..stl", "steps", "x.stl", " stl", "igs"}) {
    EXPECT_FALSE(parse_mesh_format(bad).has_value()) << bad;
  }
}

TEST(MeshReaderBytes, SameAsFromTheFile) {
  for (const Sample& s : samples()) {
    SCOPED_TRACE(s.path);
    auto from_file = read_raw_mesh(s.path);
    ASSERT_TRUE(from_file.ok()) << from_file.status().message();
    auto from_bytes = read_raw_mesh(slurp(s.path), s.format, s.path);
    ASSERT_TRUE(from_bytes.ok()) << from_bytes.status().message();
    expect_same(*from_file, *from_bytes);
    EXPECT_TRUE(build_solid(*from_bytes).ok());
  }
}

TEST(MeshReaderBytes, PathErrorsKept) {
  auto unknown = read_raw_mesh(write("part.igs", "solid x\n"));
  EXPECT_EQ(unknown.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(unknown.status().message().find("unknown mesh file extension 'igs'"), std::string::npos);
  // A STEP file is a B-rep: analyze() reads it with read_step, the mesh reader says so.
  auto step = read_raw_mesh(write("part.step", "ISO-10303-21;\n"));
  EXPECT_EQ(step.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(step.status().message().find("read_step"), std::string::npos) << step.status().message();
  EXPECT_EQ(read_raw_mesh("/nonexistent/part.stl").status().code(), StatusCode::kNotFound);
  auto empty = read_raw_mesh("", MeshFormat::kObj, "memory part");
  EXPECT_EQ(empty.status().code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(empty.status().message(), "memory part: empty file");
}

// Every prefix either fails with kInvalidArgument naming the source, or reads as a mesh
// that validation refuses (a cut at a line end of OBJ or ASCII STL is a smaller file), or
// is the whole mesh (only trailing blanks cut).
TEST(MeshReaderBytes, TruncatedAtManyCutPoints) {
  for (const Sample& s : samples()) {
    SCOPED_TRACE(s.path);
    const std::string bytes = slurp(s.path);
    auto full = read_raw_mesh(bytes, s.format, "cut");
    ASSERT_TRUE(full.ok());
    std::vector<size_t> cuts;
    for (size_t c = 0; c < std::min<size_t>(bytes.size(), 200); ++c) cuts.push_back(c);
    for (size_t k = 0; k < 300; ++k) cuts.push_back(bytes.size() * k / 300);
    for (size_t c = bytes.size() > 100 ? bytes.size() - 100 : 0; c < bytes.size(); ++c) cuts.push_back(c);
    for (size_t cut : cuts) {
      auto r = read_raw_mesh(std::string_view(bytes).substr(0, cut), s.format, "cut");
      if (!r.ok()) {
        EXPECT_EQ(r.status().code(), StatusCode::kInvalidArgument) << "cut " << cut << ": " << r.status().message();
        EXPECT_EQ(r.status().message().rfind("cut: ", 0), 0u) << r.status().message();
        continue;
      }
      if (r->points == full->points && r->faces == full->faces) continue;
      auto solid = build_solid(*r);
      EXPECT_FALSE(solid.ok()) << "cut " << cut << " of " << bytes.size() << " gives a valid part";
      if (!solid.ok()) EXPECT_EQ(solid.status().code(), StatusCode::kInvalidArgument);
    }
  }
}

TEST(MeshReaderBytes, RandomBytes) {
  const uint32_t seed = 20240611;
  std::mt19937 rng(seed);
  const std::vector<std::string> prefixes = {
      "", "solid ", "OFF\n", "OFF\n3 1 0\n", "ply\nformat ascii 1.0\n",
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar uint vertex_indices\nend_header\n",
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf "};
  const char alphabet[] = "0123456789 .-+e\nvfOFFsolidfacetvertexendfacet";
  for (int i = 0; i < 600; ++i) {
    const MeshFormat format = static_cast<MeshFormat>(i % 4);
    std::string bytes = prefixes[size_t(i / 4) % prefixes.size()];
    const size_t n = rng() % 2048;
    const bool text = i % 3 == 0;
    for (size_t k = 0; k < n; ++k) {
      bytes.push_back(text ? alphabet[rng() % (sizeof(alphabet) - 1)] : static_cast<char>(rng() & 0xff));
    }
    auto r = read_raw_mesh(bytes, format, "random");
    if (r.ok()) continue;  // a few random texts are meshes; build_solid decides those
    EXPECT_EQ(r.status().code(), StatusCode::kInvalidArgument)
        << "seed " << seed << " case " << i << ": " << r.status().message();
    EXPECT_FALSE(r.status().message().empty());
  }
}

std::string binary_stl_header(uint32_t count) {
  std::string s(80, ' ');
  s.append(reinterpret_cast<const char*>(&count), 4);
  return s;
}

void expect_invalid(const StatusOr<RawMesh>& r, const std::string& words) {
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), StatusCode::kInvalidArgument) << r.status().message();
  EXPECT_NE(r.status().message().find(words), std::string::npos) << r.status().message();
}

TEST(MeshReaderBytes, HugeDeclaredCounts) {
  // Binary STL whose count does not match its size (and no 'solid'): named, nothing reserved.
  std::string stl = binary_stl_header(0xFFFFFFFFu) + std::string(50, '\0');
  expect_invalid(read_raw_mesh(stl, MeshFormat::kStl, "huge.stl"), "declares 4294967295 facets");
  expect_invalid(read_raw_mesh(binary_stl_header(1000000) + std::string(500, '\0'), MeshFormat::kStl, "s"),
                 "declares 1000000 facets");
  expect_invalid(read_raw_mesh(binary_stl_header(1), MeshFormat::kStl, "s"), "declares 1 facets");
  expect_invalid(read_raw_mesh(std::string(40, '\1'), MeshFormat::kStl, "short"), "shorter than the 84-byte header");
  // OFF declaring billions of vertices or faces in a few bytes.
  expect_invalid(read_raw_mesh("OFF\n4000000000 1 0\n0 0 0\n", MeshFormat::kOff, "o"), "declares 4000000000 vertices");
  expect_invalid(read_raw_mesh("OFF\n3 18446744073709551615 0\n0 0 0\n1 0 0\n0 1 0\n", MeshFormat::kOff, "o"),
                 "more than the");
  expect_invalid(read_raw_mesh("OFF\n3 99999999999999999999999 0\n", MeshFormat::kOff, "o"), "bad OFF counts line");
  // OFF face with a huge vertex count on a short line.
  expect_invalid(read_raw_mesh("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4294967295 0 1 2\n", MeshFormat::kOff, "o"),
                 "bad face 0");
  // PLY elements and list lengths the bytes cannot hold.
  const std::string ply_head = "ply\nformat binary_little_endian 1.0\nelement vertex 18446744073709551615\n"
                               "property float x\nproperty float y\nproperty float z\nend_header\n";
  expect_invalid(read_raw_mesh(ply_head + std::string(24, '\0'), MeshFormat::kPly, "p"),
                 "declares 18446744073709551615 elements 'vertex'");
  const std::string ply_list =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uint uint vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1e300 0 1 2\n";
  expect_invalid(read_raw_mesh(ply_list, MeshFormat::kPly, "p"), "bad PLY list length");
  // An element without properties holds no data whatever its count: no loop over it.
  const std::string ply_empty_element =
      "ply\nformat ascii 1.0\nelement junk 18446744073709551615\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  auto r = read_raw_mesh(ply_empty_element, MeshFormat::kPly, "p");
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r->faces.size(), 1u);
  // ASCII STL ending inside a facet.
  expect_invalid(read_raw_mesh("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", MeshFormat::kStl, "a"),
                 "ends inside facet 0");
}

TEST(MeshReaderBytes, NonFiniteCoordinates) {
  for (const char* value : {"nan", "inf", "-inf", "1e999"}) {
    const std::string off = std::string("OFF\n3 1 0\n0 0 0\n1 0 0\n0 ") + value + " 0\n3 0 1 2\n";
    auto r = read_raw_mesh(off, MeshFormat::kOff, "nf.off");
    if (std::string(value) == "1e999") {
      expect_invalid(r, "bad coordinates for vertex 2");  // out of range for from_chars
    } else {
      expect_invalid(r, "vertex 2 has a non-finite coordinate");
    }
  }
  std::string stl = binary_stl_header(1) + std::string(12, '\0');
  const float coords[9] = {0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0};
  stl.append(reinterpret_cast<const char*>(coords), sizeof(coords));
  stl.append(2, '\0');
  expect_invalid(read_raw_mesh(stl, MeshFormat::kStl, "nan.stl"), "non-finite coordinate");
}

}  // namespace
}  // namespace gvm
