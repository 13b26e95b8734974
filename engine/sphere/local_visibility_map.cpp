#include "sphere/local_visibility_map.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace gvm::sphere {
namespace {

using exact::ExactVec;

// Distinct directions in input order. Candidates for equality are found by sorting
// certified unit estimates (a direction equals another only if their boxes overlap); the
// exact test decides. Faces of one plane share a normal, so most inputs are duplicates.
std::vector<ExactVec> distinct_directions(std::span<const ExactVec> normals) {
  std::vector<size_t> live;
  std::vector<exact::UnitEstimate> est(normals.size());
  for (size_t i = 0; i < normals.size(); ++i) {
    if (exact::is_zero(normals[i])) continue;
    est[i] = exact::unit_estimate(normals[i]);
    live.push_back(i);
  }
  std::vector<size_t> order = live;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return est[a].unit[0] - est[a].radius < est[b].unit[0] - est[b].radius;
  });
  std::vector<size_t> first(normals.size());
  for (size_t i : live) first[i] = i;
  for (size_t a = 0; a < order.size(); ++a) {
    const size_t i = order[a];
    if (first[i] != i) continue;  // already known to equal an earlier direction
    for (size_t b = a + 1; b < order.size(); ++b) {
      const size_t j = order[b];
      if (est[j].unit[0] - est[j].radius > est[i].unit[0] + est[i].radius) break;
      if (first[j] != j) continue;
      bool overlap = std::fabs(est[i].unit[1] - est[j].unit[1]) <= est[i].radius + est[j].radius &&
                     std::fabs(est[i].unit[2] - est[j].unit[2]) <= est[i].radius + est[j].radius;
      if (overlap && exact::same_direction(normals[i], normals[j])) {
        first[std::max(i, j)] = std::min(i, j);
      }
    }
  }
  std::vector<ExactVec> out;
  for (size_t i : live) {
    if (first[i] == i) out.push_back(normals[i]);
  }
  return out;
}

// --- Normals spanning space: the cone {u . n_i >= 0} is pointed, so its trace on the
// sphere lies in an open hemisphere. Start from the simplicial cone of three independent
// normals and clip it by every hemisphere; the set stays a convex polygon, an arc shorter
// than 180 degrees, a point, or becomes empty. Every vertex is +-(n_i x n_j).

struct Corner {
  ExactVec v;    // vertex
  ExactVec out;  // normal of the edge leaving v (counter-clockwise around it)
};

struct PointedClipper {
  enum Kind { kPolygon, kArc, kPoint, kEmpty } kind = kPolygon;
  std::vector<Corner> poly;
  ExactVec a, b, c;  // arc from a to b around c; a is also the point

  PointedClipper(const ExactVec& n0, ExactVec n1, ExactVec n2) {
    if (exact::sign_det(n0, n1, n2) == Sign::kNegative) std::swap(n1, n2);
    // det(n0, n1, n2) > 0: n1 x n2 has n0-side positive, and so on cyclically.
    poly = {{cross(n2, n0), n0}, {cross(n0, n1), n1}, {cross(n1, n2), n2}};
  }

  void clip(const ExactVec& n) {
    switch (kind) {
      case kPolygon:
        clip_polygon(n);
        break;
      case kArc:
        clip_arc(n);
        break;
      case kPoint:
        if (exact::sign_dot(a, n) == Sign::kNegative) kind = kEmpty;
        break;
      case kEmpty:
        break;
    }
  }

  void clip_polygon(const ExactVec& n) {
    size_t k = poly.size();
    std::vector<Sign> s(k);
    bool any_pos = false, any_neg = false;
    for (size_t i = 0; i < k; ++i) {
      s[i] = exact::sign_dot(poly[i].v, n);
      any_pos = any_pos || s[i] == Sign::kPositive;
      any_neg = any_neg || s[i] == Sign::kNegative;
    }
    if (!any_neg) return;
    if (!any_pos) {
      // The polygon lies in {u . n <= 0}: what remains is its face on the circle of n.
      std::vector<size_t> zeros;
      for (size_t i = 0; i < k; ++i) {
        if (s[i] == Sign::kZero) zeros.push_back(i);
      }
      if (zeros.empty()) {
        kind = kEmpty;
      } else if (zeros.size() == 1) {
        kind = kPoint;
        a = poly[zeros[0]].v;
      } else {
        // Two adjacent vertices (a full-dimensional convex polygon has no other face).
        size_t i = (zeros[1] == zeros[0] + 1) ? zeros[0] : zeros[1];
        kind = kArc;
        a = poly[i].v;
        b = poly[(i + 1) % k].v;
        c = poly[i].out;
      }
      poly.clear();
      return;
    }
    std::vector<Corner> next;
    next.reserve(k + 1);
    for (size_t i = 0; i < k; ++i) {
      size_t j = (i + 1) % k;
      const Corner& ci = poly[i];
      if (s[i] != Sign::kNegative) {
        if (s[j] != Sign::kNegative) {
          next.push_back(ci);
        } else if (s[i] == Sign::kZero) {
          next.push_back({ci.v, n});  // leaves along the circle of n
        } else {
          next.push_back(ci);
          // Exit point: moving counter-clockwise around c, u . n decreases at c x n.
          next.push_back({cross(ci.out, n), n});
        }
      } else if (s[j] == Sign::kPositive) {
        // Entry point: u . n increases at n x c.
        next.push_back({cross(n, ci.out), ci.out});
      }
    }
    poly = std::move(next);
  }

  void clip_arc(const ExactVec& n) {
    Sign sa = exact::sign_dot(a, n), sb = exact::sign_dot(b, n);
    if (sa != Sign::kNegative && sb != Sign::kNegative) return;
    if (sa != Sign::kPositive && sb != Sign::kPositive) {
      if (sa == Sign::kZero) {
        kind = kPoint;
      } else if (sb == Sign::kZero) {
        kind = kPoint;
        a = b;
      } else {
        kind = kEmpty;
      }
      return;
    }
    if (sa == Sign::kPositive) {
      b = cross(c, n);
    } else {
      a = cross(n, c);
    }
  }

  SphericalImage result() const {
    SphericalImage out;
    switch (kind) {
      case kPolygon: {
        Face f;
        f.convex = true;
        Loop l;
        for (size_t i = 0; i < poly.size(); ++i) {
          l.arcs.push_back(Arc{poly[i].v, poly[(i + 1) % poly.size()].v, poly[i].out, false});
        }
        f.loops.push_back(std::move(l));
        out.add_face(std::move(f));
        break;
      }
      case kArc:
        out.add_curve(Arc{a, b, c, false});
        break;
      case kPoint:
        out.add_point(a);
        break;
      case kEmpty:
        break;
    }
    return out;
  }
};

// --- Normals spanning a plane P with normal m: LVM = R m + C2 where C2 is the cone of
// P cut by the half planes {u . n_i >= 0}. C2 contains no line (the normals span P), so it
// is a pointed sector (lune), a ray (half great circle from m to -m) or {0} (points m,
// -m). The sector is clipped like an arc; every ray is +-(m x n_i).

struct PlanarClipper {
  enum Kind { kSector, kRay, kZero } kind = kSector;
  ExactVec m;
  ExactVec a, na, b, nb;  // sector cone(a, b), a on the line of na, b on that of nb

  PlanarClipper(const ExactVec& n0, const ExactVec& n1) : m(cross(n0, n1)) {
    a = cross(m, n0);
    if (exact::sign_dot(a, n1) == Sign::kNegative) a = -a;
    na = n0;
    b = cross(m, n1);
    if (exact::sign_dot(b, n0) == Sign::kNegative) b = -b;
    nb = n1;
  }

  void clip(const ExactVec& n) {
    if (kind == kZero) return;
    Sign sa = exact::sign_dot(a, n);
    if (kind == kRay) {
      if (sa == Sign::kNegative) kind = kZero;
      return;
    }
    Sign sb = exact::sign_dot(b, n);
    if (sa != Sign::kNegative && sb != Sign::kNegative) return;
    if (sa != Sign::kPositive && sb != Sign::kPositive) {
      if (sa == Sign::kZero) {
        kind = kRay;
      } else if (sb == Sign::kZero) {
        kind = kRay;
        a = b;
        na = nb;
      } else {
        kind = kZero;
      }
      return;
    }
    // The line of n crosses the sector strictly inside: x = +-(m x n), on the side of the
    // endpoint that stays.
    ExactVec x = cross(m, n);
    if (sa == Sign::kPositive) {
      if (exact::sign_dot(x, na) == Sign::kNegative) x = -x;
      b = x;
      nb = n;
    } else {
      if (exact::sign_dot(x, nb) == Sign::kNegative) x = -x;
      a = x;
      na = n;
    }
  }

  // The half great circle from m or -m to its antipode on the circle of c (c orthogonal to
  // m and r), passing through r, oriented counter-clockwise around c.
  Arc half_circle(const ExactVec& c, const ExactVec& r) const {
    ExactVec start = exact::sign_dot(cross(c, m), r) == Sign::kPositive ? m : -m;
    return Arc{start, -start, c, false};
  }

  SphericalImage result() const {
    SphericalImage out;
    switch (kind) {
      case kZero:
        out.add_point(m);
        out.add_point(-m);
        break;
      case kRay:
        out.add_curve(half_circle(na, a));
        break;
      case kSector: {
        // The lune {u . na >= 0, u . nb >= 0}: its sides lie on the circles of na (through
        // a) and nb (through b); region to the left of both.
        Arc first = half_circle(na, a);
        Arc second = half_circle(nb, b);
        Face f;
        f.convex = true;
        f.loops.push_back(Loop{{first, second}});
        out.add_face(std::move(f));
        break;
      }
    }
    return out;
  }
};

}  // namespace

SphericalImage local_visibility_map(std::span<const ExactVec> normals) {
  std::vector<ExactVec> u = distinct_directions(normals);
  if (u.empty()) return SphericalImage::full_sphere();
  const ExactVec& n0 = u[0];
  size_t i1 = 1;
  while (i1 < u.size() && exact::parallel(n0, u[i1])) ++i1;
  if (i1 == u.size()) {
    // All normals along one line: one direction (hemisphere) or both (great circle).
    if (u.size() == 1) return SphericalImage::hemisphere(n0);
    return SphericalImage::great_circle(n0);
  }
  const ExactVec& n1 = u[i1];
  ExactVec m = cross(n0, n1);
  size_t i2 = 0;
  while (i2 < u.size() && exact::sign_dot(u[i2], m) == Sign::kZero) ++i2;
  if (i2 == u.size()) {
    PlanarClipper clipper(n0, n1);
    for (size_t i = 1; i < u.size(); ++i) {
      if (i != i1) clipper.clip(u[i]);
    }
    return clipper.result();
  }
  PointedClipper clipper(n0, n1, u[i2]);
  for (size_t i = 1; i < u.size(); ++i) {
    if (i != i1 && i != i2) clipper.clip(u[i]);
  }
  return clipper.result();
}

bool in_spherical_convex_hull(std::span<const ExactVec> normals, const ExactVec& n) {
  return local_visibility_map(normals).within_closed_hemisphere(n);
}

}  // namespace gvm::sphere
