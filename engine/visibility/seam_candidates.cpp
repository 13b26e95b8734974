#include "visibility/seam_candidates.h"

#include <tbb/concurrent_unordered_map.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <unordered_map>

#include <spdlog/spdlog.h>

#include "exact/predicates.h"
#include "visibility/direction_window.h"
#include "visibility/seam_pieces.h"
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
  const std::vector<uint32_t> triangles = vertex_star(mesh, t, corner);
  fan.wedges.reserve(triangles.size());  // a closed star: as many neighbours as wedges
  fan.neighbours.reserve(triangles.size());
  for (uint32_t f : triangles) add_wedge(fan, mesh.triangles[f], v);
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

// The corners of the triangles of O, each with a triangle at it (its star is built when a
// contact needs it), and their edges with the triangles on both sides.
struct Occluder {
  std::vector<std::pair<uint32_t, uint32_t>> corners;  // (vertex, triangle)
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
  occ.corners.assign(corner_triangle.begin(), corner_triangle.end());
  std::sort(occ.corners.begin(), occ.corners.end());
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

// The directions q - p of contacts, each built once: arcs that share an end then share its
// node, and the exact predicates on them see the zeros by construction (seam_pieces.h's
// crossings of arcs at a common end, ends on one circle).
class ContactDirections {
 public:
  explicit ContactDirections(const SolidMesh& mesh) : mesh_(mesh) {}
  ExactVec operator()(uint32_t p, uint32_t q) const {
    const uint64_t key = uint64_t(p) << 32 | q;
    if (const auto it = cache_.find(key); it != cache_.end()) return it->second;
    return cache_.emplace(key, exact::point_difference(mesh_.points[q], mesh_.points[p]))
        .first->second;
  }

 private:
  const SolidMesh& mesh_;
  mutable tbb::concurrent_unordered_map<uint64_t, ExactVec> cache_;
};

// The arc of directions from p0 to q0 to those from p1 to q1 (one of each pair shared), when
// it may meet the open LVM.
void add_arc(const ContactDirections& direction, uint32_t p0, uint32_t q0, uint32_t p1, uint32_t q1, int side,
             const OpenLvm& lvm, std::vector<GrazingArc>& out) {
  const ExactVec a = direction(p0, q0), b = direction(p1, q1);
  if (lvm.may_meet(a, b)) out.push_back({{a, b, exact::cross(a, b), 0, 0}, side});
}

// The side of the circle of arc q - (a, b) that its contacts may occlude: towards q - r
// (rays from the inside of triangle (a, b, r) reach q), i.e. the sign of
// ((q - a) x (q - b)) . (q - r).
int edge_to_corner_side(const SolidMesh& mesh, const std::array<uint32_t, 3>& e, uint32_t q) {
  const auto& P = mesh.points;
  return -static_cast<int>(orient3d(P[q], P[e[0]], P[e[1]], P[e[2]]));
}

// The contact tests below are true (corner_to_edge_contact: empty) when the contact
// cannot be a seam's: it occludes u, or u is not in the open LVM.
//
// From inside border edge (a, b) of triangle (a, b, r) of S to corner q: occluding when a
// neighbour of q lies strictly on r's side of the plane (a, b, q).
bool edge_to_corner_rules_out(const SolidMesh& mesh, const std::array<uint32_t, 3>& e, uint32_t q,
                             const Fan& at_q) {
  const auto& P = mesh.points;
  const exact::PlaneSide plane(P[e[0]], P[e[1]], P[q]);
  const Sign side = plane(P[e[2]]);
  // u . n_S > 0 in the open LVM: q strictly in front of (a, b, r), i.e. r on the negative side.
  if (side != Sign::kNegative) return true;
  for (uint32_t w : at_q.neighbours) {
    if (plane(P[w]) == side) return true;
  }
  return false;
}

// From border corner p (S's triangles there: at_p) to inside edge (a, b) with triangles
// (a, b, c) and (b, a, d): nothing when a triangle at the edge and one of S reach
// strictly to one side of the plane (a, b, p), as the contact then occludes; else the
// side of the circle of arc (a, b) - p that its contacts may occlude, relative to
// (a - p) x (b - p): where the triangles at (a, b) reach, and away from where S's
// triangles at p reach (0 when both sides, or neither, can be told). One plane decides
// both, as orient3d(p, a, b, x) is orient3d(a, b, p, x).
std::optional<int> corner_to_edge_contact(const SolidMesh& mesh, uint32_t p, const Fan& at_p,
                                          const std::array<uint32_t, 4>& e) {
  const auto& P = mesh.points;
  const exact::PlaneSide plane(P[e[0]], P[e[1]], P[p]);
  const Sign c = plane(P[e[2]]);
  const Sign d = plane(P[e[3]]);
  for (const auto& [x, y] : at_p.wedges) {
    const Sign sx = plane(P[x]);
    const Sign sy = plane(P[y]);
    if (sx == Sign::kZero && sy == Sign::kZero) return std::nullopt;  // in the plane of S's triangle
    for (Sign side : {sx, sy}) {
      if (side != Sign::kZero && (side == c || side == d)) return std::nullopt;
    }
  }
  bool pos = false, neg = false;
  auto note = [&](Sign s) {
    pos = pos || s == Sign::kPositive;
    neg = neg || s == Sign::kNegative;
  };
  note(c);
  note(d);
  for (uint32_t s : at_p.neighbours) note(-plane(P[s]));
  return pos == neg ? 0 : pos ? 1 : -1;
}

// From border corner p to corner q: occluding when, seen along u = q - p, an edge at q
// points strictly into a triangle of S at p, or an edge of S at p into a triangle at q.
// Every angle test is a sign of det(u, a - p, b - p) = orient3d(p, q, a, b) (the same
// with b - q, as u is q - p).
bool corner_to_corner_rules_out(const SolidMesh& mesh, uint32_t p, const Fan& at_p, uint32_t q, const Fan& at_q) {
  const auto& P = mesh.points;
  auto turn = [&](uint32_t a, uint32_t b) { return orient3d(P[p], P[q], P[a], P[b]); };
  // c strictly inside the wedge from a to b (counter-clockwise around u, less than 180).
  auto inside = [&](uint32_t a, uint32_t b, uint32_t c) {
    return turn(a, c) == Sign::kPositive && turn(c, b) == Sign::kPositive;
  };
  for (const auto& [x, y] : at_p.wedges) {
    // Counter-clockwise around u: det(u, x - p, y - p) = u . n_S > 0 in the open LVM.
    if (turn(x, y) != Sign::kPositive) return true;
  }
  for (const auto& [x, y] : at_p.wedges) {
    for (uint32_t w : at_q.neighbours) {
      if (inside(x, y, w)) return true;
    }
  }
  for (const auto& [w0, w1] : at_q.wedges) {
    const Sign t = turn(w0, w1);
    if (t == Sign::kZero) continue;
    for (uint32_t s : at_p.neighbours) {
      if (t == Sign::kPositive ? inside(w0, w1, s) : inside(w1, w0, s)) return true;
    }
  }
  return false;
}

}  // namespace

SeamCandidates seam_candidates(const SolidMesh& mesh, std::span<const uint32_t> s, std::span<const uint32_t> o,
                               const sphere::SphericalImage& lvm, const DirectionWindow& window) {
  if (lvm.faces().empty() || o.empty()) return {};
  const Border border = border_of(mesh, s);
  const Occluder occ = occluder_of(mesh, o);
  const OpenLvm open(lvm);
  const ContactDirections direction(mesh);
  // The window's rows, for the certain misses in double precision: the smallest values
  // over each border edge and at each border corner of S, computed once; at each corner
  // and the largest over each edge of O, where they are used (kept for all of O, the
  // pocket part's floor had 423 values for each of its 250,000 corners and edges).
  const size_t k = window.row_size();
  auto rows_of_s = [&](const auto& elements, auto&& row_of) {
    std::vector<double> flat(elements.size() * k);
    for (size_t i = 0; i < elements.size() && k; ++i) row_of(elements[i], &flat[i * k]);
    return WindowRows(&window, elements.size(), std::move(flat), WindowRows::Side::surface);
  };
  const WindowRows s_edge =
      rows_of_s(border.edges, [&](const auto& e, double* out) { window.row(mesh, {e[0], e[1]}, false, out); });
  const WindowRows s_corner =
      rows_of_s(border.corners, [&](const auto& c, double* out) { window.row(mesh, {c.first}, false, out); });
  auto o_row = [&](std::initializer_list<uint32_t> vertices) {
    std::vector<double> row(k);
    if (k) window.row(mesh, vertices, true, row.data());
    return row;
  };
  // One slot per element of O, filled in parallel and read in order (deterministic).
  struct Found {
    std::vector<GrazingArc> arcs;
    std::vector<ExactVec> points;
  };
  std::vector<Found> at_corner(occ.corners.size()), at_edge(occ.edges.size());
  tbb::parallel_for(size_t{0}, occ.corners.size(), [&](size_t i) {
    const uint32_t q = occ.corners[i].first, triangle = occ.corners[i].second;  // not bound: clang 14 captures no bindings
    std::optional<Fan> star_q;  // built for the first contact that gets that far
    auto fan_q = [&]() -> const Fan& { return star_q ? *star_q : star_q.emplace(star(mesh, triangle, q)); };
    const std::vector<double> row = o_row({q});
    s_edge.for_each_meeting(row.data(), [&](size_t j) {
      const auto& e = border.edges[j];
      if (q != e[0] && q != e[1] && !edge_to_corner_rules_out(mesh, e, q, fan_q())) {
        add_arc(direction, e[0], q, e[1], q, edge_to_corner_side(mesh, e, q), open, at_corner[i].arcs);
      }
      return true;
    });
    s_corner.for_each_meeting(row.data(), [&](size_t j) {
      const auto& [p, fan_p] = border.corners[j];
      if (q != p && !corner_to_corner_rules_out(mesh, p, fan_p, q, fan_q())) {
        const ExactVec u = direction(p, q);
        if (open.may_meet(u, u)) at_corner[i].points.push_back(u);
      }
      return true;
    });
  });
  tbb::parallel_for(size_t{0}, occ.edges.size(), [&](size_t i) {
    const auto& e = occ.edges[i];
    const std::vector<double> row = o_row({e[0], e[1]});
    s_corner.for_each_meeting(row.data(), [&](size_t j) {
      const auto& [p, fan_p] = border.corners[j];
      if (p == e[0] || p == e[1]) return true;
      if (const std::optional<int> side = corner_to_edge_contact(mesh, p, fan_p, e)) {
        add_arc(direction, p, e[0], p, e[1], *side, open, at_edge[i].arcs);
      }
      return true;
    });
  });
  std::vector<GrazingArc> grazing;
  SeamCandidates all;
  for (auto* part : {&at_corner, &at_edge}) {
    for (Found& f : *part) {
      grazing.insert(grazing.end(), f.arcs.begin(), f.arcs.end());
      all.points.insert(all.points.end(), f.points.begin(), f.points.end());
    }
  }
  const size_t found = grazing.size(), corners = all.points.size();
  SeamPieces pieces = seam_pieces(std::move(grazing));
  all.arcs = std::move(pieces.arcs);
  all.points.insert(all.points.end(), pieces.points.begin(), pieces.points.end());
  spdlog::debug("seam candidates: {} grazing arcs, {} corner contacts: {} arcs and {} points", found, corners,
                all.arcs.size(), all.points.size());
  return all;
}

}  // namespace gvm
