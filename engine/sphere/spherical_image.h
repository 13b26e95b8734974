// Closed sets of directions on the unit sphere S^2 (paper Sec. 2: spherical images), with
// exact geometry. Every vertex is an exact direction (exact::ExactVec, never normalized:
// any positive multiple) and every great-circle arc carries its exact supporting circle
// normal, so all decisions (containment, equality, hemisphere tests) are exact predicates.
// Doubles appear only in the output: unit vectors, areas and descriptions.
//
// Cell representation (non-regularized: 2-, 1- and 0-cells may coexist):
//  - Arc: a great-circle arc from `start` to `end` running counter-clockwise around
//    `normal` (seen from the tip of `normal`); start and end are orthogonal to normal.
//    Arcs of any length in (0, 360) degrees are allowed; an arc of exactly 180 degrees
//    (end = -start) is only meaningful because the normal is stored. `full` marks a whole
//    great circle (start and end unused).
//  - Face (2-cell): the closed region to the left of all its loops (outer boundary and
//    holes). A loop is a closed chain of arcs, each starting where the previous one ends;
//    a loop of one `full` arc is a whole great circle (the face is then on the side its
//    normal points to, e.g. a hemisphere). `convex` is set when the region is the
//    intersection of the closed hemispheres {u . normal >= 0} of its arcs (every outcome
//    of local_visibility_map, and of the set operations' results that are convex);
//    contains() uses it for a fast test (general faces go through point_in_face), and
//    operator== compares convex faces by their circles, general ones structurally (see
//    below; is_subset both ways, in set_operations.h, is equality for any representation).
//  - Curves (1-cells): arcs (or full great circles); a polyline is several arcs.
//  - Points (0-cells).
// `full_sphere` stands for the whole sphere (nothing else is set).
#pragma once

#include <string>
#include <vector>

#include "exact/exact_vec.h"

namespace gvm::sphere {

struct Arc {
  exact::ExactVec start, end;  // unused when `full`
  exact::ExactVec normal;      // circle normal; the arc runs counter-clockwise around it
  bool full = false;           // a whole great circle
};

struct Loop {
  std::vector<Arc> arcs;  // arcs[i].end == arcs[i + 1].start (cyclically)
};

struct Face {
  std::vector<Loop> loops;  // the region lies to the left of every loop
  bool convex = false;      // region == intersection of {u . arc.normal >= 0}
};

// True iff direction u lies on the closed arc (exact; arcs of any length, full circles).
bool arc_contains(const Arc& arc, const exact::ExactVec& u);
// True iff direction u lies in the closed 2-cell (exact; convex or general).
bool face_contains(const Face& f, const exact::ExactVec& u);

class SphericalImage {
 public:
  SphericalImage() = default;  // empty
  static SphericalImage empty() { return {}; }
  static SphericalImage full_sphere();
  static SphericalImage point(const exact::ExactVec& p);
  // The closed hemisphere {u : u . n >= 0}.
  static SphericalImage hemisphere(const exact::ExactVec& n);
  // The great circle {u : u . n = 0}.
  static SphericalImage great_circle(const exact::ExactVec& n);

  // Building blocks (no validation beyond what the comments above require).
  void add_point(const exact::ExactVec& p) { points_.push_back(p); }
  void add_curve(const Arc& a) { curves_.push_back(a); }
  void add_face(Face f) { faces_.push_back(std::move(f)); }

  bool is_full_sphere() const { return full_; }
  bool is_empty() const { return dimension() < 0; }
  const std::vector<Face>& faces() const { return faces_; }
  const std::vector<Arc>& curves() const { return curves_; }
  const std::vector<exact::ExactVec>& points() const { return points_; }

  // -1 for the empty set, else the largest dimension of the cells.
  int dimension() const;
  // Exact membership in the closed set (u non-zero), convex or general faces.
  bool contains(const exact::ExactVec& u) const;
  // Area in steradians (Gauss-Bonnet over the loops, in doubles; 4 pi, 2 pi exactly for
  // the full sphere and a hemisphere; 0 without 2-cells).
  double area() const;
  // The same area, the same doubles for the same set however its cells, loops and arcs
  // were built and ordered (for output; exact evaluations at every vertex).
  double canonical_area() const;
  // True iff u . n >= 0 for every u of the set (exact; vacuously true when empty).
  bool within_closed_hemisphere(const exact::ExactVec& n) const;

  // Exact set equality, guaranteed for images made of convex faces whose arcs are all
  // facets (no redundant arcs: what local_visibility_map produces), arcs that do not
  // overlap one another and distinct points -- i.e. the canonical shapes produced here.
  // Faces compare by their sets of circle normals (directions), curves as point sets of
  // single arcs, points by direction; the cells are matched one to one. Non-convex faces
  // compare structurally (same loops up to cyclic rotation, same exact vertices/normals).
  friend bool operator==(const SphericalImage& a, const SphericalImage& b);

  // One line for people, e.g. "point (0, 0, 1)", "hemisphere around (0, 0, 1)".
  std::string description() const;

 private:
  bool full_ = false;
  std::vector<Face> faces_;
  std::vector<Arc> curves_;
  std::vector<exact::ExactVec> points_;
};

// Vertices of an arc split into pieces strictly shorter than 180 degrees (both endpoints
// included; a full circle repeats its first vertex at the end). Exact constructions.
std::vector<exact::ExactVec> split_arc(const Arc& arc);

// Vertices of an arc split into pieces of at most 90 degrees, for output: the added
// vertices are exact points of the arc's circle (quarter turns from its start), so that
// the doubles of consecutive vertices decide each piece unambiguously.
std::vector<exact::ExactVec> split_arc_quarters(const Arc& arc);

}  // namespace gvm::sphere
