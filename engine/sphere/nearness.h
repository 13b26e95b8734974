// Directions near a closed set: the planner's tolerance. A set S is within theta of a
// direction u when some direction of S is at most theta from u (the closed cap around u
// meets S), and within theta of another set when some pair is. theta is given by
// s2 = sin^2(theta), 0 <= s2 < 1 (theta below 90 degrees), a double taken exactly, as for
// the clearance caps (clearance.h): every comparison is the sign of a polynomial in the
// exact coordinates and s2, so the answers are exact.
#pragma once

#include <optional>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/spherical_image.h"

namespace gvm::sphere {

// Some direction of the set lies within theta of u (u non-zero).
bool within_angle(const SphericalImage& set, const exact::ExactVec& u, double s2);

// Some direction of a lies within theta of some direction of b.
bool sets_within_angle(const SphericalImage& a, const SphericalImage& b, double s2);

// The set's corners: its points, the ends of its arcs and the vertices of its faces'
// loops (whole circles have none).
std::vector<exact::ExactVec> corners(const SphericalImage& set);

// A closed set bounded by great circles that holds every direction within theta of the
// set (s2 >= sin^2(theta)): the set, and a convex quadrilateral around each piece of its
// arcs (at most 90 degrees) and each point, each checked exactly to hold the piece with
// every boundary arc farther than theta from it. Its faces may overlap. Nothing when a
// quadrilateral cannot be certified (theta too large for the construction).
std::optional<SphericalImage> dilation_cover(const SphericalImage& set, double theta, double s2);

}  // namespace gvm::sphere
