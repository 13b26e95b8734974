#include "visibility/seam_candidates.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <unordered_map>

#include <spdlog/spdlog.h>

#include "exact/predicates.h"
#include "visibility/direction_window.h"
#include "visibility/strip_events.h"

namespace gvm {
namespace {

using exact::ExactVec;
using exact::orient3d;

// A vertex's triangles as wedges (x, y): triangle (v, x, y) counter-clockwise.
struct Fan {
  std::vector<std::array<uint32_t, 2>> wedges;
  std::vector<uint32_t> neighbours;  // the other corners, without repeats
};

void add_wedge(Fan& fan, const Triangle& tri, uint32_t v) {
  int i = 0;
  while (tri[i] != v) ++i;
  const uint32_t x = tri[(i + 1) % 3], y = tri[(i + 2) % 3];
  fan.wedges.push_back({x, y});
  for (uint32_t w : {x, y}) {
    if (std::find(fan.neighbours.begin(), fan.neighbours.end(), w) == fan.neighbours.end()) {
      fan.neighbours.push_back(w);
    }
  }
}

// The whole star of a vertex of the solid, from one of its triangles.
Fan star(const SolidMesh& mesh, uint32_t t, uint32_t v) {
  Fan fan;
  int corner = 0;
  while (mesh.triangles[t][corner] != v) ++corner;
  for (uint32_t f : vertex_star(mesh, t, corner)) add_wedge(fan, mesh.triangles[f], v);
  return fan;
}

// The border of S: its edges (a, b) of triangle (a, b, r) whose neighbour is not in S, and
// its corners on such edges with S's triangles there.
struct Border {
  std::vector<std::array<uint32_t, 3>> edges;  // (a, b, r)
  std::vector<std::pair<uint32_t, Fan>> corners;
};

Border border_of(const SolidMesh& mesh, std::span<const uint32_t> s) {
  std::vector<uint8_t> in_s(mesh.triangles.size(), 0);
  for (uint32_t t : s) in_s[t] = 1;
  Border border;
  std::unordered_map<uint32_t, size_t> corner_index;
  for (uint32_t t : s) {
    const Triangle& tri = mesh.triangles[t];
    for (int i = 0; i < 3; ++i) {
      if (in_s[mesh.neighbor[t][i]]) continue;
      border.edges.push_back({tri[i], tri[(i + 1) % 3], tri[(i + 2) % 3]});
      for (uint32_t v : {tri[i], tri[(i + 1) % 3]}) {
        if (corner_index.emplace(v, border.corners.size()).second) border.corners.push_back({v, {}});
      }
    }
  }
  for (uint32_t t : s) {
    for (uint32_t v : mesh.triangles[t]) {
      const auto it = corner_index.find(v);
      if (it != corner_index.end()) add_wedge(border.corners[it->second].second, mesh.triangles[t], v);
    }
  }
  return border;
}

// The corners and edges of the triangles of O, each with what lies around it.
struct Occluder {
  std::vector<std::pair<uint32_t, Fan>> corners;
  std::vector<std::array<uint32_t, 4>> edges;  // (a, b, c, d): triangles (a, b, c) and (b, a, d)
};

Occluder occluder_of(const SolidMesh& mesh, std::span<const uint32_t> o) {
  Occluder occ;
  std::unordered_map<uint32_t, uint32_t> corner_triangle;
  std::unordered_map<uint64_t, uint8_t> seen_edges;
  for (uint32_t t : o) {
    const Triangle& tri = mesh.triangles[t];
    for (int i = 0; i < 3; ++i) {
      corner_triangle.emplace(tri[i], t);
      const uint32_t a = tri[i], b = tri[(i + 1) % 3];
      if (!seen_edges.emplace(uint64_t(std::min(a, b)) << 32 | std::max(a, b), 0).second) continue;
      const Triangle& across = mesh.triangles[mesh.neighbor[t][i]];
      uint32_t d = across[0];
      for (uint32_t v : across) d = v != a && v != b ? v : d;
      occ.edges.push_back({a, b, tri[(i + 2) % 3], d});
    }
  }
  std::vector<std::pair<uint32_t, uint32_t>> sorted(corner_triangle.begin(), corner_triangle.end());
  std::sort(sorted.begin(), sorted.end());
  occ.corners.resize(sorted.size());
  tbb::parallel_for(size_t{0}, sorted.size(), [&](size_t i) {
    occ.corners[i] = {sorted[i].first, star(mesh, sorted[i].second, sorted[i].first)};
  });
  return occ;
}

// The closed convex LVM as half-spaces {u . n >= 0}; a set of directions whose every
// direction has u . n <= 0 for one n misses the open LVM.
class OpenLvm {
 public:
  explicit OpenLvm(const sphere::SphericalImage& lvm) {
    if (lvm.faces().size() != 1 || !lvm.faces()[0].convex) return;  // no filter
    for (const sphere::Face& f : lvm.faces()) {
      for (const sphere::Loop& l : f.loops) {
        for (const sphere::Arc& a : l.arcs) normals_.push_back(a.normal);
      }
    }
  }
  bool may_meet(const ExactVec& a, const ExactVec& b) const {
    for (const ExactVec& n : normals_) {
      if (exact::sign_dot(a, n) != Sign::kPositive && exact::sign_dot(b, n) != Sign::kPositive) return false;
    }
    return true;
  }

 private:
  std::vector<ExactVec> normals_;
};

ExactVec direction(const SolidMesh& mesh, uint32_t from, uint32_t to) {
  return ExactVec::from_point(mesh.points[to]) - ExactVec::from_point(mesh.points[from]);
}

void add_arc(const SolidMesh& mesh, uint32_t p0, uint32_t q0, uint32_t p1, uint32_t q1, const OpenLvm& lvm,
             std::vector<sphere::ArrangementArc>& out) {
  const ExactVec a = direction(mesh, p0, q0), b = direction(mesh, p1, q1);
  if (lvm.may_meet(a, b)) out.push_back({a, b, exact::cross(a, b), 0, 0});
}

// The contact tests below are true when the contact cannot be a seam's: it occludes u, or
// u is not in the open LVM.
//
// From inside border edge (a, b) of triangle (a, b, r) of S to corner q: occluding when a
// neighbour of q lies strictly on r's side of the plane (a, b, q).
bool edge_to_corner_rules_out(const SolidMesh& mesh, const std::array<uint32_t, 3>& e, uint32_t q,
                             const Fan& at_q) {
  const auto& P = mesh.points;
  const Sign side = orient3d(P[e[0]], P[e[1]], P[q], P[e[2]]);
  if (side == Sign::kZero) return true;  // u in the plane of S's triangle: not in the open LVM
  for (uint32_t w : at_q.neighbours) {
    if (orient3d(P[e[0]], P[e[1]], P[q], P[w]) == side) return true;
  }
  return false;
}

// From border corner p (S's triangles there: at_p) to inside edge (a, b) with triangles
// (a, b, c) and (b, a, d): occluding when a triangle at the edge and one of S reach
// strictly to one side of the plane (a, b, p).
bool corner_to_edge_rules_out(const SolidMesh& mesh, uint32_t p, const Fan& at_p, const std::array<uint32_t, 4>& e) {
  const auto& P = mesh.points;
  const Sign c = orient3d(P[e[0]], P[e[1]], P[p], P[e[2]]);
  const Sign d = orient3d(P[e[0]], P[e[1]], P[p], P[e[3]]);
  for (const auto& [x, y] : at_p.wedges) {
    const Sign sx = orient3d(P[e[0]], P[e[1]], P[p], P[x]);
    const Sign sy = orient3d(P[e[0]], P[e[1]], P[p], P[y]);
    if (sx == Sign::kZero && sy == Sign::kZero) return true;  // in the plane of S's triangle
    for (Sign side : {sx, sy}) {
      if (side != Sign::kZero && (side == c || side == d)) return true;
    }
  }
  return false;
}

// Whether, seen along u = q - p, direction x - (p or q) lies strictly inside the wedge
// (y0, y1) at the same point: det(u, y0 - .., x - ..) > 0 and det(u, x - .., y1 - ..) > 0,
// which are orientations of p, q and the two points.
bool strictly_inside(const SolidMesh& mesh, uint32_t p, uint32_t q, uint32_t y0, uint32_t y1, uint32_t x) {
  const auto& P = mesh.points;
  return orient3d(P[p], P[q], P[y0], P[x]) == Sign::kPositive &&
         orient3d(P[p], P[q], P[x], P[y1]) == Sign::kPositive;
}

// From border corner p to corner q: occluding when, seen along u = q - p, an edge at q
// points strictly into a triangle of S at p, or an edge of S at p into a triangle at q.
bool corner_to_corner_rules_out(const SolidMesh& mesh, uint32_t p, const Fan& at_p, uint32_t q, const Fan& at_q) {
  const auto& P = mesh.points;
  for (const auto& [x, y] : at_p.wedges) {
    // Counter-clockwise around u: det(u, x - p, y - p) = u . n_S > 0 in the open LVM.
    if (orient3d(P[p], P[q], P[x], P[y]) != Sign::kPositive) return true;
    for (uint32_t w : at_q.neighbours) {
      if (strictly_inside(mesh, p, q, x, y, w)) return true;
    }
  }
  for (auto [x, y] : at_q.wedges) {
    const Sign turn = orient3d(P[p], P[q], P[x], P[y]);  // det(u, x - q, y - q)
    if (turn == Sign::kZero) continue;
    if (turn == Sign::kNegative) std::swap(x, y);
    for (uint32_t s : at_p.neighbours) {
      if (strictly_inside(mesh, p, q, x, y, s)) return true;
    }
  }
  return false;
}

// Arcs on one circle (common normal n), merged in order of their starts along it: an arc
// starting on the current one extends it while the result stays shorter than 180 degrees.
void merge_on_circle(std::vector<sphere::ArrangementArc>& arcs, std::vector<sphere::ArrangementArc>& out) {
  const ExactVec& n = arcs.front().normal;
  // Angles of the starts in a basis of the circle's plane (an order only: exactness is in
  // the merge tests).
  const std::array<double, 3> e1 = arcs.front().from.unit(), nu = n.unit();
  const std::array<double, 3> e2{nu[1] * e1[2] - nu[2] * e1[1], nu[2] * e1[0] - nu[0] * e1[2],
                                 nu[0] * e1[1] - nu[1] * e1[0]};
  auto angle = [&](const ExactVec& v) {
    const std::array<double, 3> u = v.unit();
    return std::atan2(u[0] * e2[0] + u[1] * e2[1] + u[2] * e2[2], u[0] * e1[0] + u[1] * e1[1] + u[2] * e1[2]);
  };
  std::vector<std::pair<double, size_t>> by_start;
  for (size_t i = 0; i < arcs.size(); ++i) by_start.push_back({angle(arcs[i].from), i});
  std::sort(by_start.begin(), by_start.end());
  std::optional<sphere::ArrangementArc> current;
  for (const auto& [_, i] : by_start) {
    const sphere::ArrangementArc& next = arcs[i];
    if (current) {
      const sphere::Arc held{current->from, current->to, n};
      if (sphere::arc_contains(held, next.from)) {
        if (sphere::arc_contains(held, next.to)) continue;
        if (exact::sign_det(n, current->from, next.to) == Sign::kPositive) {
          current->to = next.to;
          continue;
        }
      }
      out.push_back(*current);
    }
    current = next;
  }
  if (current) out.push_back(*current);
}

// The arcs on one great circle (normals exactly parallel) merged where they overlap, as
// long as the merged arc stays shorter than 180 degrees: candidates come in families on
// one circle (the corners of O along a line parallel to a border edge of S all give the
// plane through both), which the arrangement would otherwise split against each other.
// Circles are found by rounded unit normals and confirmed exactly; a family split by the
// rounding is only merged less.
std::vector<sphere::ArrangementArc> merged_by_circle(std::vector<sphere::ArrangementArc> arcs) {
  std::unordered_map<uint64_t, std::vector<std::vector<sphere::ArrangementArc>>> buckets;
  for (sphere::ArrangementArc& a : arcs) {
    std::array<double, 3> n = a.normal.unit();
    // One sign per line through the origin: the first non-zero component positive.
    const double lead = n[0] != 0 ? n[0] : n[1] != 0 ? n[1] : n[2];
    if (lead < 0) n = {-n[0], -n[1], -n[2]};
    uint64_t key = 0;
    for (double c : n) key = key * 1000003 + static_cast<uint64_t>(std::llround(c * 1e9) + (1LL << 40));
    auto& circles = buckets[key];
    auto it = std::find_if(circles.begin(), circles.end(),
                           [&](const auto& c) { return exact::parallel(c[0].normal, a.normal); });
    if (it == circles.end()) it = circles.insert(circles.end(), std::vector<sphere::ArrangementArc>{});
    if (!it->empty() && exact::sign_dot(it->front().normal, a.normal) == Sign::kNegative) {
      a = {a.to, a.from, it->front().normal, a.layer, a.weight};
    } else if (!it->empty()) {
      a.normal = it->front().normal;
    }
    it->push_back(std::move(a));
  }
  std::vector<std::pair<uint64_t, std::vector<sphere::ArrangementArc>*>> order;
  for (auto& [key, circles] : buckets) {
    for (auto& c : circles) order.push_back({key, &c});
  }
  std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<sphere::ArrangementArc> out;
  for (auto& [key, circle] : order) merge_on_circle(*circle, out);
  return out;
}

}  // namespace

SeamCandidates seam_candidates(const SolidMesh& mesh, std::span<const uint32_t> s, std::span<const uint32_t> o,
                               const sphere::SphericalImage& lvm, const DirectionWindow& window) {
  if (lvm.faces().empty() || o.empty()) return {};
  const Border border = border_of(mesh, s);
  const Occluder occ = occluder_of(mesh, o);
  const OpenLvm open(lvm);
  // The window's values at every point used, for the certain misses in double precision.
  const size_t k = window.size();
  std::unordered_map<uint32_t, std::vector<double>> at;
  auto add_values = [&](uint32_t v) {
    auto [it, added] = at.try_emplace(v, k);
    if (added && k) window.values(mesh.points[v], it->second.data());
  };
  for (const auto& e : border.edges) add_values(e[0]), add_values(e[1]);
  for (const auto& e : occ.edges) add_values(e[0]), add_values(e[1]);
  // Whether directions from the points p0 (and p1) of S to q0 (and q1) of O may meet L.
  auto may_meet = [&](uint32_t p0, uint32_t p1, uint32_t q0, uint32_t q1, std::vector<double>& q_max,
                      std::vector<double>& p_min) {
    const auto &a = at.at(p0), &b = at.at(p1), &c = at.at(q0), &d = at.at(q1);
    for (size_t i = 0; i < k; ++i) {
      p_min[i] = std::min(a[i], b[i]);
      q_max[i] = std::max(c[i], d[i]);
    }
    return window.may_meet(q_max.data(), p_min.data());
  };
  // One slot per element of O, filled in parallel and read in order (deterministic).
  std::vector<SeamCandidates> at_corner(occ.corners.size()), at_edge(occ.edges.size());
  tbb::parallel_for(size_t{0}, occ.corners.size(), [&](size_t i) {
    const auto& [q, fan_q] = occ.corners[i];
    std::vector<double> q_max(k), p_min(k);
    for (const auto& e : border.edges) {
      if (q == e[0] || q == e[1] || !may_meet(e[0], e[1], q, q, q_max, p_min) ||
          edge_to_corner_rules_out(mesh, e, q, fan_q)) {
        continue;
      }
      add_arc(mesh, e[0], q, e[1], q, open, at_corner[i].arcs);
    }
    for (const auto& [p, fan_p] : border.corners) {
      if (q == p || !may_meet(p, p, q, q, q_max, p_min) || corner_to_corner_rules_out(mesh, p, fan_p, q, fan_q)) {
        continue;
      }
      const ExactVec u = direction(mesh, p, q);
      if (open.may_meet(u, u)) at_corner[i].points.push_back(u);
    }
  });
  tbb::parallel_for(size_t{0}, occ.edges.size(), [&](size_t i) {
    const auto& e = occ.edges[i];
    std::vector<double> q_max(k), p_min(k);
    for (const auto& [p, fan_p] : border.corners) {
      if (p == e[0] || p == e[1] || !may_meet(p, p, e[0], e[1], q_max, p_min) ||
          corner_to_edge_rules_out(mesh, p, fan_p, e)) {
        continue;
      }
      add_arc(mesh, p, e[0], p, e[1], open, at_edge[i].arcs);
    }
  });
  SeamCandidates all;
  for (auto* part : {&at_corner, &at_edge}) {
    for (SeamCandidates& c : *part) {
      all.arcs.insert(all.arcs.end(), c.arcs.begin(), c.arcs.end());
      all.points.insert(all.points.end(), c.points.begin(), c.points.end());
    }
  }
  const size_t found = all.arcs.size();
  all.arcs = merged_by_circle(std::move(all.arcs));
  spdlog::debug("seam candidates: {} arcs ({} merged on common circles), {} points", found, all.arcs.size(),
                all.points.size());
  return all;
}

}  // namespace gvm
