// Closed sets of directions on the unit sphere (the paper's spherical images), exact and
// non-regularized: 2-cells, arcs and points may all be present, as in the GVM of a slot
// (a half great circle) or of a through hole (two antipodal points). Every operation is
// decided by exact predicates; doubles appear only in areas, descriptions and the
// clearance searches marked approx.
//
// A DirectionSet is immutable and cheap to copy (the cells are shared); const methods are
// safe to call from several threads.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gvm/direction.h"

namespace gvm {

namespace sphere {
class SphericalImage;
}

class DirectionSet {
 public:
  DirectionSet();  // the empty set
  static DirectionSet full_sphere();
  static DirectionSet point(const Direction& d);
  static DirectionSet hemisphere(const Direction& n);    // {u : u . n >= 0}
  static DirectionSet great_circle(const Direction& n);  // {u : u . n = 0}
  // The closed minor arc from `from` to `to` (not parallel).
  static DirectionSet minor_arc(const Direction& from, const Direction& to);
  // {u : u . n >= 0 for every n}: a convex polygon, lune, hemisphere, arc, point, the
  // whole sphere (no normals) or empty (paper Prop. 1).
  static DirectionSet intersection_of_hemispheres(std::span<const Direction> normals);

  // -1 for the empty set, else the largest dimension of its cells.
  int dimension() const;
  bool is_empty() const { return dimension() < 0; }
  bool is_full_sphere() const;
  bool contains(const Direction& u) const;
  // A direction of the set (a point, an arc's end or a boundary vertex); not empty.
  Direction witness() const;

  DirectionSet intersection(const DirectionSet& other) const;
  DirectionSet union_with(const DirectionSet& other) const;
  // This set minus the interior of `other`: closed, so arcs and points on other's
  // boundary stay (the paper's non-regularized difference, Eq. 6).
  DirectionSet difference(const DirectionSet& other) const;
  bool is_subset_of(const DirectionSet& other) const;
  friend bool operator==(const DirectionSet& a, const DirectionSet& b);
  // {-u : u in the set}.
  DirectionSet antipodal() const;
  // The polar (dual) set {a : a . u >= 0 for every u in the set}: the rotary axes a for
  // which the whole set lies in the closed hemisphere around a.
  DirectionSet polar() const;
  // u . n >= 0 for every u of the set (vacuously true when empty).
  bool within_closed_hemisphere(const Direction& n) const;

  // The closed cap {u : angle(u, center) <= theta} lies in the set, where
  // sin2 = sin^2(theta) (0 <= sin2 <= 1, a double taken exactly). Exact.
  bool contains_cap(const Direction& center, double sin2) const;
  // Some direction of the set lies within theta of u, where sin2 = sin^2(theta)
  // (0 <= sin2 < 1, a double taken exactly): the planner's tolerance. Exact.
  bool within(const Direction& u, double sin2) const;
  // Some direction of the set lies within theta of some direction of `other`. Exact.
  bool within(const DirectionSet& other, double sin2) const;
  // The set's corners: its points, the ends of its arcs, the vertices of its 2-cells.
  std::vector<Direction> corners() const;
  // A closed set bounded by great circles holding every direction within theta (radians)
  // of this one, where sin2 >= sin^2(theta): certified exactly, a little larger than the
  // theta-neighbourhood (for lower bounds). Nothing when it cannot be certified.
  std::optional<DirectionSet> dilation_cover(double theta, double sin2) const;
  // For searches only: angular distance (radians) from the unit vector u to the set's
  // boundary when u is inside a 2-cell, 0 on an arc or point of the set, minus the
  // distance to the set outside it.
  double approx_signed_clearance(const std::array<double, 3>& u) const;

  // The cells one by one, each a set of its own: every 2-cell (with its holes), every
  // arc (or whole circle), every point.
  std::vector<DirectionSet> cells() const;
  // An exact direction of the set close to the unit vector u (for placing a direction
  // found in doubles): u itself when its doubles are in the set, else the closest of u's
  // projections onto the set's arcs, the arcs' ends and the points (doubles compare the
  // candidates; membership is exact). Not empty.
  Direction snap(const std::array<double, 3>& u) const;
  // The set's intersection with the great circle {u . normal = 0}, as closed intervals of
  // angles in radians counter-clockwise around `normal` from `zero` (a direction on that
  // circle), in doubles, each with 0 <= from < 2 pi and from <= to < from + 2 pi; the
  // whole circle is [0, 2 pi].
  std::vector<std::array<double, 2>> circle_intervals(const Direction& normal,
                                                      const Direction& zero) const;

  // Area in steradians (doubles).
  double area() const;
  // One line for people, e.g. "point (0, 0, 1)", "hemisphere around (0, 0, 1)".
  std::string description() const;

  // The engine's cells (engine internals and the proto edge only).
  const sphere::SphericalImage& image() const { return *image_; }
  explicit DirectionSet(std::shared_ptr<const sphere::SphericalImage> image)
      : image_(std::move(image)) {}

 private:
  std::shared_ptr<const sphere::SphericalImage> image_;
};

}  // namespace gvm
