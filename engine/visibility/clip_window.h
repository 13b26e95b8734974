// A convex window around the LVM, to which the occluding cells' coverage is clipped
// before the unions are built.
//
// GVM(S) = L - Int(Phi) with L = LVM(S + N_S) convex. If L lies in the interior of a
// convex region W, a direction x of L is in Int(Phi) iff it is in Int(Phi ∩ W) (W is a
// neighbourhood of x), and the closure of the occluded directions can be built from any
// mix of groups of cells taken whole or clipped to W. Clipped, the cells of a small LVM
// (an arc, a point, a narrow 2-cell) no longer overlap one another far from it, where
// their unions used to spend most of the arrangement vertices.
//
// W is a convex polygon whose edges lie on great circles with double normals, pushed out
// by a margin from L's own circles; it is used only after checking exactly that its
// corners are proper, every vertex of L lies strictly inside it and every arc of L is
// minor. A group whose arcs meet W degenerately (an endpoint on W's boundary, a crossing
// at a corner) is simply left unclipped.
//
// An LVM that no such W holds (a hemisphere, a lune, a polygon reaching near the edge of
// its centre's hemisphere) is cut like a fan from a direction inside it into pieces of
// about a right angle each, with a window around each piece: a direction of L lies
// strictly inside the window of its piece, and the argument above holds there. Clipped to
// the pieces' windows, the cells no longer build the occluded directions behind the face.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/arrangement.h"
#include "sphere/spherical_image.h"

namespace gvm {

class ClipWindow {
 public:
  // The window around `lvm` when there is one: a single 2-cell, arc or point inside an
  // open hemisphere. None for a hemisphere, a lune, several cells, or the full sphere.
  static std::optional<ClipWindow> around(const sphere::SphericalImage& lvm);
  // Windows whose interiors together hold the LVM: the one `around` it, else one around
  // each fan piece of a single convex 2-cell. Empty when there are none (several cells, a
  // half or full circle, the full sphere).
  static std::vector<ClipWindow> covering(const sphere::SphericalImage& lvm);
  static constexpr size_t kMaxWindows = 64;  // at most 2 pi / 1.75 * 2 + 1 pieces are cut

  // W = {x : w . x >= 0 for every normal w}; the normals in counter-clockwise order of
  // W's edges, corner i (where edge i starts) on the circles of normals i - 1 and i.
  std::span<const exact::ExactVec> normals() const { return normals_; }
  const exact::ExactVec& corner(size_t i) const { return corners_[i]; }
  bool contains_strictly(const exact::ExactVec& u) const;

  // Whether a convex polygon (vertices counter-clockwise around its inside) meets W in
  // zero area: then it changes the coverage nowhere inside W.
  bool misses(std::span<const exact::ExactVec> polygon) const;

  // Arcs (weighted, layer ignored) whose coverage is c inside W and 0 outside, where c is
  // the coverage of `arcs`, given `corner_coverage`, the coverage of `arcs` at corner 0.
  // None when the arcs meet W's boundary degenerately.
  std::optional<std::vector<sphere::ArrangementArc>> clip(std::span<const sphere::ArrangementArc> arcs,
                                                          int corner_coverage) const;

 private:
  ClipWindow(std::vector<exact::ExactVec> normals);
  // The window of the polygon `vertices` with these inward side normals (doubles), its
  // sides pushed out towards `centre`, if it is proper and holds the vertices strictly.
  static std::optional<ClipWindow> fit(const std::vector<std::array<double, 3>>& inward,
                                       const std::array<double, 3>& centre,
                                       std::span<const exact::ExactVec> vertices);
  bool proper() const;

  // sign_dot of normal j and x, decided from estimates where they can: a window around a
  // pocket floor has 420 sides, tested against every vertex of every envelope face.
  Sign side(size_t j, const exact::ExactVec& x, const exact::UnitEstimate& ex) const {
    return exact::sign_dot(normals_[j], x, estimates_[j], ex);
  }

  std::vector<exact::ExactVec> normals_;
  std::vector<exact::UnitEstimate> estimates_;  // of the normals
  std::vector<exact::ExactVec> corners_;
};

}  // namespace gvm
