// Where a direction inside a 2-cell of the LVM can be visible although every direction
// around it is occluded: the candidates for the seams of the occluded directions.
//
// Inside a 2-cell of L = LVM(S + N_S) every triangle of S faces u strictly, and u is
// occluded iff some open prism relint(F_S) + R>0 u contains a point of the boundary (it
// then contains points of the interior). Call a segment from x in S to y in O along u a
// contact. A contact occludes u whenever rays from the inside of S near x meet the boundary
// near y: when S surrounds x (S near x projects along u onto a neighbourhood of x), or
// when the projections along u of S near x and of the boundary near y overlap. A seam --
// a visible direction of Int(Phi), where occluding cells only meet -- has no such contact,
// so all its contacts start on the border of S, and each direction of a contact is also
// the direction of a contact of one of these kinds (the ray from the origin leaves the
// convex set T - e or T - p, for a triangle T of O and a border edge e or corner p, through
// an edge or a corner; through the inside of a facet it would overlap):
//  - from inside a border edge e of S to a corner q of O: u on the arc q - e, unless a
//    neighbour of q lies strictly on the side of the plane (e, q) where S is;
//  - from a border corner p of S to inside an edge (a, b) of O: u on the arc (a, b) - p,
//    unless a triangle at (a, b) and a triangle of S at p reach strictly to one side of
//    the plane (a, b, p);
//  - from a border corner p to a corner q: u = q - p, unless, seen along u, an edge at q
//    points strictly into a triangle of S at p or an edge of S at p strictly into a
//    triangle at q.
// Those arcs and points that may meet the open LVM hold every seam. Which parts of the
// arcs can (seam_pieces.h): where arcs occluding opposite sides of one circle overlap,
// and where arcs of three circles cross; the occlusion probe decides them and the corner
// contacts exactly (occlusion_probe.h).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "gvm/mesh.h"
#include "sphere/arrangement.h"
#include "sphere/spherical_image.h"

namespace gvm {

struct SeamCandidates {
  std::vector<sphere::ArrangementArc> arcs;  // weight 0, layer 0 (set by the caller)
  std::vector<exact::ExactVec> points;       // corner contacts and crossings of three arcs
};

class DirectionWindow;

// s: the triangles of S; o: those of O that may occlude directions of `lvm` (the beam);
// window: the LVM's direction window (contacts certainly outside it are left out). Empty
// when the LVM has no 2-cell.
SeamCandidates seam_candidates(const SolidMesh& mesh, std::span<const uint32_t> s,
                               std::span<const uint32_t> o, const sphere::SphericalImage& lvm,
                               const DirectionWindow& window);

}  // namespace gvm
