// Local visibility map (paper Sec. 2, Def. 1 and Prop. 1), exactly:
//   LVM(S) = { u : u . n_i >= 0 for every face normal n_i }   (closed).
// Equivalently the dual of the spherical convex hull of the normals; empty when the normals
// are not in a closed hemisphere (only u = 0 satisfies every constraint).
//
// Every outcome gets its own cell type: full sphere (no normals), hemisphere (one normal
// direction), great circle (two antipodal directions only), lune (normals spanning a
// plane, positive hull pointed), half great circle with antipodal endpoints (normals in a
// plane, positive hull a half plane), two antipodal points (normals in a plane whose
// positive hull is the plane), convex polygon, arc shorter than 180 degrees, point, empty
// (normals spanning space). Vertices are exact cross products of normals (or of a normal
// and the cross product of two normals in the planar cases); circle normals are input
// normals or such cross products.
#pragma once

#include <span>

#include "exact/exact_vec.h"
#include "sphere/spherical_image.h"

namespace gvm::sphere {

// Zero normals (degenerate faces) constrain nothing and are ignored; equal directions are
// deduplicated.
SphericalImage local_visibility_map(std::span<const exact::ExactVec> normals);

// True iff n lies in the closed spherical convex hull of the normals, i.e. in the closed
// cone they span (the whole space when they are not in a closed hemisphere). Equivalent
// to local_visibility_map(normals).within_closed_hemisphere(n) (paper Property 2).
bool in_spherical_convex_hull(std::span<const exact::ExactVec> normals, const exact::ExactVec& n);

}  // namespace gvm::sphere
