// Brute-force ray-casting visibility oracle (see ray_oracle.h for its limits).
#include "support/ray_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>

namespace gvm::oracle {
namespace {

Vec to_vec(const Point3& p) { return {p.x, p.y, p.z}; }
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

// Slab test of the ray p + t u, t in (tmin, inf), against a box (widened a little so that
// rays along a face of the box are not lost).
bool ray_hits_box(const Vec& p, const Vec& inv, const Vec& lo, const Vec& hi, double tmin,
                  double pad) {
  double t0 = tmin, t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    double a = lo[k] - pad, b = hi[k] + pad;
    if (std::isinf(inv[k])) {  // ray parallel to the slab
      if (p[k] < a || p[k] > b) return false;
      continue;
    }
    double ta = (a - p[k]) * inv[k], tb = (b - p[k]) * inv[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

RayOracle::RayOracle(const SolidMesh& mesh, OracleOptions options)
    : mesh_(mesh), options_(options) {
  const std::size_t n = mesh.triangles.size();
  normal_.resize(n);
  std::vector<Vec> centroids(n);
  Vec lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
         std::numeric_limits<double>::infinity()};
  Vec hi{-lo[0], -lo[1], -lo[2]};
  for (const Point3& p : mesh.points) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  double diagonal = mesh.points.empty() ? 1.0 : norm(sub(hi, lo));
  tmin_ = options_.tmin_relative * diagonal;
  for (std::size_t t = 0; t < n; ++t) {
    Vec a = to_vec(mesh.points[mesh.triangles[t][0]]);
    Vec b = to_vec(mesh.points[mesh.triangles[t][1]]);
    Vec c = to_vec(mesh.points[mesh.triangles[t][2]]);
    normal_[t] = cross(sub(b, a), sub(c, a));
    for (int i = 0; i < 3; ++i) {
      across_[{mesh.triangles[t][i], mesh.triangles[t][(i + 1) % 3]}] = static_cast<uint32_t>(t);
    }
    for (int k = 0; k < 3; ++k) centroids[t][k] = (a[k] + b[k] + c[k]) / 3.0;
  }
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0u);
  nodes_.reserve(2 * n + 1);
  if (n > 0) build(0, static_cast<uint32_t>(n), centroids);
}

uint32_t RayOracle::build(uint32_t first, uint32_t count, std::vector<Vec>& centroids) {
  const uint32_t index = static_cast<uint32_t>(nodes_.size());
  nodes_.push_back({});
  Node node;
  node.lo = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity()};
  node.hi = {-node.lo[0], -node.lo[1], -node.lo[2]};
  Vec clo = node.lo, chi = node.hi;
  for (uint32_t i = first; i < first + count; ++i) {
    const Triangle& tri = mesh_.triangles[order_[i]];
    for (uint32_t v : tri) {
      const Point3& p = mesh_.points[v];
      for (int k = 0; k < 3; ++k) {
        node.lo[k] = std::min(node.lo[k], p[k]);
        node.hi[k] = std::max(node.hi[k], p[k]);
      }
    }
    for (int k = 0; k < 3; ++k) {
      clo[k] = std::min(clo[k], centroids[order_[i]][k]);
      chi[k] = std::max(chi[k], centroids[order_[i]][k]);
    }
  }
  if (count <= 4) {
    node.first = first;
    node.count = count;
    nodes_[index] = node;
    return index;
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
  }
  const uint32_t half = count / 2;  // median split on the longest centroid axis
  std::nth_element(order_.begin() + first, order_.begin() + first + half,
                   order_.begin() + first + count, [&](uint32_t a, uint32_t b) {
                     return centroids[a][axis] < centroids[b][axis];
                   });
  node.left = build(first, half, centroids);
  node.right = build(first + half, count - half, centroids);
  node.count = 0;
  nodes_[index] = node;
  return index;
}

bool RayOracle::ray_blocked(const Vec& p, const Vec& u, uint32_t* hit) const {
  if (nodes_.empty()) return false;
  Vec inv;
  for (int k = 0; k < 3; ++k) {
    inv[k] = u[k] != 0 ? 1.0 / u[k] : std::numeric_limits<double>::infinity();
  }
  const double pad = tmin_;
  const double bary_tol = options_.barycentric_tolerance;
  std::vector<uint32_t> stack;
  stack.reserve(64);
  stack.push_back(0);
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (!ray_hits_box(p, inv, node.lo, node.hi, tmin_, pad)) continue;
    if (node.count == 0) {
      stack.push_back(node.left);
      stack.push_back(node.right);
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      const uint32_t t = order_[i];
      const Vec& n = normal_[t];
      const double un = dot(u, n);
      const double nn = norm(n);
      // Only transversal hits from the front side block (or from either side, with
      // exits_block); grazing ones do not.
      const bool front = un < -options_.front_tolerance * nn;
      if (!front && !(options_.exits_block && un > options_.front_tolerance * nn)) continue;
      // Moeller-Trumbore with barycentrics normalized by the determinant (= -u . n).
      const Triangle& tri = mesh_.triangles[t];
      const Vec a = to_vec(mesh_.points[tri[0]]);
      const Vec e1 = sub(to_vec(mesh_.points[tri[1]]), a);
      const Vec e2 = sub(to_vec(mesh_.points[tri[2]]), a);
      const Vec pvec = cross(u, e2);
      const double det = dot(e1, pvec);
      if (!(front ? det > 0 : det < 0)) continue;
      const Vec s = sub(p, a);
      const double b1 = dot(s, pvec) / det;
      if (!(b1 > -bary_tol)) continue;
      const Vec qvec = cross(s, e1);
      const double b2 = dot(u, qvec) / det;
      if (!(b2 > -bary_tol) || !(1.0 - b1 - b2 > -bary_tol)) continue;
      const double tt = dot(e2, qvec) / det;
      if (!(tt > tmin_)) continue;
      if (hit) *hit = t;
      return true;
    }
  }
  return false;
}

std::vector<Vec> RayOracle::sample_points(const std::vector<uint32_t>& s) const {
  std::vector<Vec> points;
  if (s.empty()) return points;
  const double eps = options_.inset;
  auto inset_point = [&](uint32_t t, double w0, double w1, double w2) {
    w0 = (1 - 3 * eps) * w0 + eps;
    w1 = (1 - 3 * eps) * w1 + eps;
    w2 = (1 - 3 * eps) * w2 + eps;
    const Triangle& tri = mesh_.triangles[t];
    const Point3 &a = mesh_.points[tri[0]], &b = mesh_.points[tri[1]], &c = mesh_.points[tri[2]];
    return Vec{w0 * a.x + w1 * b.x + w2 * c.x, w0 * a.y + w1 * b.y + w2 * c.y,
               w0 * a.z + w1 * b.z + w2 * c.z};
  };
  int g = 0;
  for (int level = 1; level <= std::max(1, options_.max_grid); ++level) {
    const std::size_t per = static_cast<std::size_t>(level + 1) * (level + 2) / 2;
    if (s.size() * per <= options_.max_points) g = level;
  }
  if (g >= 1) {
    for (uint32_t t : s) {
      for (int i = 0; i <= g; ++i) {
        for (int j = 0; i + j <= g; ++j) {
          const int k = g - i - j;
          points.push_back(inset_point(t, double(i) / g, double(j) / g, double(k) / g));
        }
      }
    }
    return points;
  }
  // Too many triangles: every distinct vertex of S (inset into its first triangle of S)
  // and every centroid, thinned by a fixed stride to the cap.
  std::vector<Vec> all;
  std::set<uint32_t> seen;
  for (uint32_t t : s) {
    for (int corner = 0; corner < 3; ++corner) {
      if (!seen.insert(mesh_.triangles[t][corner]).second) continue;
      all.push_back(inset_point(t, corner == 0, corner == 1, corner == 2));
    }
  }
  for (uint32_t t : s) all.push_back(inset_point(t, 1.0 / 3, 1.0 / 3, 1.0 / 3));
  const std::size_t cap = std::max<std::size_t>(1, options_.max_points);
  if (all.size() <= cap) return all;
  for (std::size_t i = 0; i < cap; ++i) points.push_back(all[i * all.size() / cap]);
  return points;
}

bool RayOracle::surface_visible(const std::vector<uint32_t>& s, const std::vector<Vec>& points,
                                const Vec& u) const {
  for (uint32_t t : s) {
    const Vec& n = normal_[t];
    if (dot(u, n) < -options_.self_tolerance * norm(n)) return false;  // self-occlusion
  }
  const std::set<uint32_t> in_s(s.begin(), s.end());
  for (uint32_t t : s) {
    const Triangle& tri = mesh_.triangles[t];
    for (int i = 0; i < 3; ++i) {
      // The triangle F across edge (a, b) is the one with the directed edge (b, a).
      auto it = across_.find({tri[(i + 1) % 3], tri[i]});
      if (it == across_.end() || in_s.count(it->second)) continue;
      const uint32_t f = it->second;
      const Triangle& g = mesh_.triangles[f];
      uint32_t far = g[0];
      for (uint32_t v : g) {
        if (v != tri[i] && v != tri[(i + 1) % 3]) far = v;
      }
      // Concave: F's far vertex lies in front of S's plane.
      const Vec& nt = normal_[t];
      const Vec d = sub(to_vec(mesh_.points[far]), to_vec(mesh_.points[tri[i]]));
      const bool concave = dot(nt, d) > options_.self_tolerance * norm(nt) * norm(d);
      const Vec& nf = normal_[f];
      if (concave && dot(u, nf) < -options_.self_tolerance * norm(nf)) return false;
    }
  }
  for (const Vec& p : points) {
    if (ray_blocked(p, u)) return false;
  }
  return !any_ray_blocked(s, u);
}

namespace {

using Vec2 = std::array<double, 2>;

double cross2(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double area2(const std::vector<Vec2>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2 &x = p[i], &y = p[(i + 1) % p.size()];
    a += x[0] * y[1] - y[0] * x[1];
  }
  return a / 2;
}

// Sutherland-Hodgman: the part of `poly` to the left of a -> b.
std::vector<Vec2> clip(const std::vector<Vec2>& poly, const Vec2& a, const Vec2& b) {
  std::vector<Vec2> out;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec2 &p = poly[i], &q = poly[(i + 1) % poly.size()];
    const double sp = cross2(a, b, p), sq = cross2(a, b, q);
    if (sp >= 0) out.push_back(p);
    if ((sp >= 0) != (sq >= 0)) {
      const double t = sp / (sp - sq);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  return out;
}

// Depth along u at the 2-D point c of a triangle given by 2-D corners and depths.
double depth_at(const std::array<Vec2, 3>& t, const std::array<double, 3>& d, const Vec2& c) {
  const double det = cross2(t[0], t[1], t[2]);
  const double l1 = cross2(t[0], c, t[2]) / det;
  const double l2 = cross2(t[0], t[1], c) / det;
  return d[0] + l1 * (d[1] - d[0]) + l2 * (d[2] - d[0]);
}

}  // namespace

bool RayOracle::any_ray_blocked(const std::vector<uint32_t>& s, const Vec& u) const {
  if (nodes_.empty()) return false;
  const Vec helper = std::fabs(u[0]) < 0.6 ? Vec{1, 0, 0} : Vec{0, 1, 0};
  Vec e1 = cross(u, helper);
  const double l1 = norm(e1);
  e1 = {e1[0] / l1, e1[1] / l1, e1[2] / l1};
  const Vec e2 = cross(u, e1);
  auto project = [&](uint32_t t, std::array<Vec2, 3>& p, std::array<double, 3>& d) {
    for (int i = 0; i < 3; ++i) {
      const Vec v = to_vec(mesh_.points[mesh_.triangles[t][i]]);
      p[i] = {dot(v, e1), dot(v, e2)};
      d[i] = dot(v, u);
    }
    if (cross2(p[0], p[1], p[2]) < 0) {
      std::swap(p[1], p[2]);
      std::swap(d[1], d[2]);
    }
  };
  for (uint32_t t : s) {
    std::array<Vec2, 3> tp;
    std::array<double, 3> td;
    project(t, tp, td);
    const double t_area = cross2(tp[0], tp[1], tp[2]) / 2;
    if (!(t_area > 0)) continue;  // seen edge-on: no rays leave it along u
    Vec2 lo{std::min({tp[0][0], tp[1][0], tp[2][0]}), std::min({tp[0][1], tp[1][1], tp[2][1]})};
    Vec2 hi{std::max({tp[0][0], tp[1][0], tp[2][0]}), std::max({tp[0][1], tp[1][1], tp[2][1]})};
    const double t_depth = std::min({td[0], td[1], td[2]});
    std::vector<uint32_t> stack{0};
    while (!stack.empty()) {
      const Node& node = nodes_[stack.back()];
      stack.pop_back();
      // The node's box seen along u: its 2-D extent and how far ahead it reaches.
      Vec2 blo{1e300, 1e300}, bhi{-1e300, -1e300};
      double ahead = -1e300;
      for (int c = 0; c < 8; ++c) {
        const Vec v{c & 1 ? node.hi[0] : node.lo[0], c & 2 ? node.hi[1] : node.lo[1],
                    c & 4 ? node.hi[2] : node.lo[2]};
        const double x = dot(v, e1), y = dot(v, e2);
        blo = {std::min(blo[0], x), std::min(blo[1], y)};
        bhi = {std::max(bhi[0], x), std::max(bhi[1], y)};
        ahead = std::max(ahead, dot(v, u));
      }
      if (bhi[0] < lo[0] || blo[0] > hi[0] || bhi[1] < lo[1] || blo[1] > hi[1] ||
          ahead < t_depth) {
        continue;
      }
      if (node.count == 0) {
        stack.push_back(node.left);
        stack.push_back(node.right);
        continue;
      }
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        const uint32_t f = order_[i];
        if (f == t || !(dot(u, normal_[f]) < -options_.front_tolerance * norm(normal_[f]))) {
          continue;
        }
        std::array<Vec2, 3> fp;
        std::array<double, 3> fd;
        project(f, fp, fd);
        std::vector<Vec2> overlap(tp.begin(), tp.end());
        for (int k = 0; k < 3 && overlap.size() >= 3; ++k) overlap = clip(overlap, fp[k], fp[(k + 1) % 3]);
        if (overlap.size() < 3) continue;
        const double f_area = cross2(fp[0], fp[1], fp[2]) / 2;
        if (!(area2(overlap) > 1e-10 * std::max(t_area, f_area))) continue;
        Vec2 c{0, 0};
        for (const Vec2& p : overlap) c = {c[0] + p[0] / overlap.size(), c[1] + p[1] / overlap.size()};
        // The mesh does not self-intersect, so F is ahead of T all over the overlap or
        // nowhere; the centroid decides.
        if (depth_at(fp, fd, c) > depth_at(tp, td, c) + tmin_) return true;
      }
    }
  }
  return false;
}

bool surface_visible(const SolidMesh& mesh, const std::vector<uint32_t>& s_triangles,
                     const std::array<double, 3>& u, const OracleOptions& options) {
  RayOracle oracle(mesh, options);
  return oracle.surface_visible(s_triangles, u);
}

}  // namespace gvm::oracle
