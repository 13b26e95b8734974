// Exact 3D convex hull of a point set (randomized incremental construction with conflict
// lists). Every decision is an exact orient3d; a point on the plane of a hull facet is not
// outside it, so coplanar points never become hull vertices unless needed, and the hull
// may have coplanar adjacent facets (it is a triangulation of the hull boundary).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "gvm/geometry.h"

namespace gvm::part {

struct ConvexHull {
  // Facets, counter-clockwise seen from outside: every input point is on the closed
  // negative side of every facet.
  std::vector<Triangle> facets;
  // Vertex graph of the hull (CSR over input point indices): neighbors of point p are
  // adjacency[offset[p] .. offset[p+1]); empty for points that are not hull vertices.
  std::vector<uint32_t> offset;
  std::vector<uint32_t> adjacency;
  // One facet incident to each hull vertex (index into facets), kNone-like max otherwise.
  std::vector<uint32_t> vertex_facet;
  uint32_t any_vertex = 0;
};

// `use` selects the points taking part (e.g. those referenced by triangles). Returns an
// empty hull when the selected points are coplanar (no solid can be bounded by them).
ConvexHull convex_hull(std::span<const Point3> points, std::span<const uint32_t> use);

// The point among the hull vertices maximizing the linear function x -> n . x with
// n = (b - a) x (c - a), found by exact hill climbing on the hull graph from `start`
// (a hull vertex). On a convex polytope an extreme vertex without an improving neighbor
// is a global maximum; a hull vertex may also lie inside a flat face (it was extreme when
// inserted), where all neighbors tie: if that face is the minimal one, the climb walks
// the face's vertices to leave it.
uint32_t hull_extreme_vertex(const ConvexHull& hull, std::span<const Point3> points,
                             const Point3& a, const Point3& b, const Point3& c,
                             uint32_t start);

}  // namespace gvm::part
