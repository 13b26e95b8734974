// Closed regions of the sphere given by their boundaries, and their unions.
//
// Int(Phi(O + (-S))) only depends on the closed region C = closure{coverage > 0}, and the
// closure of a finite union is the union of the closures. So C can be built by divide
// and conquer: the positive region of each group of envelope faces, then unions of
// regions up a balanced tree. Each arrangement then only holds arcs that bound a partial
// union, instead of every arc of every face over every other, which is what makes
// deeply overlapping envelopes affordable.
#pragma once

#include <span>
#include <vector>

#include "sphere/arrangement.h"
#include "sphere/spherical_image.h"

namespace gvm::sphere {

// A closed regular region: the closure of the directions with positive winding number
// of `boundary` (arcs of weight 1 with the region on their left). `contains_reference`
// tells whether the common reference direction (on none of the arcs) lies in it.
struct Region {
  std::vector<ArrangementArc> boundary;
  bool contains_reference = false;
  // Vertices of all the arrangements built to find this region (a measure of the work).
  uint64_t arrangement_vertices = 0;
};

// closure{coverage > 0} for weighted arcs (their layer is ignored) whose coverage at
// `reference` is `reference_coverage`.
Region positive_region(std::span<const ArrangementArc> arcs, const exact::ExactVec& reference,
                       int reference_coverage);

// The union of closed regions, merged pairwise up a balanced tree (in parallel; the
// result does not depend on the thread count).
Region region_union(std::vector<Region> parts, const exact::ExactVec& reference);

// The directions of `set` outside the interior of r (a closed set: r's boundary within
// `set` is kept). `reference` lies on none of their circles and on no point of `set`.
SphericalImage outside_interior(const SphericalImage& set, const Region& r, const exact::ExactVec& reference);

}  // namespace gvm::sphere
