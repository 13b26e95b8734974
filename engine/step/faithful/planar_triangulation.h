// Triangles of a planar face from its boundary loops alone: the holes bridged to the outer
// loop, then ear clipping, every decision an exact sign of integers. The points are
// exactly coplanar grid points (lattice_placement.h) given by their integer coordinates in
// a coordinate plane the face does not project flat onto, so that the signs in that
// projection are the signs in the face's plane.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace gvm::faithful {

using Point2 = std::array<int64_t, 2>;

struct PlanarLoop {
  std::vector<uint32_t> ids;   // mesh points, in the loop's order
  std::vector<Point2> xy;      // their projected coordinates
};

// loops[0] is the outer boundary, the others holes running the other way round. Appends
// triangles whose corners follow the loops' orientation (a face counter-clockwise seen
// from outside stays so); false and `why` when the loops do not bound a polygon with holes.
bool triangulate_planar(const std::vector<PlanarLoop>& loops, std::vector<std::array<uint32_t, 3>>& out,
                        std::string& why);

}  // namespace gvm::faithful
