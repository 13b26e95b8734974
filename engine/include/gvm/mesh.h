// Reading and validating a part: a closed, oriented, manifold polyhedral solid.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gvm/geometry.h"
#include "gvm/status.h"

namespace gvm {

// The vertex and face lists exactly as the file holds them (vertices welded on exact
// coordinate equality), before any half-edge structure is built: validation runs on this
// so that every problem can be named by the input face/vertex that has it.
struct RawMesh {
  std::string source;                        // file name, for messages
  std::vector<Point3> points;
  std::vector<std::vector<uint32_t>> faces;  // input faces, input order, vertex indices
  // Named face groups found in the file (OBJ `g`), face indices into `faces`.
  std::map<std::string, std::vector<uint32_t>> groups;
};

// A validated solid. Polygonal input faces are split into triangles; every triangle
// remembers the input face it came from, and the input face numbering is the one used in
// all output.
struct SolidMesh {
  std::string source;
  std::vector<Point3> points;
  std::vector<Triangle> triangles;           // counter-clockwise seen from outside
  std::vector<uint32_t> triangle_face;       // input face index of each triangle
  uint32_t input_face_count = 0;
  // Topology: neighbor[t][i] is the triangle across edge (v[i], v[i+1 mod 3]) of t.
  std::vector<std::array<uint32_t, 3>> neighbor;
  // Shells: maximal edge-connected sets of triangles. A shell with negative signed volume
  // bounds an internal void; its faces can never be seen from outside.
  std::vector<uint32_t> shell;               // shell id of each triangle
  std::vector<bool> shell_is_void;
  std::map<std::string, std::vector<uint32_t>> groups;  // from the file, input face ids
};

// kStep is a B-rep, not a mesh: read_step (gvm/step.h) tessellates it; analyze() takes it.
enum class MeshFormat { kOff, kObj, kStl, kPly, kStep };

// "off", "obj", "stl", "ply", "stp", "step" (any case, optional leading dot); nothing
// otherwise.
std::optional<MeshFormat> parse_mesh_format(std::string_view name);

// Reads OFF, OBJ, STL (ASCII or binary) or PLY, chosen by file extension (through
// parse_mesh_format; kInvalidArgument for any other extension, kNotFound when the file
// cannot be opened), with the bytes reader below.
StatusOr<RawMesh> read_raw_mesh(const std::string& path);

// The same readers as read_raw_mesh(path), on bytes in memory; `source` names the part in
// messages (and becomes RawMesh::source). Any bytes are safe to pass: malformed,
// truncated or inconsistent input (declared counts the bytes cannot hold, a binary STL
// whose size does not match its facet count, non-finite coordinates, indices out of
// range) fails with kInvalidArgument naming the problem; only a well-formed part of more
// than 50 million faces fails with kResourceExhausted. Memory stays proportional to the
// size of the bytes.
StatusOr<RawMesh> read_raw_mesh(std::string_view bytes, MeshFormat format, const std::string& source);

// Checks the raw mesh and builds the solid. Fails with kInvalidArgument and a message
// naming the file and the first offending face, edge or vertex (input numbering) when the
// mesh is empty, has non-planar or self-overlapping polygons, zero-area or duplicate
// faces, border edges, non-manifold edges or vertices, inconsistent or inward orientation,
// or self-intersections. Planar non-convex polygons are split into triangles (ear
// clipping), every triangle keeping its input face.
StatusOr<SolidMesh> build_solid(const RawMesh& raw);

// read_raw_mesh + build_solid.
StatusOr<SolidMesh> load_solid(const std::string& path);

}  // namespace gvm
