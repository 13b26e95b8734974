// Every geometric decision of the engine is one of these predicates. Each is exact for
// double input: a floating-point filter with a certified error bound decides almost all
// calls, and an exact dyadic (GMP) evaluation decides the rest (the determinants of input
// differences take a static bound before the filter and floating-point expansions before
// GMP; see predicates.cpp). A zero result is reported
// as zero: degenerate input (coplanar faces, parallel walls) is answered, never perturbed.
// Nothing outside the exact module compares a floating-point value with an epsilon.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "gvm/geometry.h"

namespace gvm::exact {

// Sign of det(b-a, c-a, d-a): positive when d lies on the side of plane (a, b, c) that the
// normal (b-a) x (c-a) points to.
Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

// det_diff(a0, a1, b0, b1, c0, c1) for one pair of differences and many third ones: the
// minors of a1 - a0 and b1 - b0 that the static filter stage needs are formed once, so
// that a call costs about half the arithmetic of det_diff; what that stage cannot decide
// goes to det_diff.
class DifferenceDet {
 public:
  DifferenceDet(const Point3& a0, const Point3& a1, const Point3& b0, const Point3& b1);
  Sign operator()(const Point3& c0, const Point3& c1) const;
  // The static stage alone: nothing when it cannot decide.
  std::optional<Sign> filtered(const Point3& c0, const Point3& c1) const;

 private:
  Point3 a0_, a1_, b0_, b1_;
  double minor_[3], permanent_[3];  // (a1 - a0) x (b1 - b0) in doubles, and its terms' magnitudes
  int axis_ = -1;                   // the axis both differences are normal to, if any
  Sign axis_sign_ = Sign::kZero;    // the sign of (a1 - a0) x (b1 - b0) along it
};

// orient3d(a, b, c, d) for one plane (a, b, c) and many points d, by DifferenceDet; what
// its static stage cannot decide goes to orient3d.
class PlaneSide {
 public:
  PlaneSide(const Point3& a, const Point3& b, const Point3& c) : a_(a), b_(b), c_(c), det_(a, b, a, c) {}
  Sign operator()(const Point3& d) const;
  // det(b - a, c - a, e1 - e0): the side of the plane's normal that e1 - e0 points to.
  Sign along(const Point3& e0, const Point3& e1) const { return det_(e0, e1); }

 private:
  Point3 a_, b_, c_;
  DifferenceDet det_;
};

// Sign of det(a1-a0, b1-b0, c1-c0) for three difference vectors of input points. This is
// the predicate of the Minkowski-sum faces: (a1-a0) x (b1-b0) is a face normal or an
// edge-edge normal, c1-c0 a vertex difference or an edge direction.
Sign det_diff(const Point3& a0, const Point3& a1, const Point3& b0, const Point3& b1,
              const Point3& c0, const Point3& c1);

// Sign of (a1-a0) . (b1-b0).
Sign dot_diff(const Point3& a0, const Point3& a1, const Point3& b0, const Point3& b1);

// Orientation of a, b, c in the coordinate plane that drops axis `drop` (0, 1 or 2):
// sign of the 2D determinant of (b-a, c-a) in the remaining axes in cyclic order
// (drop 0 -> (y, z), drop 1 -> (z, x), drop 2 -> (x, y)).
Sign orient2d(const Point3& a, const Point3& b, const Point3& c, int drop);

// True when (b-a) x (c-a) is exactly zero: a, b, c collinear (or coincident).
bool collinear(const Point3& a, const Point3& b, const Point3& c);

// Sign of the component `axis` of (b-a) x (c-a); the dominant non-zero component gives a
// projection plane in which a triangle keeps its orientation.
Sign cross_component(const Point3& a, const Point3& b, const Point3& c, int axis);

// Sign of (a-b) compared coordinate-wise in order x, y, z (lexicographic comparison).
int compare_lex(const Point3& a, const Point3& b);

// Sign of ((b1-a1) x (c1-a1)) . ((b2-a2) x (c2-a2)): whether two triangles' normals point
// the same way (positive), opposite ways, or are orthogonal (zero).
Sign normal_dot(const Point3& a1, const Point3& b1, const Point3& c1, const Point3& a2, const Point3& b2,
                const Point3& c2);

// Whether the normals n1, n2 of two non-degenerate triangles make an angle whose cosine is
// above k (-1 <= k < 1; a user's tolerance, taken as an exact double, so that the
// result never depends on rounding), i.e. n1 . n2 > k |n1| |n2|, decided exactly through squares.
bool normals_within(const Point3& a1, const Point3& b1, const Point3& c1, const Point3& a2, const Point3& b2,
                    const Point3& c2, double k);

// Sign of the signed area of a polygon (indices into `points`, in order) projected along
// axis `drop` as orient2d projects (the shoelace sum).
Sign polygon_area_sign(std::span<const Point3> points, std::span<const uint32_t> polygon, int drop);

// Sign of the signed volume of a set of triangles (six times it: the sum of det(a, b, c)),
// the triangles given by index into `triangles`.
Sign signed_volume_sign(std::span<const Point3> points, std::span<const Triangle> triangles,
                        std::span<const uint32_t> which);

}  // namespace gvm::exact
