#include "part/convex_hull.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <random>
#include <unordered_set>

#include "exact/filtered.h"
#include "exact/predicates.h"

namespace gvm::part {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

struct Facet {
  uint32_t v[3];
  uint32_t nb[3];  // nb[i]: facet across edge (v[i], v[i+1])
  bool alive = true;
  std::vector<uint32_t> conflicts;  // points strictly outside, assigned to this facet
};

class Builder {
 public:
  explicit Builder(std::span<const Point3> pts) : p_(pts) {}

  bool outside(uint32_t f, uint32_t q) const {
    const Facet& F = facets_[f];
    return exact::orient3d(p_[F.v[0]], p_[F.v[1]], p_[F.v[2]], p_[q]) == Sign::kPositive;
  }

  ConvexHull run(std::span<const uint32_t> use) {
    ConvexHull hull;
    if (use.size() < 4) return hull;
    // Initial tetrahedron: lexicographic extremes, then the first point off their line,
    // then the first point off their plane.
    uint32_t a = use[0], b = use[0];
    for (uint32_t q : use) {
      if (exact::compare_lex(p_[q], p_[a]) < 0) a = q;
      if (exact::compare_lex(p_[q], p_[b]) > 0) b = q;
    }
    if (a == b) return hull;
    uint32_t c = kNone, d = kNone;
    for (uint32_t q : use)
      if (!exact::collinear(p_[a], p_[b], p_[q])) { c = q; break; }
    if (c == kNone) return hull;
    for (uint32_t q : use)
      if (exact::orient3d(p_[a], p_[b], p_[c], p_[q]) != Sign::kZero) { d = q; break; }
    if (d == kNone) return hull;
    if (exact::orient3d(p_[a], p_[b], p_[c], p_[d]) == Sign::kPositive) std::swap(b, c);
    // Now d is behind (a, b, c); these four facets are all oriented outward.
    add_facet(a, b, c);
    add_facet(a, d, b);
    add_facet(b, d, c);
    add_facet(c, d, a);
    for (uint32_t f = 0; f < 4; ++f)
      for (int i = 0; i < 3; ++i) {
        uint32_t u = facets_[f].v[i], w = facets_[f].v[(i + 1) % 3];
        for (uint32_t g = 0; g < 4; ++g)
          for (int j = 0; j < 3; ++j)
            if (facets_[g].v[j] == w && facets_[g].v[(j + 1) % 3] == u) facets_[f].nb[i] = g;
      }

    point_facet_.assign(p_.size(), kNone);
    std::vector<uint32_t> order;
    order.reserve(use.size());
    for (uint32_t q : use)
      if (q != a && q != b && q != c && q != d) order.push_back(q);
    const uint32_t first4[] = {0, 1, 2, 3};
    assign_conflicts(order, first4);
    std::mt19937_64 rng(0x9e3779b97f4a7c15ull);
    for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng() % i]);

    mark_.assign(facets_.size(), 0);
    start_of_.assign(p_.size(), kNone);
    end_of_.assign(p_.size(), kNone);
    for (uint32_t q : order)
      if (point_facet_[q] != kNone) insert(q);

    std::vector<uint32_t> deg(p_.size() + 1, 0);
    for (const Facet& f : facets_) {
      if (!f.alive) continue;
      hull.facets.push_back({f.v[0], f.v[1], f.v[2]});
      for (int i = 0; i < 3; ++i) ++deg[f.v[i] + 1];
    }
    for (size_t i = 1; i < deg.size(); ++i) deg[i] += deg[i - 1];
    hull.offset = deg;
    hull.vertex_facet.assign(p_.size(), kNone);
    for (uint32_t f = 0; f < hull.facets.size(); ++f)
      for (uint32_t v : hull.facets[f]) hull.vertex_facet[v] = f;
    hull.adjacency.resize(deg.back());
    for (const Triangle& t : hull.facets)
      for (int i = 0; i < 3; ++i) hull.adjacency[deg[t[i]]++] = t[(i + 1) % 3];
    hull.any_vertex = hull.facets.front()[0];
    return hull;
  }

 private:
  uint32_t add_facet(uint32_t a, uint32_t b, uint32_t c) {
    Facet f;
    f.v[0] = a, f.v[1] = b, f.v[2] = c;
    f.nb[0] = f.nb[1] = f.nb[2] = kNone;
    facets_.push_back(std::move(f));
    return static_cast<uint32_t>(facets_.size() - 1);
  }

  void insert(uint32_t q) {
    // Facets strictly visible from q: a connected set containing q's conflict facet.
    ++stamp_;
    const uint32_t kVisible = stamp_, kHidden = ++stamp_;
    visible_.clear();
    uint32_t f0 = point_facet_[q];
    mark_[f0] = kVisible;
    visible_.push_back(f0);
    for (size_t i = 0; i < visible_.size(); ++i) {
      const Facet& F = facets_[visible_[i]];
      for (uint32_t g : F.nb) {
        if (mark_[g] == kVisible || mark_[g] == kHidden) continue;
        if (outside(g, q)) {
          mark_[g] = kVisible;
          visible_.push_back(g);
        } else {
          mark_[g] = kHidden;
        }
      }
    }
    // One new facet (u, w, q) per horizon edge (u, w), keeping the edge's orientation.
    created_.clear();
    for (uint32_t f : visible_) {
      for (int i = 0; i < 3; ++i) {
        uint32_t g = facets_[f].nb[i];
        if (mark_[g] == kVisible) continue;
        uint32_t u = facets_[f].v[i], w = facets_[f].v[(i + 1) % 3];
        uint32_t nf = add_facet(u, w, q);
        facets_[nf].nb[0] = g;
        for (int j = 0; j < 3; ++j)
          if (facets_[g].nb[j] == f) facets_[g].nb[j] = nf;
        start_of_[u] = nf;
        end_of_[w] = nf;
        created_.push_back(nf);
      }
    }
    mark_.resize(facets_.size(), 0);
    for (uint32_t nf : created_) {
      Facet& F = facets_[nf];
      F.nb[1] = start_of_[F.v[1]];  // edge (w, q) is edge (q, w) of the facet starting at w
      F.nb[2] = end_of_[F.v[0]];    // edge (q, u) is edge (u, q) of the facet ending at u
    }
    // Reassign the points of the removed facets (quickhull rule: a point outside the new
    // hull is outside one of the new facets).
    point_facet_[q] = kNone;
    moving_.clear();
    for (uint32_t f : visible_) {
      Facet& F = facets_[f];
      F.alive = false;
      for (uint32_t r : F.conflicts)
        if (r != q) moving_.push_back(r);
      std::vector<uint32_t>().swap(F.conflicts);
    }
    assign_conflicts(moving_, created_);
  }

  // Each point of `points` to the first of `candidates` it is strictly outside of (or to
  // none), appended to that facet's conflicts in the order of `points`. The tests run in
  // parallel when there are many (the first insertions move nearly every point), the
  // lists are filled in order after: the hull is the same on any number of threads.
  void assign_conflicts(std::span<const uint32_t> points, std::span<const uint32_t> candidates) {
    auto first_outside = [&](uint32_t r) {
      for (uint32_t f : candidates)
        if (outside(f, r)) return f;
      return kNone;
    };
    constexpr size_t kParallelFrom = 4096;
    if (points.size() >= kParallelFrom) {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 1024), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) point_facet_[points[i]] = first_outside(points[i]);
      });
    } else {
      for (uint32_t r : points) point_facet_[r] = first_outside(r);
    }
    for (uint32_t r : points)
      if (point_facet_[r] != kNone) facets_[point_facet_[r]].conflicts.push_back(r);
  }

  std::span<const Point3> p_;
  std::vector<Facet> facets_;
  std::vector<uint32_t> point_facet_;
  std::vector<uint32_t> mark_;
  uint32_t stamp_ = 0;
  std::vector<uint32_t> visible_, created_, moving_;
  std::vector<uint32_t> start_of_, end_of_;
};

}  // namespace

ConvexHull convex_hull(std::span<const Point3> points, std::span<const uint32_t> use) {
  return Builder(points).run(use);
}

uint32_t hull_extreme_vertex(const ConvexHull& hull, std::span<const Point3> points,
                             const Point3& a, const Point3& b, const Point3& c,
                             uint32_t start) {
  // sign of ((b - a) x (c - a)) . (w - v)
  auto gain = [&](uint32_t v, uint32_t w) {
    return exact::det_diff(a, b, a, c, points[v], points[w]);
  };
  uint32_t v = start;
  for (;;) {
    bool moved = false, saw_less = false;
    for (uint32_t k = hull.offset[v]; k < hull.offset[v + 1] && !moved; ++k) {
      Sign s = gain(v, hull.adjacency[k]);
      if (s == Sign::kPositive) {
        v = hull.adjacency[k];
        moved = true;
      }
      saw_less |= s == Sign::kNegative;
    }
    if (moved) continue;
    // No improving neighbor. Unless every neighbor ties, v is an extreme point or lies on
    // an edge of the polytope, where the neighbors span the tangent cone: v is optimal.
    if (saw_less) return v;
    // All neighbors tie: v is inside a flat face orthogonal to n, the maximal face when
    // its outward normal agrees with n.
    const Triangle& f = hull.facets[hull.vertex_facet[v]];
    if (exact::normal_dot(a, b, c, points[f[0]], points[f[1]], points[f[2]]) != Sign::kNegative)
      return v;
    // The minimal face: walk its vertices (all tie) to one with an improving neighbor.
    std::vector<uint32_t> plateau{v};
    std::unordered_set<uint32_t> seen{v};
    uint32_t next = kNone;
    for (size_t i = 0; i < plateau.size() && next == kNone; ++i) {
      const uint32_t u = plateau[i];
      for (uint32_t k = hull.offset[u]; k < hull.offset[u + 1]; ++k) {
        const uint32_t w = hull.adjacency[k];
        Sign s = gain(u, w);
        if (s == Sign::kPositive) {
          next = w;
          break;
        }
        if (s == Sign::kZero && seen.insert(w).second) plateau.push_back(w);
      }
    }
    if (next == kNone) return v;  // unreachable for a solid: the polytope is not flat
    v = next;
  }
}

}  // namespace gvm::part
