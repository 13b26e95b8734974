// Exact triangle-triangle intersection and the self-intersection search of a mesh.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "gvm/geometry.h"

namespace gvm::mesh_internal {

// Closed segment ab against closed non-degenerate triangle pqr.
bool segment_meets_triangle(const Point3& a, const Point3& b, const Point3& p, const Point3& q,
                            const Point3& r);

// Closed non-degenerate triangles: do they have a point in common?
bool triangles_meet(const Point3 t[3], const Point3 u[3]);

// Whether triangles t and u (vertex indices into P) intersect other than in what their
// shared vertex indices allow: a shared edge may only be met along that edge, a shared
// vertex only at that vertex.
bool improper_contact(const std::vector<Point3>& P, const Triangle& t, const Triangle& u);

// One pair of input faces whose triangles intersect improperly (triangles of the same face
// are not compared), or nothing. Broad phase: uniform grid on bounding boxes.
std::optional<std::pair<uint32_t, uint32_t>> find_self_intersection(
    const std::vector<Point3>& P, const std::vector<Triangle>& tris,
    const std::vector<uint32_t>& tri_face);

// Closed 2D segments ab and cd have a common point, in the projection dropping axis `drop`.
bool seg_seg_2d(const Point3& a, const Point3& b, const Point3& c, const Point3& d, int drop);

}  // namespace gvm::mesh_internal
