// Open sub-arcs of one arc shorter than 180 degrees, and what they leave uncovered: how the
// occlusion probe and the open cells of the occluded directions cut an arc exactly.
#pragma once

#include <span>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/spherical_image.h"

namespace gvm::sphere {

// Points of one arc shorter than 180 degrees around n, in their order along it.
struct ArcOrder {
  const exact::ExactVec& n;
  bool before(const exact::ExactVec& x, const exact::ExactVec& y) const {
    return exact::sign_det(n, x, y) == Sign::kPositive;
  }
};

// An open sub-arc (lo, hi) of an arc.
struct Interval {
  exact::ExactVec lo, hi;
};

// The directions of the open arc in every open half-space {x . m > 0}: one open
// interval, or false when there are none. `whole` is set when no half-space cuts the arc.
bool clip(const Arc& arc, std::span<const exact::ExactVec> normals, Interval& out, bool* whole);

// The closed pieces of the open arc outside every open interval (a piece with equal ends
// is a point between two intervals), in order along it.
std::vector<Arc> complement(const Arc& arc, std::vector<Interval> covered);

}  // namespace gvm::sphere
