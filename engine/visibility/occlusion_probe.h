// Whether a single direction of the LVM is occluded, decided from the rays themselves.
//
// The paper takes GOM(S, O) = Int(Phi(O + (-S))) (Eq. 3). That is exact away from
// degenerate directions, but a direction whose rays only graze O while every direction
// around it is blocked lies in that interior and is still visible: the floor of a bore
// with a circlip groove, seen along the axis (the rays run along the wall above the groove
// and touch its rim), or a pocket whose opening has exactly the floor's outline. The GVM
// asks this probe about the points of the LVM that lie in that interior.
//
// u is occluded iff some ray from S along u meets the interior of the solid. For a
// triangle F_S of S with u . n_S > 0 its rays sweep the prism F_S + R>0 u, whose interior
// is open and starts outside the solid: it meets the solid's interior iff it meets its
// boundary, i.e. a triangle of O (the first entry is through a face met from the front,
// which is potentially facing, Def. 5, and in the occluder beam). A triangle T and that
// open prism are disjoint iff an axis w weakly separates them (w . t <= w . x for t in T
// and x in the prism): the separating axis theorem for the Minkowski difference, whose
// facet normals are the normals of both and the cross products of their edge directions.
// Decided exactly.
//
// Triangles of S parallel to u sweep a planar strip instead, and rays along a face's plane
// may graze it: there the probe counts any triangle of O that meets the closed strip as
// blocking. So "occluded" may be conservative when u lies in a plane of S (the old answer,
// Int(Phi) stays), "visible" is always exact.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "exact/exact_vec.h"
#include "gvm/mesh.h"
#include "sphere/spherical_image.h"

namespace gvm {

class OcclusionProbe {
 public:
  // s: the triangles of S; o: those of O that may block directions of the LVM (the beam).
  OcclusionProbe(const SolidMesh& mesh, std::span<const uint32_t> s, std::span<const uint32_t> o);

  // False only if no ray from S along u (a direction of LVM(S + N_S)) meets the interior
  // of the solid.
  bool occluded(const exact::ExactVec& u) const;

  // The directions of an open arc of the LVM (shorter than 180 degrees) along which no
  // ray from S meets the interior of the solid: closed sub-arcs, and points (start ==
  // end), in order. Exact, except that an arc in the plane of a triangle of S counts as
  // occluded (nothing is returned).
  std::vector<sphere::Arc> unoccluded(const sphere::Arc& open_arc) const;

 private:
  // Whether rays from triangle fs of S along u may meet the interior of the solid through
  // triangle ft of O (exact unless u lies in fs's plane and the rays pass a corner of ft).
  bool may_block(uint32_t fs, uint32_t ft, const exact::ExactVec& u) const;
  // Calls visit(fs, ft) (in parallel) for the pairs of S and O whose segments may have a
  // direction in the cell; a pair's visit returning false ends its triangle of S early.
  template <class Visit>
  void for_each_pair(const sphere::SphericalImage& cell, const Visit& visit) const;

  const SolidMesh& mesh_;
  std::vector<uint32_t> s_, o_;
  double coordinate_bound_;
};

}  // namespace gvm
