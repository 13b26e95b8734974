#include "part/potentially_facing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "exact/exact_vec.h"
#include "exact/predicates.h"
#include "parallel/interrupt.h"

namespace gvm::part_internal {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
// Planes with fewer triangles of S stay with the per-triangle search.
constexpr size_t kMinPlaneTriangles = 16;

// A triangle's plane in doubles, {x : u . x + w = 0} with u about unit, and how far the
// value u . x + w may lie from the exact signed distance for any |x| <= the bound it was
// made with. Conditioning: the rounded cross product of two edges turns by about
// eps |e1| |e2| / |e1 x e2| radians, a sliver's by much more (its slack is then infinite).
// Doubles outside exact/ on purpose: the slack only decides which subtrees are skipped as
// certainly behind (condition (ii) false for all of them), and every triangle not skipped
// is decided by the exact predicates; a larger slack skips less and gives the same O_S.
struct ApproxPlane {
  double u[4];  // u[3] = w
  double slack;

  ApproxPlane(const SolidMesh& m, uint32_t t, double bound) {
    const Point3 &a = m.points[m.triangles[t][0]], &b = m.points[m.triangles[t][1]],
                 &c = m.points[m.triangles[t][2]];
    const double e[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, f[3] = {c.x - a.x, c.y - a.y, c.z - a.z};
    const double n[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double le = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    const double lf = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    constexpr double kEps = 0x1p-52;
    const double turn = 64 * kEps * le * lf / len + 64 * kEps;  // radians, generously
    slack = len > 0 && turn < 1e-3 ? (4 * turn + 256 * kEps) * bound : INFINITY;
    for (int k = 0; k < 3; ++k) u[k] = len > 0 ? n[k] / len : 0;
    u[3] = -(u[0] * a.x + u[1] * a.y + u[2] * a.z);
  }
};

// Bounding-box tree over a set of triangles (structure only: boxes are exact min/max of
// input coordinates, so corner points are input-like doubles usable in exact predicates).
// Each node also bounds its triangles' planes, coefficient by coefficient: a point whose
// largest value over those bounds is certainly negative lies strictly behind every plane.
struct BoxTree {
  struct Node {
    Point3 lo, hi;
    double plane_lo[4], plane_hi[4], slack = 0;
    uint32_t begin, end;  // range in `items`
    uint32_t left = kNone, right = kNone;
  };
  std::vector<Node> nodes;
  std::vector<uint32_t> items;

  // bound: at least the largest absolute coordinate of any point searched with.
  BoxTree(const SolidMesh& m, std::vector<uint32_t> tris, double bound) : items(std::move(tris)) {
    if (!items.empty()) build(m, 0, static_cast<uint32_t>(items.size()), bound);
  }

  uint32_t build(const SolidMesh& m, uint32_t begin, uint32_t end, double bound) {
    Node n;
    n.begin = begin, n.end = end;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int k = 0; k < 4; ++k) n.plane_lo[k] = INFINITY, n.plane_hi[k] = -INFINITY;
    for (uint32_t i = begin; i < end; ++i) {
      for (uint32_t v : m.triangles[items[i]])
        for (int k = 0; k < 3; ++k) {
          lo[k] = std::min(lo[k], m.points[v][k]);
          hi[k] = std::max(hi[k], m.points[v][k]);
        }
      const ApproxPlane plane(m, items[i], bound);
      for (int k = 0; k < 4; ++k) {
        n.plane_lo[k] = std::min(n.plane_lo[k], plane.u[k]);
        n.plane_hi[k] = std::max(n.plane_hi[k], plane.u[k]);
      }
      n.slack = std::max(n.slack, plane.slack);
    }
    n.lo = {lo[0], lo[1], lo[2]};
    n.hi = {hi[0], hi[1], hi[2]};
    uint32_t id = static_cast<uint32_t>(nodes.size());
    nodes.push_back(n);
    if (end - begin > 4) {
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
      auto key = [&](uint32_t t) {
        const Triangle& tr = m.triangles[t];
        return m.points[tr[0]][axis] + m.points[tr[1]][axis] + m.points[tr[2]][axis];
      };
      uint32_t mid = begin + (end - begin) / 2;
      std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                       [&](uint32_t x, uint32_t y) { return key(x) < key(y); });
      uint32_t l = build(m, begin, mid, bound);
      uint32_t r = build(m, mid, end, bound);
      nodes[id].left = l;
      nodes[id].right = r;
    }
    return id;
  }

  // Whether a, b and c certainly lie strictly behind the plane of every triangle of the
  // node: condition (ii) then fails for all of them. The largest value over the bounds
  // rounds by less than 8 eps (4 |x| + 1) <= 40 eps |x|, inside the slack.
  static bool behind_all(const Node& n, const Point3& a, const Point3& b, const Point3& c) {
    for (const Point3* x : {&a, &b, &c}) {
      double most = n.plane_hi[3];
      for (int k = 0; k < 3; ++k) most += std::max(n.plane_lo[k] * (*x)[k], n.plane_hi[k] * (*x)[k]);
      if (!(most < -n.slack)) return false;
    }
    return true;
  }

  // Calls leaf(i) for the items[i] of the leaves whose box has a corner strictly in front of
  // the plane (a, b, c) -- a certified prune for condition (i): the corner farthest along
  // the normal (chosen by its exact signs) is not in front, so no vertex in the box is --
  // and whose planes a, b, c are not all certainly behind (condition (ii)), until leaf
  // returns true; returns whether one did.
  template <class Leaf>
  bool search(const Point3& a, const Point3& b, const Point3& c, const exact::PlaneSide& side,
              const Leaf& leaf) const {
    if (nodes.empty()) return false;
    Sign ns[3];
    for (int k = 0; k < 3; ++k) ns[k] = exact::cross_component(a, b, c, k);
    uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes[stack[--top]];
      const Point3 corner{ns[0] == Sign::kPositive ? n.hi.x : n.lo.x,
                          ns[1] == Sign::kPositive ? n.hi.y : n.lo.y,
                          ns[2] == Sign::kPositive ? n.hi.z : n.lo.z};
      if (behind_all(n, a, b, c) || side(corner) != Sign::kPositive) continue;
      if (n.left != kNone) {
        stack[top++] = n.left;
        stack[top++] = n.right;
        continue;
      }
      for (uint32_t i = n.begin; i < n.end; ++i) {
        if (leaf(i)) return true;
      }
    }
    return false;
  }
};

// A key of the triangle's oriented plane in doubles; exactly coplanar triangles get the
// same key except at rounding boundaries (then they form two groups, which is only
// slower).
std::array<int64_t, 4> plane_key(const SolidMesh& m, uint32_t t, double scale) {
  const Point3 &a = m.points[m.triangles[t][0]], &b = m.points[m.triangles[t][1]],
               &c = m.points[m.triangles[t][2]];
  const double u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, v[3] = {c.x - a.x, c.y - a.y, c.z - a.z};
  double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(len > 0)) return {0, 0, 0, int64_t(t) + 1};  // alone
  for (double& x : n) x /= len;
  const double d = (n[0] * a.x + n[1] * a.y + n[2] * a.z) / scale;
  return {std::llround(n[0] * 1e6), std::llround(n[1] * 1e6), std::llround(n[2] * 1e6),
          std::llround(d * 1e6)};
}

}  // namespace

struct PotentiallyFacing::Impl {
  const SolidMesh& mesh;
  struct Plane {
    exact::PlaneSide side;        // (ii) holds for all triangles of the plane or for none
    std::vector<uint32_t> hull;   // vertices of the convex hull of its triangles' vertices
  };
  std::vector<Plane> planes;
  BoxTree rest;  // triangles of smaller planes: both conditions per triangle
  std::vector<exact::PlaneSide> rest_side;  // the plane of each of rest.items

  const Point3& P(uint32_t t, int i) const { return mesh.points[mesh.triangles[t][i]]; }
  // (ii): some vertex of f not strictly behind the plane `of_s` of a triangle of S.
  bool not_behind(const exact::PlaneSide& of_s, uint32_t f) const {
    for (int k = 0; k < 3; ++k) {
      if (of_s(P(f, k)) != Sign::kNegative) return true;
    }
    return false;
  }
  // (i): some vertex of s strictly in front of f (its plane `of_f`).
  bool in_front(uint32_t s, const exact::PlaneSide& of_f) const {
    for (int k = 0; k < 3; ++k) {
      if (of_f(P(s, k)) == Sign::kPositive) return true;
    }
    return false;
  }
};

namespace {

// Splits S into the triangles of its large planes (exactly coplanar, alike oriented) and
// the rest.
void group_by_plane(const SolidMesh& m, const std::vector<uint32_t>& s,
                    std::vector<std::vector<uint32_t>>& planes, std::vector<uint32_t>& rest) {
  double scale = 1;
  for (uint32_t t : s)
    for (uint32_t v : m.triangles[t])
      scale = std::max({scale, std::fabs(m.points[v].x), std::fabs(m.points[v].y), std::fabs(m.points[v].z)});
  std::map<std::array<int64_t, 4>, std::vector<uint32_t>> by_key;
  for (uint32_t t : s) by_key[plane_key(m, t, scale)].push_back(t);
  auto P = [&](uint32_t t, int i) -> const Point3& { return m.points[m.triangles[t][i]]; };
  auto normal = [&](uint32_t t) { return exact::triangle_normal(P(t, 0), P(t, 1), P(t, 2)); };
  for (auto& [key, members] : by_key) {
    std::vector<std::vector<uint32_t>> exact_groups;
    for (uint32_t t : members) {
      interruption_point();  // each t is compared with every group of its key
      bool placed = false;
      for (auto& g : exact_groups) {
        const uint32_t r = g.front();
        bool coplanar = true;
        for (int k = 0; k < 3 && coplanar; ++k)
          coplanar = exact::orient3d(P(r, 0), P(r, 1), P(r, 2), P(t, k)) == Sign::kZero;
        if (coplanar && exact::sign_dot(normal(r), normal(t)) == Sign::kPositive) {
          g.push_back(t);
          placed = true;
          break;
        }
      }
      if (!placed) exact_groups.push_back({t});
    }
    for (auto& g : exact_groups) {
      if (g.size() >= kMinPlaneTriangles) {
        planes.push_back(std::move(g));
      } else {
        rest.insert(rest.end(), g.begin(), g.end());
      }
    }
  }
}

// The vertices of the convex hull of the triangles' vertices (all on one plane): a vertex
// of the plane is strictly in front of F' iff one of these is, the sign being affine along
// the plane. Monotone chain in the projection along an axis the plane is not parallel to.
std::vector<uint32_t> planar_hull(const SolidMesh& m, const std::vector<uint32_t>& triangles) {
  auto P = [&](uint32_t v) -> const Point3& { return m.points[v]; };
  const Triangle& r = m.triangles[triangles.front()];
  int drop = 0;
  while (exact::cross_component(P(r[0]), P(r[1]), P(r[2]), drop) == Sign::kZero) ++drop;
  const int i = (drop + 1) % 3, j = (drop + 2) % 3;
  std::vector<uint32_t> v;
  for (uint32_t t : triangles) v.insert(v.end(), m.triangles[t].begin(), m.triangles[t].end());
  std::sort(v.begin(), v.end(), [&](uint32_t a, uint32_t b) {
    return P(a)[i] != P(b)[i] ? P(a)[i] < P(b)[i] : P(a)[j] < P(b)[j];
  });
  v.erase(std::unique(v.begin(), v.end(), [&](uint32_t a, uint32_t b) {
            return P(a)[i] == P(b)[i] && P(a)[j] == P(b)[j];
          }),
          v.end());
  if (v.size() < 3) return v;
  std::vector<uint32_t> hull(2 * v.size());
  size_t k = 0;
  auto turns_left = [&](uint32_t a, uint32_t b, uint32_t c) {
    return exact::orient2d(P(a), P(b), P(c), drop) == Sign::kPositive;
  };
  for (size_t n = 0; n < v.size(); ++n) {  // lower chain
    while (k >= 2 && !turns_left(hull[k - 2], hull[k - 1], v[n])) --k;
    hull[k++] = v[n];
  }
  for (size_t n = v.size() - 1, lower = k + 1; n-- > 0;) {  // upper chain
    while (k >= lower && !turns_left(hull[k - 2], hull[k - 1], v[n])) --k;
    hull[k++] = v[n];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace

PotentiallyFacing::PotentiallyFacing(const SolidMesh& mesh, const std::vector<uint32_t>& s,
                                     double coordinate_bound) {
  std::vector<std::vector<uint32_t>> planes;
  std::vector<uint32_t> rest;
  group_by_plane(mesh, s, planes, rest);
  auto side = [&](uint32_t t) {
    const Triangle& tri = mesh.triangles[t];
    return exact::PlaneSide(mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]);
  };
  // The points searched with are the mesh's.
  auto impl = std::make_unique<Impl>(Impl{mesh, {}, BoxTree(mesh, std::move(rest), 2 * coordinate_bound), {}});
  for (const auto& p : planes) impl->planes.push_back({side(p.front()), planar_hull(mesh, p)});
  for (uint32_t t : impl->rest.items) impl->rest_side.push_back(side(t));
  impl_ = std::move(impl);
}

PotentiallyFacing::~PotentiallyFacing() = default;

bool PotentiallyFacing::faces(uint32_t f) const {
  const Impl& I = *impl_;
  const Point3 &a = I.P(f, 0), &b = I.P(f, 1), &c = I.P(f, 2);
  const exact::PlaneSide of_f(a, b, c);
  for (const Impl::Plane& plane : I.planes) {
    if (!I.not_behind(plane.side, f)) continue;
    for (uint32_t v : plane.hull) {
      if (of_f(I.mesh.points[v]) == Sign::kPositive) return true;
    }
  }
  return I.rest.search(a, b, c, of_f, [&](uint32_t i) {
    return I.in_front(I.rest.items[i], of_f) && I.not_behind(I.rest_side[i], f);
  });
}

}  // namespace gvm::part_internal
