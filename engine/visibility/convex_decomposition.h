// The baseline the paper compares with (its reference [18]): Phi(O + (-S)) as the union of
// the pairwise occlusion maps Phi(F_O + (-F_S)) of every triangle F_S of S and F_O of O.
//
// F_O + (-F_S) is the convex hull of the nine differences q - p of their vertices, so its
// map is the set of directions of the cone they span (zero differences, at a vertex the
// two share, span nothing). That cone is the dual of LVM(differences): a convex polygon
// when the LVM is one, a lune when it is an arc, a hemisphere when it is a point, the
// whole sphere when it is empty (the triangles touch around the origin). Other cones are
// planar or thinner: such maps have no interior and cannot change Int(GOM), since the
// other maps are closed (a closed set's interior does not grow by adding a nowhere dense
// set), so they are left out.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "exact/exact_vec.h"
#include "gvm/mesh.h"
#include "sphere/spherical_image.h"

namespace gvm {

class DirectionWindow;

struct ConvexDecompositionStatistics {
  uint64_t pairs = 0;           // triangle pairs (F_S, F_O) examined
  uint64_t outside_window = 0;  // of those, left out: their directions miss the window
  uint64_t maps = 0;            // pairwise occlusion maps with interior
  uint64_t map_arcs = 0;        // their boundary arcs (#GOM in the paper's Table 2)
};

// The map of one pair, from the differences q - p: a convex 2-cell, the whole sphere,
// or empty when it has no interior.
sphere::SphericalImage pairwise_occlusion_map(std::span<const exact::ExactVec> differences);

// The maps with interior of every pair, in a fixed order (S-major). With a window,
// pairs whose directions certainly miss it are left out (see direction_window.h).
std::vector<sphere::SphericalImage> pairwise_occlusion_maps(
    const SolidMesh& mesh, std::span<const uint32_t> s, std::span<const uint32_t> o,
    const DirectionWindow* window, ConvexDecompositionStatistics* stats);

}  // namespace gvm
