#include "sphere/cell_witness.h"

#include <optional>

namespace gvm::sphere {
namespace {

using exact::ExactVec;

bool positive(Sign s) { return s == Sign::kPositive; }

// The ray of directions leaving m (strictly inside an edge of the face) at a right angle,
// into the face: the open half circle from m to -m through n, the edge's normal oriented
// with the face on its left. Its points y are those of the circle with normal c = m x n
// with det(c, m, y) > 0; along it, y1 comes before y2 iff det(c, y1, y2) > 0.
struct Ray {
  ExactVec m, n, c;
  bool holds(const ExactVec& y) const { return positive(exact::sign_det(c, m, y)); }
  bool before(const ExactVec& y1, const ExactVec& y2) const {
    return positive(exact::sign_det(c, y1, y2));
  }
};

// The first point where the closed minor arc p -> q (counter-clockwise around normal)
// meets the ray, if it does.
std::optional<ExactVec> first_meeting(const Ray& ray, const ExactVec& p, const ExactVec& q,
                                      const ExactVec& normal) {
  std::optional<ExactVec> best;
  auto offer = [&](const ExactVec& y) {
    if (ray.holds(y) && (!best || ray.before(y, *best))) best = y;
  };
  if (exact::parallel(normal, ray.c)) {
    // The arc lies on the ray's circle. It cannot contain m (m is inside another edge),
    // so if it meets the open half circle, one of its ends is there.
    offer(p);
    offer(q);
    return best;
  }
  // The circles meet at +-x; the one on the ray's side, if it is on the arc.
  ExactVec x = exact::cross(ray.c, normal);
  const Sign side = exact::sign_det(ray.c, ray.m, x);
  if (side == Sign::kZero) return best;  // x = +-m: not on the open half circle
  if (side == Sign::kNegative) x = -x;
  if (exact::sign_det(normal, p, x) != Sign::kNegative && exact::sign_det(normal, x, q) != Sign::kNegative) {
    best = x;
  }
  return best;
}

}  // namespace

ExactVec direction_inside_edge(const Arrangement& arr, uint32_t e) {
  const Arrangement::Edge& edge = arr.edges()[e];
  return arr.vertices()[edge.v0].p + arr.vertices()[edge.v1].p;
}

// Walk from the middle m of one boundary edge of the face straight into it (at a right
// angle, along the open half circle from m to -m) and stop half way to the first point
// where the face's boundary meets that path: every point of the path before it is inside
// the face, and any positive combination of m and that point lies strictly between them.
// With no boundary on the path at all, its middle n is inside.
ExactVec direction_inside_face(const Arrangement& arr, uint32_t f) {
  const uint32_t h0 = arr.faces()[f].first_half_edge;
  if (h0 == UINT32_MAX) return arr.vertices()[arr.reference_vertex()].p;  // the whole sphere
  const auto& half = arr.half_edges();
  const auto& edges = arr.edges();
  const auto& vertices = arr.vertices();
  auto dest = [&](uint32_t h) { return half[half[h].twin].origin; };
  const uint32_t e0 = half[h0].edge;
  const ExactVec m = vertices[half[h0].origin].p + vertices[dest(h0)].p;
  const ExactVec n = half[h0].forward ? edges[e0].normal : -edges[e0].normal;
  const Ray ray{m, n, exact::cross(m, n)};
  std::optional<ExactVec> first;
  uint32_t h = h0;
  do {
    const uint32_t e = half[h].edge;
    if (e != e0) {  // edge e0 meets the path's circle at m and -m only
      const Arrangement::Edge& edge = edges[e];
      if (auto y = first_meeting(ray, vertices[edge.v0].p, vertices[edge.v1].p, edge.normal)) {
        if (!first || ray.before(*y, *first)) first = *y;
      }
    }
    h = half[h].next;
  } while (h != h0);
  return first ? m + *first : n;
}

}  // namespace gvm::sphere
