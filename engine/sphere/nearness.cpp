#include "sphere/nearness.h"

#include <array>
#include <cmath>

#include "sphere/d3.h"
#include "sphere/local_visibility_map.h"
#include "sphere/set_operations.h"

namespace gvm::sphere {
namespace {

using exact::ExactVec;

// |a . b| of the exact unit vectors is at least this (certified from the estimates; 0 when
// they cannot tell): a filter that spares the exact test of arcs whose circle is far.
double dot_at_least(const exact::UnitEstimate& a, const exact::UnitEstimate& b) {
  const double d = std::fabs(a.unit[0] * b.unit[0] + a.unit[1] * b.unit[1] + a.unit[2] * b.unit[2]);
  return d - (a.radius + b.radius + a.radius * b.radius + 0x1p-48);
}

// An end a of an arc within theta of c: closer than 90 degrees, and sin^2 of the angle at
// most s2.
bool end_near(const ExactVec& c, const ExactVec& a, double s2) {
  return exact::sign_dot(c, a) == Sign::kPositive && exact::sign_sin2_angle_minus(c, a, s2) != Sign::kPositive;
}

// The closed arc within theta of c. Its circle's point nearest c is n x (c x n); along the
// circle the distance grows both ways from it, so the arc's nearest point is that one when
// the arc holds it, else the nearer end. The distance to the circle d has
// sin(d) = |cos(angle(c, n))|. c at a pole of the circle is 90 degrees from all of it.
bool arc_near(const Arc& arc, const ExactVec& c, const exact::UnitEstimate& ec, double s2) {
  const double far = dot_at_least(ec, exact::unit_estimate(arc.normal));
  if (far > 0 && far * far > s2 * (1 + 0x1p-40)) return false;  // the whole circle is farther
  const ExactVec closest = exact::cross(arc.normal, exact::cross(c, arc.normal));
  if (exact::is_zero(closest)) return false;
  if (arc_contains(arc, closest)) return exact::sign_cos2_angle_minus(c, arc.normal, s2) != Sign::kPositive;
  return !arc.full && (end_near(c, arc.start, s2) || end_near(c, arc.end, s2));
}

bool boundary_near(const SphericalImage& set, const ExactVec& c, double s2) {
  const exact::UnitEstimate ec = exact::unit_estimate(c);
  for (const Face& f : set.faces()) {
    for (const Loop& l : f.loops) {
      for (const Arc& a : l.arcs) {
        if (arc_near(a, c, ec, s2)) return true;
      }
    }
  }
  for (const Arc& a : set.curves()) {
    if (arc_near(a, c, ec, s2)) return true;
  }
  for (const ExactVec& p : set.points()) {
    if (end_near(c, p, s2)) return true;
  }
  return false;
}

}  // namespace

bool within_angle(const SphericalImage& set, const ExactVec& u, double s2) {
  if (set.is_full_sphere() || set.contains(u)) return true;
  return s2 > 0 && boundary_near(set, u, s2);
}

// Disjoint closed sets bounded by great-circle arcs are nearest at a corner of one of them:
// two arcs that do not cross are nearest where one of them ends (at a pair of interior
// points the joining geodesic would be perpendicular to both, where the distance to the
// other's circle is at its largest along the first arc, not its least), and whole circles
// always cross.
bool sets_within_angle(const SphericalImage& a, const SphericalImage& b, double s2) {
  if (a.is_empty() || b.is_empty()) return false;
  for (const ExactVec& v : corners(a)) {
    if (within_angle(b, v, s2)) return true;
  }
  for (const ExactVec& v : corners(b)) {
    if (within_angle(a, v, s2)) return true;
  }
  return !set_intersection(a, b).is_empty();
}

std::vector<ExactVec> corners(const SphericalImage& set) {
  std::vector<ExactVec> out = set.points();
  auto add = [&](const Arc& arc) {
    if (arc.full) return;
    out.push_back(arc.start);
    out.push_back(arc.end);
  };
  for (const Arc& a : set.curves()) add(a);
  for (const Face& f : set.faces()) {
    for (const Loop& l : f.loops) {
      for (const Arc& a : l.arcs) {
        if (!a.full) out.push_back(a.start);
      }
    }
  }
  return out;
}

namespace {

ExactVec exact_of(const D3& v) { return ExactVec::from_point({v[0], v[1], v[2]}); }

// The convex quadrilateral with these corners (doubles taken exactly), as the LVM of its
// edges' circles, each oriented towards `inside`.
SphericalImage quadrilateral(const std::array<D3, 4>& v, const ExactVec& inside) {
  std::vector<ExactVec> normals;
  for (int i = 0; i < 4; ++i) {
    ExactVec m = exact::cross(exact_of(v[i]), exact_of(v[(i + 1) % 4]));
    if (exact::sign_dot(m, inside) == Sign::kNegative) m = -m;
    normals.push_back(m);
  }
  return local_visibility_map(normals);
}

// The quadrilateral's boundary arcs are all farther than theta from `piece`, which it holds.
bool holds_with_margin(const SphericalImage& quad, const SphericalImage& piece, const std::vector<ExactVec>& ends,
                       double s2) {
  if (quad.faces().size() != 1 || quad.dimension() != 2) return false;
  for (const ExactVec& e : ends) {
    if (!quad.contains(e)) return false;
  }
  for (const Loop& l : quad.faces().front().loops) {
    for (const Arc& a : l.arcs) {
      SphericalImage edge;
      edge.add_curve(a);
      if (sets_within_angle(edge, piece, s2)) return false;
    }
  }
  return true;
}

// A certified quadrilateral around the arc piece p -> q on the circle with normal n (or
// around the point p when q is p), corners a distance of about `delta` outside it.
std::optional<SphericalImage> piece_cover(const ExactVec& p, const ExactVec& q, const ExactVec* n, double theta,
                                          double s2) {
  const D3 pu = unit_estimate(p).unit, qu = unit_estimate(q).unit;
  D3 nu, back, ahead;
  SphericalImage piece;
  std::vector<ExactVec> ends = {p};
  if (n) {
    nu = unit_estimate(*n).unit;
    back = normalized(cross(pu, nu));   // -(n x p): backwards along the arc at p
    ahead = normalized(cross(nu, qu));  // n x q: onwards at q
    piece.add_curve({p, q, *n, false});
    ends.push_back(q);
  } else {
    const D3 a = std::fabs(pu[0]) < 0.6 ? D3{1, 0, 0} : D3{0, 1, 0};
    nu = normalized(cross(pu, a));
    back = cross(nu, pu);
    ahead = {-back[0], -back[1], -back[2]};
    piece.add_point(p);
  }
  double delta = 1.5 * std::tan(theta) + 1e-15;
  for (int attempt = 0; attempt < 6; ++attempt, delta *= 2) {
    auto at = [&](const D3& base, const D3& along, double side) {
      return D3{base[0] + delta * (along[0] + side * nu[0]), base[1] + delta * (along[1] + side * nu[1]),
                base[2] + delta * (along[2] + side * nu[2])};
    };
    const std::array<D3, 4> corners = {at(pu, back, 1), at(pu, back, -1), at(qu, ahead, -1), at(qu, ahead, 1)};
    const ExactVec middle = n ? p + q : p;
    SphericalImage quad = quadrilateral(corners, exact::is_zero(middle) ? p : middle);
    if (holds_with_margin(quad, piece, ends, s2)) return quad;
  }
  return std::nullopt;
}

}  // namespace

std::optional<SphericalImage> dilation_cover(const SphericalImage& set, double theta, double s2) {
  if (set.is_full_sphere() || set.is_empty() || !(theta > 0)) return set;
  SphericalImage out = set;
  auto cover_arc = [&](const Arc& arc) {
    const std::vector<ExactVec> v = split_arc_quarters(arc);
    for (size_t i = 0; i + 1 < v.size(); ++i) {
      std::optional<SphericalImage> quad = piece_cover(v[i], v[i + 1], &arc.normal, theta, s2);
      if (!quad) return false;
      out.add_face(quad->faces().front());
    }
    return true;
  };
  for (const Face& f : set.faces())
    for (const Loop& l : f.loops)
      for (const Arc& a : l.arcs)
        if (!cover_arc(a)) return std::nullopt;
  for (const Arc& a : set.curves())
    if (!cover_arc(a)) return std::nullopt;
  for (const ExactVec& p : set.points()) {
    std::optional<SphericalImage> quad = piece_cover(p, p, nullptr, theta, s2);
    if (!quad) return std::nullopt;
    out.add_face(quad->faces().front());
  }
  return out;
}

}  // namespace gvm::sphere
