// Exact directions inside the cells of an arrangement: what the coverage overlay hands out
// as witnesses, so that a caller can test, probe or plan along a direction that has
// exactly the cell's coverage.
#pragma once

#include <cstdint>

#include "exact/exact_vec.h"
#include "sphere/arrangement.h"

namespace gvm::sphere {

// A direction strictly inside edge e (on its circle, off both ends): the sum of its end
// vectors, a positive combination of the ends of a minor arc.
exact::ExactVec direction_inside_edge(const Arrangement& arr, uint32_t e);

// A direction strictly inside face f (on no edge and no vertex of the arrangement).
exact::ExactVec direction_inside_face(const Arrangement& arr, uint32_t f);

}  // namespace gvm::sphere
