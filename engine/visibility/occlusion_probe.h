// Whether directions of the LVM inside Int(GOM) are occluded, decided from the rays.
//
// The paper takes GOM(S, O) = Int(Phi(O + (-S))) (Eq. 3). That is exact away from
// degenerate directions, but a direction whose rays only graze O while every direction
// around it is blocked lies in that interior and is still visible: the floor of a bore
// with a circlip groove seen along the axis (its rays run along the wall above the groove
// and touch the groove's rims), or the wall of a countersunk hole seen out of the
// countersink. The GVM asks this probe about the points and arcs of the LVM in there.
//
// u is occluded iff some ray from S along u meets the interior of the solid.
//  - For a triangle F_S of S with u . n_S > 0 the rays sweep the prism F_S + R>0 u, whose
//    interior is open and starts outside the solid: it meets the solid's interior iff it
//    meets its boundary, i.e. a triangle of O (the first entry is through a face met from
//    the front, which is potentially facing, Def. 5, and in the occluder beam). A triangle
//    T and the open prism are disjoint iff an axis weakly separates them (separating axis
//    theorem: the facet normals of their Minkowski difference are the normals of both and
//    the cross products of their edge directions).
//  - For F_S parallel to u the rays sweep a planar strip and may graze faces. They enter
//    the solid at a point of the strip where u points into it, on a face T met from the
//    front: T crosses the strip's plane there (the relative interiors meet: the same
//    test), or touches it along an edge, where u enters iff the edge is concave or flat,
//    or convex with the face across met from the front too, or at a corner, where u
//    enters iff it points strictly into the solid's cone at the corner (bounded by the
//    corner's star).
// Every pair is decided exactly, so both answers for a direction are exact; an arc of
// the LVM in the plane of a triangle of S is not decided (unoccluded() below).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "exact/exact_vec.h"
#include "gvm/mesh.h"
#include "sphere/arc_intervals.h"
#include "sphere/spherical_image.h"
#include "visibility/direction_window.h"

namespace gvm {

class OcclusionProbe {
 public:
  // s: the triangles of S; o: those of O that may block directions of the LVM (the beam).
  OcclusionProbe(const SolidMesh& mesh, std::span<const uint32_t> s, std::span<const uint32_t> o);

  // True iff some ray from S along u (a direction of LVM(S + N_S)) meets the interior of
  // the solid.
  bool occluded(const exact::ExactVec& u) const;

  // The directions of an open arc of the LVM (shorter than 180 degrees) along which no
  // ray from S meets the interior of the solid: closed sub-arcs, and points (start ==
  // end), in order. Exact (an arc in the plane of triangles of S is decided between the
  // events of their strips, strip_events.h).
  std::vector<sphere::Arc> unoccluded(const sphere::Arc& open_arc) const;

  // The triangles of O through which rays from S along u (a direction of the LVM) enter
  // the solid, ascending: the faces that block u (exact).
  std::vector<uint32_t> blockers(const exact::ExactVec& u) const;

 private:
  // Whether rays from triangle fs of S along u meet the interior of the solid through
  // triangle ft of O (exactly; true as well when u is not in fs's closed half-space).
  bool may_block(uint32_t fs, uint32_t ft, const exact::ExactVec& u) const;
  // Whether a ray along u through corner `corner` of triangle t enters the solid's
  // interior there: u strictly inside the solid's tangent cone at that vertex.
  bool enters_at_corner(uint32_t t, int corner, const exact::ExactVec& u) const;
  // The strips swept along an arc by the triangles of S in its plane: the pairs of such a
  // triangle and a triangle of O touching that plane, and their events inside the open
  // arc (strip_events.h), in order along it, without repeats.
  struct Strips {
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    std::vector<exact::UnitEstimate> plane_normals;  // of each pair's triangle of S
    std::vector<exact::ExactVec> events;
    std::vector<std::vector<uint32_t>> event_sources;  // the triangles of O with an event there
    // Whether some pair blocks u; `last` is the pair that blocked last (tried first, updated).
    bool block(const OcclusionProbe& probe, const exact::ExactVec& u, size_t& last) const;
    // Whether what pair i answers may change at event e: one of its triangle's events.
    bool changes_at(size_t e, size_t i) const;
  };
  Strips strips_along(std::span<const uint32_t> in_plane, const sphere::Arc& open_arc) const;
  // Appends the visible parts of `piece`, a closed sub-arc of open_arc that no prism
  // blocks, to `out` (merged into maximal arcs, and points).
  void decide_between_events(const sphere::Arc& piece, const sphere::Arc& open_arc, const Strips& strips,
                             std::vector<sphere::Arc>& out) const;
  // The open intervals of an open arc inside the maps of the pairs of a triangle of S (not
  // in the arc's plane) and one of O: the arc the prisms block.
  struct PrismCover {
    bool whole = false;  // one map holds the whole arc (intervals then left empty)
    std::vector<sphere::Interval> intervals;
  };
  PrismCover prism_cover(const sphere::Arc& open_arc, const std::vector<bool>& in_plane) const;
  // Calls visit(fs, ft) (in parallel) for the pairs of S and O whose segments may have a
  // direction in the cell; a pair's visit returning false ends its triangle of S early.
  template <class Visit>
  void for_each_pair(const sphere::SphericalImage& cell, const Visit& visit) const;
  // The positions in o_ of the triangles of O in runs whose box may meet a run of S
  // (s_min: the window's rows of S): a point's or an arc's window rules out most runs of
  // O at once, so the others need no rows of their own.
  std::vector<uint32_t> near_runs(const DirectionWindow& window, std::span<const double> s_min) const;

  const SolidMesh& mesh_;
  std::vector<uint32_t> s_, o_;
  double coordinate_bound_;
  // The corners of a box around each run of WindowRows::kRun consecutive triangles of o_.
  std::vector<std::array<Point3, 8>> o_run_corners_;
};

}  // namespace gvm
