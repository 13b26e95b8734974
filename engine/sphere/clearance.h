// Caps of directions inside closed sets: the clearance of a tool or probe direction. The
// closed cap of half-angle theta around c is {u : angle(u, c) <= theta}; theta is given by
// s2 = sin^2(theta), 0 <= s2 <= 1 (theta at most 90 degrees), a double taken exactly.
#pragma once

#include <array>

#include "exact/exact_vec.h"
#include "sphere/spherical_image.h"

namespace gvm::sphere {

// True iff the closed cap around `center` (non-zero) lies in the set: `center` is in a
// 2-cell and no boundary arc of that 2-cell comes closer than theta (exact: every
// comparison is a sign of a polynomial in the exact coordinates and s2; no square roots).
// With s2 = 0 this is set.contains(center). 2-cells that overlap or share edges are
// merged first (set_union) when no single one holds the cap, so the answer is exact for
// any representation of the set.
bool contains_cap(const SphericalImage& set, const exact::ExactVec& center, double s2);

// For searching only (doubles): the angular distance in radians from the unit vector u to
// the boundary of the set when u is inside a 2-cell, 0 on a curve or a point of the set,
// minus the distance to the set when u is outside it (membership decided exactly).
// +pi for the whole sphere, -pi for the empty set. Inside overlapping 2-cells it is the
// largest distance to the boundary of one 2-cell containing u (a lower bound).
double approx_signed_clearance(const SphericalImage& set, const std::array<double, 3>& u);

}  // namespace gvm::sphere
