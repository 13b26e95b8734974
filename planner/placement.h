// Where, among the directions every member set allows, a setup's direction goes: the one
// with the largest clearance (angular distance to the members' boundaries), found in
// doubles by a local search and then verified exactly -- the direction lies in every
// member by the exact predicates, and each clearance printed is a certified lower bound.
#pragma once

#include <span>
#include <vector>

#include "gvm/direction.h"
#include "gvm/direction_set.h"

namespace gvm::planner {

// The largest angle c, in degrees rounded down to 1e-6, such that the closed cap of
// half-angle c around d lies in `set` (exact test); `estimate` (radians) is where the
// search starts. 0 when d is on the set's boundary or the set has no 2-cell, 180 for the
// whole sphere. Precondition: d is in the set.
double certified_clearance_degrees(const DirectionSet& set, const Direction& d, double estimate);

struct Placement {
  Direction direction;                  // in every member, exactly
  std::vector<double> clearance_degrees;  // per member, certified
  std::vector<bool> exact_alignment;      // per member: clearance 0 (an arc, a point, or its edge)
};

// Moves `start` (which must lie in every member) to where the smallest clearance of the
// 2-dimensional members is largest: on the intersection of the others when some member
// is an arc or a point (its direction must then be aligned exactly).
Placement place_in(std::span<const DirectionSet* const> members, const Direction& start);

// The clearances of the members at d (which must lie in every member), without moving it.
Placement placement_at(std::span<const DirectionSet* const> members, const Direction& d);

// sin^2 of an angle in degrees, rounded up so that a cap tested with it is never smaller
// than the angle asked for.
double sin2_at_least(double degrees);

// The smallest signed clearance of the unit vector u in the members, in doubles (radians).
double approx_clearance(std::span<const DirectionSet* const> members, const std::array<double, 3>& u);

}  // namespace gvm::planner
