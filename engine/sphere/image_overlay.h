// Closed sets of directions as arrangement input, shared by everything that overlays
// SphericalImages (the GVM's last difference, the set operations, the coverage overlay).
#pragma once

#include <span>
#include <vector>

#include "sphere/arrangement.h"
#include "sphere/spherical_image.h"

namespace gvm::sphere {

// The cells of `image` on `layer`: the boundary arcs of its 2-cells with weight 1 (the face
// on their left, so a layer's coverage is the number of its faces over a point), its
// curves with weight 0 (they only mark where the set is), its points. Arcs are split into
// pieces shorter than 180 degrees; the full sphere adds nothing (see face_winding).
void add_image(const SphericalImage& image, int layer, std::vector<ArrangementArc>& arcs,
               std::vector<ArrangementPoint>& points);

// A direction on none of the great circles with the given normals and on none of the
// points: the reference at which coverage is counted directly. Small integer directions
// are tried in turn; finitely many circles cannot contain them all.
exact::ExactVec generic_direction(std::span<const exact::ExactVec> circles,
                                  std::span<const exact::ExactVec> points);
// The same for the circles and points of arrangement input.
exact::ExactVec generic_direction(std::span<const ArrangementArc> arcs,
                                  std::span<const ArrangementPoint> points);

// The coverage of `image`'s layer (see add_image) at r, which lies on no boundary arc of
// it: the number of its 2-cells containing r, 1 for the full sphere.
int face_winding(const SphericalImage& image, const exact::ExactVec& r);

}  // namespace gvm::sphere
