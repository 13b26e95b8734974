// Triangles of a ruled face (a cylinder, a cone, an extrusion) between its rulings: every
// triangle has two corners on one ruling, so that, once the points of each ruling are on
// one line parallel to the axis (lattice_placement.h), every facet contains the axis
// direction exactly -- the facets of a hole's wall are parallel to its axis.
//
// The face is given in its (u, v) parameters, u across the rulings (the angle of a
// cylinder), v along them, by the points of its boundary: each point's ruling (an index
// into the face's rulings, in increasing u) and its v. Every boundary segment must join
// two neighbouring rulings or run along one (the caller inserts points where a segment
// would skip one). Between two neighbouring rulings the face is then a set of cells, each
// bounded by one boundary segment below, one above, and the boundary points on the two
// rulings between them; each cell is cut into a ladder of triangles.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace gvm::faithful {

struct StripPoint {
  uint32_t id = 0;      // the mesh point
  uint32_t ruling = 0;  // index of its ruling, 0 .. rulings - 1
  double v = 0;         // along the ruling
};

// loops: the face's boundary loops, each closed (its last point joins its first), the face
// on their left in (u, v) (u to the right, v up). Appends to `out` triangles that are
// counter-clockwise in (u, v); false and `why` when the boundary is not of that form.
bool ruled_strips(const std::vector<std::vector<StripPoint>>& loops, uint32_t rulings,
                  std::vector<std::array<uint32_t, 3>>& out, std::string& why);

}  // namespace gvm::faithful
