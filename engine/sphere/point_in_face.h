// Exact membership of a direction in a general 2-cell (any loops, holes, non-convex).
#pragma once

#include "sphere/spherical_image.h"

namespace gvm::sphere {

// True iff u lies in the closed region to the left of every loop of `f`.
bool point_in_face(const Face& f, const exact::ExactVec& u);

}  // namespace gvm::sphere
