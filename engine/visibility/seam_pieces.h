// Where the grazing arcs of seam_candidates.h can hold a seam.
//
// A contact of a grazing arc occludes, next to the arc, directions on one side of its
// circle at most (the side of the triangles it touches). A seam is a visible direction
// with every direction around it occluded, by contacts along it. Inside a seam arc that
// crosses no other grazing arc, those contacts lie on its circle, so arcs on that circle
// occlude both sides there: the seam lies where an arc occluding one side overlaps one
// occluding the other. At an isolated seam point that is no corner contact, the sides
// the arcs through it occlude cover every direction around it, which takes arcs of three
// circles (two half-planes leave a wedge free).
#pragma once

#include <vector>

#include "exact/exact_vec.h"
#include "sphere/arrangement.h"

namespace gvm {

struct GrazingArc {
  sphere::ArrangementArc arc;
  // The side of the circle its contacts may occlude next to it: +1 where x . normal > 0,
  // -1 the other, 0 either.
  int side = 0;
};

struct SeamPieces {
  std::vector<sphere::ArrangementArc> arcs;  // weight 0, layer 0
  std::vector<exact::ExactVec> points;
};

// The pieces of circles where arcs occluding both sides overlap (arcs, or points where
// they only touch), and the points where arcs of three distinct circles cross.
SeamPieces seam_pieces(std::vector<GrazingArc> arcs);

}  // namespace gvm
