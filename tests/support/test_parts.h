// Exact test parts with integer coordinates: small machined shapes (slot, hole, pocket,
// step, T-slot, ...) built as unions of grid cells, emitted as RawMesh (triangles, or
// quads on request) with every maximal planar face named in RawMesh::groups.
//
// Group names: semantic names where the part defines them ("floor", "wall_x0", ...), and
// otherwise "<axis><sign><coordinate>" of the face's plane in the part's own units before
// scaling/rotation, e.g. "z+8" for a face on z = 8 with outward normal +z, suffixed
// "_0", "_1", ... when several disjoint faces share a plane. The groups are disjoint and
// cover every face, so they are the exact planar-face partition of the part.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "gvm/mesh.h"

namespace gvm::test {

struct TestPartOptions {
  // 0: none; 1: M = [[3,4,0],[-4,3,0],[0,0,5]] (3-4-5 rotation about z, scaled by 5);
  // 2: Rx * M with Rx = [[5,0,0],[0,3,4],[0,-4,3]]. Both keep coordinates integer.
  int rotation = 0;
  // Split every grid quad into 4 coplanar triangles (fan from its center).
  bool split = false;
  // Emit each grid quad as one quadrilateral input face (ignored when split).
  bool quads = false;
};

// Every part is scaled by 12 so that quad centers stay integer.
RawMesh box_part(const TestPartOptions& o = {});            // 10 x 6 x 4 block
RawMesh slot_part(const TestPartOptions& o = {});           // groove along y, open ends
RawMesh grooved_slot_part(const TestPartOptions& o = {});   // the slot, a groove in both walls
RawMesh through_hole_part(const TestPartOptions& o = {});   // square hole along z
RawMesh pocket_part(const TestPartOptions& o = {});         // blind square pocket
RawMesh drafted_pocket_part(const TestPartOptions& o = {}); // walls lean out 1 in 4
RawMesh grooved_pocket_part(const TestPartOptions& o = {}); // pocket, groove round its walls
// The same, with a vertex in the middle of the groove ceiling's inner edge on x = 4 and the
// lower wall there a single quad across it (the floor's and groove floor's grid vertices
// at y = 6 on that wall moved to y = 5): rays up the wall pass that rim vertex.
RawMesh grooved_pocket_rim_vertex_part(const TestPartOptions& o = {});
// Zero clearance: walls lean out from the floor and back in to an opening (or a slot's
// mouth) exactly the floor's size; the slot optionally with a boss flush with its mouth.
RawMesh flared_pocket_part(const TestPartOptions& o = {});
RawMesh flared_slot_part(const TestPartOptions& o = {});
RawMesh flared_slot_boss_part(const TestPartOptions& o = {});
RawMesh step_part(const TestPartOptions& o = {});           // L-shaped step along y
RawMesh tslot_closed_part(const TestPartOptions& o = {});   // T-slot closed at both ends
RawMesh tslot_open_part(const TestPartOptions& o = {});     // T-slot open at both ends
RawMesh two_pockets_part(const TestPartOptions& o = {});    // plate with two pockets
RawMesh pocket_with_void_part(const TestPartOptions& o = {}); // pocket + internal cubic void
// A 16 x 12 x 10 block with a through hole along x (hole_*), a pocket from +z
// (pocket_*) and a slot along y (slot_*): the planner's hand-derived case.
RawMesh machined_block_part(const TestPartOptions& o = {});

// Where the part's rotation (TestPartOptions::rotation) takes a point or direction, exactly.
Point3 rotated(const TestPartOptions& o, const Point3& p);

struct NamedTestPart {
  std::string name;
  RawMesh (*make)(const TestPartOptions&);
};
std::vector<NamedTestPart> all_test_parts();

// Input faces of the named groups (ascending); fails a test assertion-free way: unknown
// names contribute nothing.
std::vector<uint32_t> faces_of(const RawMesh& raw, std::initializer_list<std::string> names);

// Triangles (of a SolidMesh built from the raw mesh) whose input face is in `faces`.
std::vector<uint32_t> triangles_of_faces(const SolidMesh& mesh, const std::vector<uint32_t>& faces);
std::vector<uint32_t> triangles_of(const SolidMesh& mesh, const RawMesh& raw,
                                   std::initializer_list<std::string> names);

}  // namespace gvm::test
