// Hole bridges and ear clipping on integer coordinates (planar_triangulation.h).
#include "step/faithful/planar_triangulation.h"

#include <algorithm>
#include <numeric>

#include "step/faithful/int_vec.h"

namespace gvm::faithful {
namespace {

i128 orient(const Point2& a, const Point2& b, const Point2& c) {
  return i128(b[0] - a[0]) * (c[1] - a[1]) - i128(b[1] - a[1]) * (c[0] - a[0]);
}
int sgn(i128 v) { return (v > 0) - (v < 0); }

i128 doubled_area(const std::vector<Point2>& p) {
  i128 s = 0;
  for (size_t k = 0; k < p.size(); ++k) {
    const Point2& a = p[k];
    const Point2& b = p[(k + 1) % p.size()];
    s += i128(a[0]) * b[1] - i128(b[0]) * a[1];
  }
  return s;
}

bool on_segment(const Point2& a, const Point2& b, const Point2& p) {
  return orient(a, b, p) == 0 && std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
}

// Closed segments a-b and c-d share a point.
bool meet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int o1 = sgn(orient(a, b, c)), o2 = sgn(orient(a, b, d)), o3 = sgn(orient(c, d, a)), o4 = sgn(orient(c, d, b));
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

struct Node {
  uint32_t id;
  Point2 p;
  size_t prev, next;
};

class Polygon {
 public:
  // Counter-clockwise outer loop after mirroring where needed; holes clockwise.
  bool build(const std::vector<PlanarLoop>& loops, std::string& why) {
    mirror_ = doubled_area(loops[0].xy) < 0;
    for (size_t l = 0; l < loops.size(); ++l) {
      std::vector<Point2> xy = loops[l].xy;
      if (mirror_)
        for (Point2& p : xy) p[0] = -p[0];
      const i128 area = doubled_area(xy);
      if (area == 0 || (l == 0) != (area > 0)) {
        why = l == 0 ? "the outer boundary has zero area" : "a hole does not run opposite to the outer boundary";
        return false;
      }
      total_area_ += area;
      std::vector<size_t> ring;
      for (size_t k = 0; k < xy.size(); ++k) ring.push_back(add(loops[l].ids[k], xy[k]));
      link(ring);
      if (l > 0) holes_.push_back(ring.front());
      else outer_ = ring.front();
    }
    return true;
  }

  bool bridge_holes(std::string& why) {
    // Rightmost holes first, each to the nearest outer point it sees.
    std::vector<size_t> order;
    for (size_t h : holes_) order.push_back(rightmost(h));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return n_[a].p[0] > n_[b].p[0]; });
    merged_.assign(n_.size(), false);
    mark(outer_);
    for (size_t m : order) {
      const size_t v = visible_outer(m);
      if (v == SIZE_MAX) {
        why = "a hole sees no point of the outer boundary";
        return false;
      }
      splice(v, m);
      mark(m);
    }
    return true;
  }

  bool clip(std::vector<std::array<uint32_t, 3>>& out, std::string& why) {
    size_t ear = outer_, stop = outer_;
    size_t left = 0;
    for (size_t k = ear; ; k = n_[k].next) { ++left; if (n_[k].next == ear) break; }
    i128 clipped = 0;
    while (left > 3) {
      const Node& b = n_[ear];
      if (is_ear(ear)) {
        emit(n_[b.prev], b, n_[b.next], out, clipped);
        const size_t next = b.next;
        unlink(ear);
        --left;
        ear = stop = n_[next].next;
        continue;
      }
      ear = b.next;
      if (ear == stop) {
        why = "ear clipping found no ear (the boundary overlaps itself)";
        return false;
      }
    }
    const Node& b = n_[ear];
    if (orient(n_[b.prev].p, b.p, n_[b.next].p) <= 0) {
      why = "the last triangle has no area";
      return false;
    }
    emit(n_[b.prev], b, n_[b.next], out, clipped);
    if (clipped != total_area_) {
      why = "the triangles do not cover the face exactly once";
      return false;
    }
    return true;
  }

 private:
  size_t add(uint32_t id, const Point2& p) {
    n_.push_back({id, p, 0, 0});
    return n_.size() - 1;
  }
  void link(const std::vector<size_t>& ring) {
    for (size_t k = 0; k < ring.size(); ++k) {
      n_[ring[k]].next = ring[(k + 1) % ring.size()];
      n_[ring[k]].prev = ring[(k + ring.size() - 1) % ring.size()];
    }
  }
  void unlink(size_t k) {
    n_[n_[k].prev].next = n_[k].next;
    n_[n_[k].next].prev = n_[k].prev;
  }
  void mark(size_t start) {
    size_t k = start;
    do merged_[k] = true, k = n_[k].next;
    while (k != start);
  }
  size_t rightmost(size_t start) const {
    size_t best = start, k = start;
    do {
      if (n_[k].p[0] > n_[best].p[0] || (n_[k].p[0] == n_[best].p[0] && n_[k].p[1] < n_[best].p[1])) best = k;
      k = n_[k].next;
    } while (k != start);
    return best;
  }

  // Direction v -> m inside the polygon's angle at v (prev, v, next).
  bool inside_wedge(size_t v, const Point2& m) const {
    const Point2 &a = n_[n_[v].prev].p, &b = n_[v].p, &c = n_[n_[v].next].p;
    if (orient(a, b, c) >= 0) return orient(a, b, m) > 0 && orient(b, c, m) > 0;  // convex
    return orient(a, b, m) > 0 || orient(b, c, m) > 0;                              // reflex
  }

  // The segment m - v meets no edge but at its ends.
  bool clear(size_t m, size_t v) const {
    const Point2 &pm = n_[m].p, &pv = n_[v].p;
    for (size_t e = 0; e < n_.size(); ++e) {
      if (!alive(e)) continue;
      const Point2 &a = n_[e].p, &b = n_[n_[e].next].p;
      const bool touches_end = a == pm || a == pv || b == pm || b == pv;
      if (!touches_end) {
        if (meet(pm, pv, a, b)) return false;
        continue;
      }
      // An edge from one end: only its other end lying on the segment blocks.
      for (const Point2* q : {&a, &b})
        if (*q != pm && *q != pv && on_segment(pm, pv, *q)) return false;
    }
    return true;
  }

  size_t visible_outer(size_t m) const {
    std::vector<size_t> candidates;
    for (size_t k = 0; k < n_.size(); ++k)
      if (merged_[k] && alive(k) && n_[k].p[0] >= n_[m].p[0]) candidates.push_back(k);
    for (size_t k = 0; k < n_.size(); ++k)
      if (merged_[k] && alive(k) && n_[k].p[0] < n_[m].p[0]) candidates.push_back(k);
    auto dist = [&](size_t k) {
      const i128 dx = n_[k].p[0] - n_[m].p[0], dy = n_[k].p[1] - n_[m].p[1];
      return dx * dx + dy * dy;
    };
    std::stable_sort(candidates.begin(), candidates.end(), [&](size_t a, size_t b) { return dist(a) < dist(b); });
    for (size_t v : candidates)
      if (n_[v].p != n_[m].p && inside_wedge(v, n_[m].p) && clear(m, v)) return v;
    return SIZE_MAX;
  }

  // ... v, m, (hole from m round to m), m', v', ...
  void splice(size_t v, size_t m) {
    const size_t v2 = add(n_[v].id, n_[v].p), m2 = add(n_[m].id, n_[m].p);
    merged_.resize(n_.size(), true);
    const size_t v_next = n_[v].next, m_prev = n_[m].prev;
    n_[v].next = m, n_[m].prev = v;
    n_[m_prev].next = m2, n_[m2].prev = m_prev;
    n_[m2].next = v2, n_[v2].prev = m2;
    n_[v2].next = v_next, n_[v_next].prev = v2;
  }

  bool alive(size_t k) const { return n_[n_[k].next].prev == k; }

  bool is_ear(size_t k) const {
    const Point2 &a = n_[n_[k].prev].p, &b = n_[k].p, &c = n_[n_[k].next].p;
    if (orient(a, b, c) <= 0) return false;
    for (size_t q = n_[n_[k].next].next; q != n_[k].prev; q = n_[q].next) {
      const Point2& p = n_[q].p;
      if (p == a || p == b || p == c) continue;
      if (orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0) return false;
    }
    return true;
  }

  void emit(const Node& a, const Node& b, const Node& c, std::vector<std::array<uint32_t, 3>>& out, i128& area) const {
    out.push_back({a.id, b.id, c.id});
    area += orient(a.p, b.p, c.p);
  }

  std::vector<Node> n_;
  std::vector<size_t> holes_;
  std::vector<bool> merged_;
  size_t outer_ = 0;
  bool mirror_ = false;
  i128 total_area_ = 0;
};

}  // namespace

bool triangulate_planar(const std::vector<PlanarLoop>& loops, std::vector<std::array<uint32_t, 3>>& out,
                        std::string& why) {
  if (loops.empty() || loops[0].ids.size() < 3) {
    why = "the face has no boundary of three points";
    return false;
  }
  Polygon polygon;
  return polygon.build(loops, why) && polygon.bridge_holes(why) && polygon.clip(out, why);
}

}  // namespace gvm::faithful
