// Envelope faces that cannot change the occluded directions, left out before the unions.
//
// Only the union of the projected faces matters (its closure is the closure of the
// occluded directions), and the projection of a Minkowski envelope is mostly small faces
// (vertex-face and edge-edge sums) lying inside large ones (a face of O seen from a
// vertex of S). A face that lies inside the union of the largest faces, which are all
// kept, changes nothing in that union.
//
// The test is conservative and certified: the sphere is cut into the cells of a cube-map
// grid (cells bounded by great circles, so convex); a cell counts as covered when its
// four corners lie inside one large face, decided in double precision with a slack far
// above the rounding of the estimates (as direction_window.h decides); a small face is
// redundant when the cells of a rectangle of the grid certainly holding it are all
// covered. A face that straddles two cube faces, or anything the doubles cannot decide,
// is kept.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "exact/exact_vec.h"

namespace gvm {

// faces[i]: the vertices of a projected face, a convex polygon counter-clockwise around
// its inside, inside an open hemisphere. Returns a mask of the faces that can be left out.
std::vector<uint8_t> redundant_faces(std::span<const std::vector<exact::ExactVec>> faces);

}  // namespace gvm
