// Validation of a raw mesh and construction of the SolidMesh. Every geometric decision is
// an exact predicate from engine/exact; no epsilon anywhere.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <span>
#include <string>

#include "exact/predicates.h"
#include "gvm/mesh.h"
#include "mesh/tri_intersect.h"
#include "parallel/interrupt.h"

namespace gvm {
namespace {

using exact::collinear;
using exact::orient2d;
using exact::orient3d;

std::string S(uint64_t v) { return std::to_string(v); }
std::string edge_name(uint32_t a, uint32_t b) { return "(" + S(a) + ", " + S(b) + ")"; }

// The axis to drop so that the plane of a, b, c projects without collapsing, and the sign
// the triangle a, b, c has in that projection.
int drop_axis(const Point3& a, const Point3& b, const Point3& c) {
  for (int ax = 2; ax >= 0; --ax)
    if (orient2d(a, b, c, ax) != Sign::kZero) return ax;
  return -1;
}

// Splits a planar simple polygon (vertex indices `f`) into triangles by ear clipping in
// projection `drop`, where the polygon has orientation `s`. Returns false if the polygon is
// not simple (self-overlapping) or cannot be clipped into non-degenerate triangles.
bool triangulate_polygon(const std::vector<Point3>& P, const std::vector<uint32_t>& f,
                         int drop, std::vector<Triangle>& out) {
  const size_t n = f.size();
  // Orientation in the projection: exact signed area (shoelace sum).
  Sign s = exact::polygon_area_sign(P, f, drop);
  if (s == Sign::kZero) return false;
  // Simplicity: no two non-adjacent edges touch, adjacent edges meet only at their vertex.
  for (size_t a = 0; a < n; ++a) {
    const Point3 &a0 = P[f[a]], &a1 = P[f[(a + 1) % n]];
    for (size_t b = a + 1; b < n; ++b) {
      const Point3 &b0 = P[f[b]], &b1 = P[f[(b + 1) % n]];
      bool adjacent = (b == a + 1) || (a == 0 && b == n - 1);
      if (!adjacent) {
        if (mesh_internal::seg_seg_2d(a0, a1, b0, b1, drop)) return false;
      } else {
        // shared vertex v; fold-back when the other ends are collinear on the same ray
        const Point3& v = (b == a + 1) ? a1 : a0;
        const Point3& x = (b == a + 1) ? a0 : a1;
        const Point3& y = (b == a + 1) ? b1 : b0;
        if (orient2d(v, x, y, drop) == Sign::kZero &&
            exact::dot_diff(v, x, v, y) == Sign::kPositive)
          return false;
      }
    }
  }
  // Strictly convex and turning once: fan from the first vertex.
  bool convex = true;
  for (size_t k = 0; k < n && convex; ++k)
    if (orient2d(P[f[k]], P[f[(k + 1) % n]], P[f[(k + 2) % n]], drop) != s) convex = false;
  if (convex) {
    for (size_t k = 1; k + 1 < n; ++k) out.push_back({f[0], f[k], f[k + 1]});
    return true;
  }
  std::vector<uint32_t> poly(f);
  while (poly.size() > 3) {
    const size_t m = poly.size();
    bool clipped = false;
    for (size_t k = 0; k < m && !clipped; ++k) {
      uint32_t ia = poly[(k + m - 1) % m], ib = poly[k], ic = poly[(k + 1) % m];
      const Point3 &a = P[ia], &b = P[ib], &c = P[ic];
      if (orient2d(a, b, c, drop) != s) continue;
      bool empty = true;
      for (size_t r = 0; r < m && empty; ++r) {
        uint32_t ir = poly[r];
        if (ir == ia || ir == ib || ir == ic) continue;
        const Point3& q = P[ir];
        if (orient2d(a, b, q, drop) != -s && orient2d(b, c, q, drop) != -s &&
            orient2d(c, a, q, drop) != -s)
          empty = false;
      }
      if (!empty) continue;
      out.push_back({ia, ib, ic});
      poly.erase(poly.begin() + long(k));
      clipped = true;
    }
    if (!clipped) return false;
  }
  if (orient2d(P[poly[0]], P[poly[1]], P[poly[2]], drop) != s) return false;
  out.push_back({poly[0], poly[1], poly[2]});
  return true;
}

struct HalfEdge {
  uint64_t key;  // min << 32 | max
  uint32_t id;   // corner id: the half-edge starts at that corner
};

uint64_t ekey(uint32_t a, uint32_t b) {
  return a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
}

// Splits every face into triangles (tris, and the face of each in tri_face); returns what
// is wrong with the first face that is not planar or not simple, or that has zero area.
// Faces that are triangles already (every face of an STL) are checked in parallel.
std::string triangulate_faces(const std::vector<Point3>& P, const std::vector<std::vector<uint32_t>>& F,
                              std::vector<Triangle>& tris, std::vector<uint32_t>& tri_face) {
  const uint32_t nf = uint32_t(F.size());
  std::vector<uint8_t> degenerate(nf, 0);
  if (std::all_of(F.begin(), F.end(), [](const std::vector<uint32_t>& v) { return v.size() == 3; })) {
    tris.resize(nf);
    tri_face.resize(nf);
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, nf, 4096), [&](const tbb::blocked_range<uint32_t>& range) {
      for (uint32_t f = range.begin(); f != range.end(); ++f) {
        const auto& v = F[f];
        tris[f] = {v[0], v[1], v[2]};
        tri_face[f] = f;
        degenerate[f] = collinear(P[v[0]], P[v[1]], P[v[2]]);
      }
    });
    interruption_point();
  } else {
    tris.reserve(nf);
    tri_face.reserve(nf);
    for (uint32_t f = 0; f < nf; ++f) {
      const auto& v = F[f];
      if (v.size() == 3) {
        if (collinear(P[v[0]], P[v[1]], P[v[2]])) degenerate[f] = 1;
        tris.push_back({v[0], v[1], v[2]});
        tri_face.push_back(f);
        continue;
      }
      // a non-collinear triple v0, v[k-1], v[k]... first one with v0, v1 fixed when possible
      size_t n = v.size();
      int ia = -1, ib = -1, ic = -1;
      for (size_t i = 1; i < n && ia < 0; ++i)
        for (size_t j = i + 1; j < n; ++j)
          if (!collinear(P[v[0]], P[v[i]], P[v[j]])) {
            ia = 0, ib = int(i), ic = int(j);
            break;
          }
      if (ia < 0) {
        degenerate[f] = 1;
        continue;
      }
      const Point3 &a = P[v[ia]], &b = P[v[ib]], &c = P[v[ic]];
      for (size_t k = 0; k < n; ++k)
        if (orient3d(a, b, c, P[v[k]]) != Sign::kZero)
          return "face " + S(f) + " is not planar (vertex " + S(v[k]) + " is off the plane of vertices " +
                 S(v[ia]) + ", " + S(v[ib]) + ", " + S(v[ic]) + ")";
      int drop = drop_axis(a, b, c);
      size_t before = tris.size();
      if (!triangulate_polygon(P, v, drop, tris)) return "face " + S(f) + " is a self-overlapping polygon";
      for (size_t t = before; t < tris.size(); ++t) tri_face.push_back(f);
    }
  }
  for (uint32_t f = 0; f < nf; ++f)
    if (degenerate[f]) return "face " + S(f) + " has zero area (all vertices collinear)";
  return {};
}

// The two faces with the same vertex set that come first (the smallest later face, with
// the first face of its set), if any. The sorted vertex lists are kept in one array.
std::optional<std::pair<uint32_t, uint32_t>> first_duplicate_faces(const std::vector<std::vector<uint32_t>>& F) {
  const uint32_t nf = uint32_t(F.size());
  std::vector<size_t> first(nf + 1, 0);
  for (uint32_t f = 0; f < nf; ++f) first[f + 1] = first[f] + F[f].size();
  std::vector<uint32_t> sorted(first[nf]);
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, nf, 4096), [&](const tbb::blocked_range<uint32_t>& range) {
    for (uint32_t f = range.begin(); f != range.end(); ++f) {
      std::copy(F[f].begin(), F[f].end(), sorted.begin() + first[f]);
      std::sort(sorted.begin() + first[f], sorted.begin() + first[f + 1]);
    }
  });
  auto vertices = [&](uint32_t f) { return std::span<const uint32_t>(sorted.data() + first[f], F[f].size()); };
  auto same = [&](uint32_t a, uint32_t b) { return std::ranges::equal(vertices(a), vertices(b)); };
  std::vector<uint32_t> order(nf);
  std::iota(order.begin(), order.end(), 0u);
  tbb::parallel_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    const auto va = vertices(a), vb = vertices(b);
    if (std::ranges::lexicographical_compare(va, vb)) return true;
    if (std::ranges::lexicographical_compare(vb, va)) return false;
    return a < b;
  });
  interruption_point();  // a cancelled sort stops half done
  uint32_t best_a = UINT32_MAX, best_b = UINT32_MAX, group_first = 0;
  for (uint32_t k = 0; k < nf; ++k) {
    if (k == 0 || !same(order[k], order[k - 1])) {
      group_first = order[k];
    } else if (order[k] < best_b) {
      best_a = group_first;
      best_b = order[k];
    }
  }
  if (best_a == UINT32_MAX) return std::nullopt;
  return std::make_pair(best_a, best_b);
}

// The signed volume of all shells together (only needed when there are several: with one,
// it is that shell's).
bool total_volume_positive(const std::vector<Point3>& P, const std::vector<Triangle>& tris) {
  std::vector<uint32_t> all(tris.size());
  std::iota(all.begin(), all.end(), 0u);
  return exact::signed_volume_sign(P, tris, all) == Sign::kPositive;
}

// Steps 1 and 2: faces of at least 3 vertices, in range, none repeated.
std::string check_face_indices(const std::vector<Point3>& P, const std::vector<std::vector<uint32_t>>& F) {
  if (F.empty() || P.empty()) return "empty mesh (no faces)";
  for (uint32_t f = 0; f < F.size(); ++f) {
    if (F[f].size() < 3) return "face " + S(f) + " has " + S(F[f].size()) + " vertices (at least 3 needed)";
    for (size_t i = 0; i < F[f].size(); ++i) {
      if (F[f][i] >= P.size()) return "face " + S(f) + " refers to missing vertex " + S(F[f][i]);
      for (size_t j = 0; j < i; ++j)
        if (F[f][i] == F[f][j]) return "face " + S(f) + " has the repeated vertex index " + S(F[f][i]);
    }
  }
  return {};
}

// The corners (half-edges) of the input polygons, corner c of face f being the edge from
// its vertex c to the next, with the number of uses of each undirected edge and the twin
// of each edge used exactly twice.
struct Corners {
  const std::vector<std::vector<uint32_t>>& F;
  std::vector<uint32_t> first, face, uses, twin;

  explicit Corners(const std::vector<std::vector<uint32_t>>& faces) : F(faces), first(faces.size() + 1, 0) {
    const uint32_t nf = uint32_t(F.size());
    for (uint32_t f = 0; f < nf; ++f) first[f + 1] = first[f] + uint32_t(F[f].size());
    face.resize(first[nf]);
    for (uint32_t f = 0; f < nf; ++f)
      for (uint32_t c = first[f]; c < first[f + 1]; ++c) face[c] = f;
    pair_edges();
  }
  uint32_t size() const { return first.back(); }
  uint32_t vertex(uint32_t c) const { return F[face[c]][c - first[face[c]]]; }
  uint32_t next(uint32_t c) const { return c + 1 == first[face[c] + 1] ? first[face[c]] : c + 1; }
  uint32_t prev(uint32_t c) const { return c == first[face[c]] ? first[face[c] + 1] - 1 : c - 1; }
  std::string edge(uint32_t c) const { return edge_name(vertex(c), vertex(next(c))); }

 private:
  void pair_edges() {
    const uint32_t nc = size();
    std::vector<HalfEdge> he(nc);
    for (uint32_t c = 0; c < nc; ++c) he[c] = {ekey(vertex(c), vertex(next(c))), c};
    tbb::parallel_sort(he.begin(), he.end(), [](const HalfEdge& a, const HalfEdge& b) {
      return a.key != b.key ? a.key < b.key : a.id < b.id;
    });
    interruption_point();
    uses.assign(nc, 0);
    twin.assign(nc, UINT32_MAX);
    for (size_t i = 0; i < nc;) {
      size_t j = i;
      while (j < nc && he[j].key == he[i].key) ++j;
      for (size_t k = i; k < j; ++k) uses[he[k].id] = uint32_t(j - i);
      if (j - i == 2) {
        twin[he[i].id] = he[i + 1].id;
        twin[he[i + 1].id] = he[i].id;
      }
      i = j;
    }
  }
};

// Steps 6-8: border edges, non-manifold edges, inconsistent orientation; the first
// offending edge in input order.
std::string check_edges(const Corners& k) {
  for (uint32_t c = 0; c < k.size(); ++c)
    if (k.uses[c] == 1)
      return "border edge " + k.edge(c) + " of face " + S(k.face[c]) + " is used by no other face (mesh not closed)";
  for (uint32_t c = 0; c < k.size(); ++c)
    if (k.uses[c] > 2)
      return "non-manifold edge " + k.edge(c) + " is used by " + S(k.uses[c]) + " faces (first: face " +
             S(k.face[c]) + ")";
  for (uint32_t c = 0; c < k.size(); ++c)
    if (k.vertex(k.twin[c]) == k.vertex(c))
      return "inconsistent orientation: faces " + S(k.face[c]) + " and " + S(k.face[k.twin[c]]) +
             " both traverse edge " + k.edge(c) + " in the same direction";
  return {};
}

// Step 9: the corners at a vertex form a single fan (the next corner around v is the twin
// of the incoming half-edge).
std::string check_vertex_fans(const Corners& k, size_t vertices) {
  std::vector<uint32_t> count(vertices, 0), start(vertices, UINT32_MAX);
  for (uint32_t c = 0; c < k.size(); ++c) {
    ++count[k.vertex(c)];
    if (start[k.vertex(c)] == UINT32_MAX) start[k.vertex(c)] = c;
  }
  for (uint32_t c = 0; c < k.size(); ++c) {
    const uint32_t v = k.vertex(c);
    if (start[v] != c) continue;
    uint32_t steps = 0, around = c;
    do {
      around = k.twin[k.prev(around)];
      ++steps;
    } while (around != c && steps <= count[v]);
    if (steps != count[v]) return "non-manifold vertex " + S(v) + ": its " + S(count[v]) + " faces form more than one fan";
  }
  return {};
}

// Shells: the edge-connected components of the faces, numbered in order of their first face.
std::vector<uint32_t> shells_of_faces(const Corners& k, uint32_t faces, uint32_t& shells) {
  std::vector<uint32_t> comp(faces);
  std::iota(comp.begin(), comp.end(), 0u);
  auto find = [&](uint32_t x) {
    while (comp[x] != x) x = comp[x] = comp[comp[x]];
    return x;
  };
  for (uint32_t c = 0; c < k.size(); ++c) {
    const uint32_t a = find(k.face[c]), b = find(k.face[k.twin[c]]);
    if (a != b) comp[std::max(a, b)] = std::min(a, b);
  }
  std::vector<uint32_t> shell_of_face(faces), shell_id(faces, UINT32_MAX);
  shells = 0;
  for (uint32_t f = 0; f < faces; ++f) {
    const uint32_t r = find(f);
    if (shell_id[r] == UINT32_MAX) shell_id[r] = shells++;
    shell_of_face[f] = shell_id[r];
  }
  return shell_of_face;
}

// Step 10: the exact signed volume of each shell: negative is an internal void, zero is
// refused, and all together must be positive (faces pointing outward).
std::string orient_shells(const std::vector<Point3>& P, const std::vector<Triangle>& tris,
                          const std::vector<uint32_t>& tri_face, const std::vector<uint32_t>& shell_of_face,
                          uint32_t shells, std::vector<bool>& is_void) {
  std::vector<std::vector<uint32_t>> shell_tris(shells);
  for (uint32_t t = 0; t < tris.size(); ++t) shell_tris[shell_of_face[tri_face[t]]].push_back(t);
  is_void.assign(shells, false);
  for (uint32_t s = 0; s < shells; ++s) {
    const Sign v = exact::signed_volume_sign(P, tris, shell_tris[s]);
    if (v == Sign::kZero)
      return "shell " + S(s) + " (containing face " + S(tri_face[shell_tris[s][0]]) + ") encloses zero volume";
    is_void[s] = v == Sign::kNegative;
  }
  if (shells == 1 ? is_void[0] : !total_volume_positive(P, tris))
    return "faces point inward (total signed volume is not positive)";
  return {};
}

// Triangle adjacency (with the diagonals inside split polygons). A diagonal that is also
// an edge elsewhere makes that edge non-manifold: a face touches a polygon's inside.
std::string triangle_neighbors(const std::vector<Triangle>& tris, const std::vector<uint32_t>& tri_face,
                               std::vector<std::array<uint32_t, 3>>& neighbor) {
  const uint32_t nt = uint32_t(tris.size());
  neighbor.assign(nt, {UINT32_MAX, UINT32_MAX, UINT32_MAX});
  std::vector<HalfEdge> th(3 * size_t(nt));
  for (uint32_t t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) th[3 * t + i] = {ekey(tris[t][i], tris[t][(i + 1) % 3]), 3 * t + i};
  tbb::parallel_sort(th.begin(), th.end(), [](const HalfEdge& a, const HalfEdge& b) {
    return a.key != b.key ? a.key < b.key : a.id < b.id;
  });
  interruption_point();
  for (size_t i = 0; i < th.size();) {
    size_t j = i;
    while (j < th.size() && th[j].key == th[i].key) ++j;
    if (j - i != 2) {
      return "self-intersection: edge " + edge_name(uint32_t(th[i].key >> 32), uint32_t(th[i].key)) +
             " inside polygon face " + S(tri_face[th[i].id / 3]) + " is also used by other faces";
    }
    neighbor[th[i].id / 3][th[i].id % 3] = th[i + 1].id / 3;
    neighbor[th[i + 1].id / 3][th[i + 1].id % 3] = th[i].id / 3;
    i = j;
  }
  return {};
}

}  // namespace

// The checks in a fixed order (the numbers above); each refusal names the first offending
// face, edge, vertex or shell.
StatusOr<SolidMesh> build_solid(const RawMesh& raw) {
  auto fail = [&](const std::string& what) { return InvalidArgument(raw.source + ": " + what); };
  const auto& P = raw.points;
  const auto& F = raw.faces;
  if (std::string e = check_face_indices(P, F); !e.empty()) return fail(e);
  // 3. Polygons planar and simple, split into triangles; 4. no zero-area faces.
  std::vector<Triangle> tris;
  std::vector<uint32_t> tri_face;
  if (std::string e = triangulate_faces(P, F, tris, tri_face); !e.empty()) return fail(e);
  // 5. No duplicate faces (the same vertex set).
  if (auto pair = first_duplicate_faces(F))
    return fail("faces " + S(pair->first) + " and " + S(pair->second) + " are duplicates (same vertices)");
  const Corners corners(F);
  if (std::string e = check_edges(corners); !e.empty()) return fail(e);
  if (std::string e = check_vertex_fans(corners, P.size()); !e.empty()) return fail(e);
  uint32_t shells = 0;
  const std::vector<uint32_t> shell_of_face = shells_of_faces(corners, uint32_t(F.size()), shells);
  std::vector<bool> is_void;
  if (std::string e = orient_shells(P, tris, tri_face, shell_of_face, shells, is_void); !e.empty()) return fail(e);
  std::vector<std::array<uint32_t, 3>> neighbor;
  if (std::string e = triangle_neighbors(tris, tri_face, neighbor); !e.empty()) return fail(e);
  // 11. No self-intersections.
  if (auto pair = mesh_internal::find_self_intersection(P, tris, tri_face))
    return fail("self-intersection: faces " + S(pair->first) + " and " + S(pair->second) + " intersect");

  SolidMesh m;
  m.source = raw.source;
  m.points = P;
  m.triangles = std::move(tris);
  m.triangle_face = std::move(tri_face);
  m.input_face_count = uint32_t(F.size());
  m.neighbor = std::move(neighbor);
  m.shell.resize(m.triangles.size());
  for (uint32_t t = 0; t < m.triangles.size(); ++t) m.shell[t] = shell_of_face[m.triangle_face[t]];
  m.shell_is_void = std::move(is_void);
  m.groups = raw.groups;
  return m;
}

}  // namespace gvm
