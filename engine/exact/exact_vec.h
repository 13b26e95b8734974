// Exact vectors for spherical geometry. A direction on the sphere is a non-zero vector of
// R^3 whose coordinates are polynomials in the input doubles: a face normal is a cross
// product of two vertex differences, an arc intersection is a cross product of two such
// normals. An ExactVec records how it was constructed (an immutable expression DAG) and
// caches a filtered floating-point approximation; predicates use the approximation and
// re-evaluate the DAG exactly only when the filter cannot decide. Never normalized: a
// direction is any positive multiple, so all constructions stay exact.
#pragma once

#include <optional>

#include <array>
#include <memory>

#include "gvm/geometry.h"

namespace gvm::exact {

class Approx;

class ExactVec {
 public:
  ExactVec() = default;  // the zero vector
  static ExactVec from_point(const Point3& p);

  friend ExactVec operator+(const ExactVec& a, const ExactVec& b);
  friend ExactVec operator-(const ExactVec& a, const ExactVec& b);
  friend ExactVec operator-(const ExactVec& a);
  friend ExactVec cross(const ExactVec& a, const ExactVec& b);
  friend ExactVec point_difference(const Point3& q, const Point3& p);
  friend ExactVec triangle_normal(const Point3& a, const Point3& b, const Point3& c);

  // Floating-point approximation (value only), e.g. for output and bounding boxes.
  std::array<double, 3> approx() const;
  // The exact direction, rounded (the vector must be non-zero; one exact evaluation):
  // each coordinate within 2^-50 of its own magnitude (plus 2^-1070) of the exact unit
  // vector's. The coordinates are truncated to 53 bits (2^-52 each), which moves the norm
  // by 2^-52 at most; the norm and the divisions round within 7 * 2^-54 more.
  std::array<double, 3> unit() const;
  // The exact direction, each coordinate rounded to the nearest double (ties to even; the
  // vector must be non-zero). One direction then gives the same doubles however it was
  // constructed -- a vertex reached through another arc's normal included -- so output
  // written with it is canonical. Exact comparisons of squares, a few per coordinate: for
  // output, not for inner loops.
  std::array<double, 3> nearest_unit() const;

  struct Node;
  const Node* node() const { return node_.get(); }

 private:
  explicit ExactVec(std::shared_ptr<const Node> n) : node_(std::move(n)) {}
  std::shared_ptr<const Node> node_;
};

ExactVec cross(const ExactVec& a, const ExactVec& b);

// from_point(q) - from_point(p), and the normal (b - a) x (c - a) of triangle a, b, c, each
// as one node (for the many built from mesh points).
ExactVec point_difference(const Point3& q, const Point3& p);
ExactVec triangle_normal(const Point3& a, const Point3& b, const Point3& c);

// Exact predicates on exact vectors.
Sign sign_dot(const ExactVec& a, const ExactVec& b);
Sign sign_det(const ExactVec& a, const ExactVec& b, const ExactVec& c);
bool is_zero(const ExactVec& a);
// Sign of coordinate i of a (the dot with an axis, without the axis's vector).
Sign sign_of_coordinate(const ExactVec& a, int i);
// a x b == 0: parallel, antiparallel, or one of them zero.
bool parallel(const ExactVec& a, const ExactVec& b);
// Same direction on the sphere: parallel and a . b > 0.
bool same_direction(const ExactVec& a, const ExactVec& b);

// Angles against a double s2 taken exactly (a, b non-zero): the sign of
// sin^2(angle(a, b)) - s2, i.e. of |a x b|^2 - s2 |a|^2 |b|^2, and of cos^2(angle(a, b)) - s2,
// i.e. of (a . b)^2 - s2 |a|^2 |b|^2. With s2 = sin^2(theta): a point within theta of a
// direction, a direction within theta of the great circle with normal b.
Sign sign_sin2_angle_minus(const ExactVec& a, const ExactVec& b, double s2);
Sign sign_cos2_angle_minus(const ExactVec& a, const ExactVec& b, double s2);

// A unit vector within `radius` (Euclidean, certified) of the exact direction of a
// non-zero vector: for bounding boxes and candidate searches, never for decisions.
struct UnitEstimate {
  std::array<double, 3> unit;
  double radius;
};
UnitEstimate unit_estimate(const ExactVec& a);

// sign_dot(a, b), decided from unit estimates ea, eb of a and b where they certainly can:
// the exact unit vectors lie within the radii, so their dot is within ra + rb + ra rb of
// the estimates', which the doubles round by less than 2^-50 more. For loops that test
// each estimate many times (an arrangement's candidate pairs).
Sign sign_dot(const ExactVec& a, const ExactVec& b, const UnitEstimate& ea, const UnitEstimate& eb);
// The same sign from the estimates alone: nothing where they cannot certainly decide it.
std::optional<Sign> estimated_sign_dot(const UnitEstimate& ea, const UnitEstimate& eb);

}  // namespace gvm::exact
