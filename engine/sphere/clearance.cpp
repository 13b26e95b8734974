#include "sphere/clearance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sphere/d3.h"
#include "sphere/set_operations.h"

namespace gvm::sphere {
namespace {

using exact::ExactVec;

constexpr double kPi = 3.14159265358979323846;

// The point of the arc's circle closest to c is n x (c x n) (zero when c is a pole of the
// circle: every point of it is then 90 degrees away). The distance from c to the arc is
// the distance to the circle when that point is on the arc, else the distance to the
// nearer end: along the circle the distance grows both ways from the closest point.
// Compared with theta <= 90 degrees through squares, exactly:
//  - to the circle: sin(distance) = |cos(angle(c, n))|, so distance >= theta iff
//    cos^2(angle(c, n)) >= s2;
//  - to an end a: beyond 90 degrees (c . a <= 0) always; else iff sin^2(angle(c, a)) >= s2.
bool end_clear(const ExactVec& c, const ExactVec& a, double s2) {
  return exact::sign_dot(c, a) != Sign::kPositive || exact::sign_sin2_angle_minus(c, a, s2) != Sign::kNegative;
}

bool arc_clear(const Arc& arc, const ExactVec& c, double s2) {
  const ExactVec closest = exact::cross(arc.normal, exact::cross(c, arc.normal));
  if (exact::is_zero(closest)) return true;
  if (arc_contains(arc, closest)) return exact::sign_cos2_angle_minus(c, arc.normal, s2) != Sign::kNegative;
  return end_clear(c, arc.start, s2) && end_clear(c, arc.end, s2);
}

// The cap lies in the closed face: the center is in it and no boundary arc is closer than
// theta (a boundary point closer than theta would be interior to the cap, hence to the
// face; a point of the cap outside the face would put a boundary point on the way to it).
bool face_holds_cap(const Face& f, const ExactVec& c, double s2) {
  if (!face_contains(f, c)) return false;
  for (const Loop& l : f.loops) {
    for (const Arc& a : l.arcs) {
      if (!arc_clear(a, c, s2)) return false;
    }
  }
  return true;
}

// --- doubles, for searching ---

D3 unit(const ExactVec& v) { return exact::unit_estimate(v).unit; }
double angle(const D3& a, const D3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

// Angular position of unit v along the circle with unit normal n, from unit `from`, in
// [0, 2 pi).
double position(const D3& n, const D3& from, const D3& v) {
  double t = std::atan2(dot(n, cross(from, v)), dot(from, v));
  return t < 0 ? t + 2 * kPi : t;
}

double distance_to_arc(const D3& u, const Arc& arc) {
  const D3 n = unit(arc.normal);
  const D3 closest = cross(n, cross(u, n));
  const double to_circle = std::atan2(std::fabs(dot(u, n)), norm(cross(u, n)));
  if (norm(closest) == 0) return kPi / 2;
  if (arc.full) return to_circle;
  const D3 a = unit(arc.start), b = unit(arc.end);
  double length = position(n, a, b);
  if (length == 0 && !exact::same_direction(arc.start, arc.end)) length = 2 * kPi;
  if (position(n, a, closest) <= length) return to_circle;
  return std::min(angle(u, a), angle(u, b));
}

double distance_to_face_boundary(const D3& u, const Face& f) {
  double d = kPi;
  for (const Loop& l : f.loops) {
    for (const Arc& a : l.arcs) d = std::min(d, distance_to_arc(u, a));
  }
  return d;
}

}  // namespace

bool contains_cap(const SphericalImage& set, const ExactVec& center, double s2) {
  if (set.is_full_sphere()) return true;
  if (!(s2 > 0)) return set.contains(center);
  bool in_some_face = false;
  for (const Face& f : set.faces()) {
    if (face_holds_cap(f, center, s2)) return true;
    in_some_face = in_some_face || face_contains(f, center);
  }
  if (!in_some_face || set.faces().size() < 2) return false;
  // Faces that overlap or share edges may hold the cap together: their union, as
  // faces meeting at most at vertices, holds it iff one of its faces does (a cap with
  // interior does not pass through a single point between two faces).
  SphericalImage faces;
  for (const Face& f : set.faces()) faces.add_face(f);
  const SphericalImage merged = set_union(faces, SphericalImage::empty());
  if (merged.is_full_sphere()) return true;
  for (const Face& f : merged.faces()) {
    if (face_holds_cap(f, center, s2)) return true;
  }
  return false;
}

double approx_signed_clearance(const SphericalImage& set, const std::array<double, 3>& u) {
  if (set.is_full_sphere()) return kPi;
  if (set.is_empty()) return -kPi;
  const ExactVec exact_u = ExactVec::from_point({u[0], u[1], u[2]});
  double inside = -1;
  for (const Face& f : set.faces()) {
    if (face_contains(f, exact_u)) inside = std::max(inside, distance_to_face_boundary(u, f));
  }
  if (inside >= 0) return inside;
  if (set.contains(exact_u)) return 0;
  double d = kPi;
  for (const Face& f : set.faces()) d = std::min(d, distance_to_face_boundary(u, f));
  for (const Arc& a : set.curves()) d = std::min(d, distance_to_arc(u, a));
  for (const ExactVec& p : set.points()) d = std::min(d, angle(u, unit(p)));
  return -d;
}

}  // namespace gvm::sphere
