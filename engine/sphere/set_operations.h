// Boolean operations on closed sets of directions, exact and non-regularized: the
// operands are overlaid in one exact arrangement (their faces by winding number, their
// arcs and points as marks) and every vertex, edge and face of it is kept or dropped on
// its own, so points and arcs survive wherever the definition keeps them (a through
// hole's axis, a slot's arc).
//
// Membership of a cell c of the arrangement in a closed set A: a face iff A's faces cover
// it; an edge iff it lies on an arc of A or beside a face in A; a vertex iff it is a point
// of A or lies on an edge or beside a face in A. c is in Int(B) iff every face around it
// is in B.
//
// Results are canonical as Arrangement::extract makes them (faces merged across edges,
// consecutive arcs on one circle merged, curves and points never inside faces). A result
// face is marked convex when it is one (one loop, every vertex in the closed hemisphere of
// every arc, checked exactly; very large faces stay general), so results compare equal
// (operator==) to the convex faces of local visibility maps; other faces are general
// (convex = false), which contains() handles exactly.
//
// The operands may be any closed sets: overlapping 2-cells (a point is in the set when
// some 2-cell covers it), convex or general faces, the full sphere, the empty set.
#pragma once

#include "sphere/spherical_image.h"

namespace gvm::sphere {

SphericalImage set_union(const SphericalImage& a, const SphericalImage& b);
SphericalImage set_intersection(const SphericalImage& a, const SphericalImage& b);
// a minus the interior of b: closed; the arcs and points of a on b's boundary stay.
SphericalImage set_difference(const SphericalImage& a, const SphericalImage& b);
// a is a subset of b (exact, whatever the representation of either).
bool is_subset(const SphericalImage& a, const SphericalImage& b);

}  // namespace gvm::sphere
