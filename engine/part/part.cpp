#include "gvm/part.h"

#include <google/protobuf/struct.pb.h>
#include <google/protobuf/util/json_util.h>
#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <numeric>
#include <set>
#include <sstream>

#include "exact/filtered.h"
#include "exact/interrupt.h"
#include "exact/predicates.h"
#include "part/convex_hull.h"
#include "part/potentially_facing.h"

namespace gvm {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

// A non-negative integral double as digits, however large (a cast past 2^64 is undefined).
std::string integer_text(double d) {
  if (d < 0x1p63) return std::to_string(static_cast<uint64_t>(d));
  std::ostringstream text;
  text.precision(17);
  text << d;
  return text.str();
}

struct UnionFind {
  std::vector<uint32_t> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t find(uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(uint32_t a, uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // root = smallest member
  }
};

// Builds a CSR table from (key, value) pairs.
void build_csr(size_t keys, const std::vector<std::pair<uint32_t, uint32_t>>& pairs,
               std::vector<uint32_t>& offset, std::vector<uint32_t>& values) {
  offset.assign(keys + 1, 0);
  for (const auto& [k, v] : pairs) ++offset[k + 1];
  for (size_t i = 1; i <= keys; ++i) offset[i] += offset[i - 1];
  values.resize(pairs.size());
  std::vector<uint32_t> pos(offset.begin(), offset.end() - 1);
  for (const auto& [k, v] : pairs) values[pos[k]++] = v;
}

// A sorted set of triangle ids with O(log n) membership.
struct IdSet {
  std::vector<uint32_t> ids;
  IdSet(std::span<const uint32_t> s, size_t limit) {
    for (uint32_t t : s)
      if (t < limit) ids.push_back(t);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  }
  bool contains(uint32_t t) const { return std::binary_search(ids.begin(), ids.end(), t); }
};

// body(i, found) for every i < n, in parallel; all it found, sorted, without repeats.
template <class Body>
std::vector<uint32_t> sorted_union(size_t n, const Body& body) {
  tbb::combinable<std::vector<uint32_t>> parts;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& r) {
    std::vector<uint32_t>& found = parts.local();
    for (size_t i = r.begin(); i != r.end(); ++i) body(i, found);
  });
  std::vector<uint32_t> all;
  parts.combine_each([&](const std::vector<uint32_t>& p) { all.insert(all.end(), p.begin(), p.end()); });
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

}  // namespace

struct Part::Impl {
  SolidMesh mesh;
  std::vector<uint8_t> hull;
  std::vector<int32_t> region;
  std::vector<ConcaveRegion> regions;
  std::vector<Feature> features;
  std::vector<uint32_t> vt_offset, vt;  // vertex -> incident triangles
  std::vector<uint32_t> vv_offset, vv;  // vertex -> neighbor vertices
  double coordinate_bound = 0;          // the largest absolute coordinate of a vertex

  const Point3& P(uint32_t t, int i) const { return mesh.points[mesh.triangles[t][i]]; }
};

Part::Part(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Part::Part(Part&&) noexcept = default;
Part& Part::operator=(Part&&) noexcept = default;
Part::~Part() = default;

const SolidMesh& Part::mesh() const { return impl_->mesh; }
bool Part::is_hull(uint32_t t) const { return impl_->hull[t] != 0; }
int32_t Part::region_of(uint32_t t) const { return impl_->region[t]; }
const std::vector<ConcaveRegion>& Part::regions() const { return impl_->regions; }
const std::vector<Feature>& Part::features() const { return impl_->features; }

StatusOr<Part> Part::analyze(SolidMesh mesh, const PartOptions& options) {
  auto impl = std::make_unique<Impl>();
  const size_t nt = mesh.triangles.size();
  const std::string src = mesh.source.empty() ? std::string("part") : mesh.source;
  if (nt == 0) return InvalidArgument(src + ": the part has no triangles");
  if (mesh.neighbor.size() != nt || mesh.triangle_face.size() != nt || mesh.shell.size() != nt)
    return FailedPrecondition(src + ": the solid mesh has no topology (use build_solid)");
  for (size_t t = 0; t < nt; ++t) {
    for (int i = 0; i < 3; ++i)
      if (mesh.triangles[t][i] >= mesh.points.size() || mesh.neighbor[t][i] >= nt)
        return FailedPrecondition(src + ": triangle " + std::to_string(t) +
                                  " has an invalid vertex or neighbor");
    if (mesh.triangle_face[t] >= mesh.input_face_count || mesh.shell[t] >= mesh.shell_is_void.size())
      return FailedPrecondition(src + ": triangle " + std::to_string(t) +
                                " has an invalid input face or shell");
  }
  // User groups: valid, disjoint input faces.
  std::vector<uint32_t> face_group(mesh.input_face_count, kNone);
  std::vector<std::string> group_names;
  for (const auto& [name, faces] : options.face_groups) {
    if (faces.empty()) return InvalidArgument(src + ": face group '" + name + "' is empty");
    uint32_t g = static_cast<uint32_t>(group_names.size());
    group_names.push_back(name);
    for (uint32_t f : faces) {
      if (f >= mesh.input_face_count)
        return InvalidArgument(src + ": face group '" + name + "' names face " +
                               std::to_string(f) + ", but the part has " +
                               std::to_string(mesh.input_face_count) + " faces");
      if (face_group[f] != kNone)
        return InvalidArgument(src + ": face " + std::to_string(f) + " is in face groups '" +
                               group_names[face_group[f]] + "' and '" + name + "'");
      face_group[f] = g;
    }
  }

  Impl& I = *impl;
  I.mesh = std::move(mesh);
  const SolidMesh& m = I.mesh;
  const size_t nv = m.points.size();
  for (const Point3& p : m.points) {
    I.coordinate_bound = std::max({I.coordinate_bound, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  }

  // Adjacency: vertex -> triangles, vertex -> neighbor vertices (each directed triangle
  // edge (a, b) gives b as a neighbor of a; on a closed manifold every edge appears once
  // in each direction).
  {
    std::vector<std::pair<uint32_t, uint32_t>> vt, vv;
    vt.reserve(3 * nt);
    vv.reserve(3 * nt);
    for (uint32_t t = 0; t < nt; ++t)
      for (int i = 0; i < 3; ++i) {
        vt.emplace_back(m.triangles[t][i], t);
        vv.emplace_back(m.triangles[t][i], m.triangles[t][(i + 1) % 3]);
      }
    build_csr(nv, vt, I.vt_offset, I.vt);
    build_csr(nv, vv, I.vv_offset, I.vv);
  }

  // 1. Hull facets. A triangle is a hull facet iff every vertex lies on the closed
  // negative side of its plane, i.e. iff the maximum of n . x over the convex hull's
  // vertices is attained on the triangle's plane. The maximum is found exactly by hill
  // climbing on the hull graph, warm-started from the answer of a neighboring triangle.
  {
    std::vector<uint32_t> use;
    use.reserve(nv);
    for (uint32_t v = 0; v < nv; ++v)
      if (I.vt_offset[v + 1] > I.vt_offset[v]) use.push_back(v);
    part::ConvexHull hull = part::convex_hull(m.points, use);
    if (hull.facets.empty())
      return InvalidArgument(src + ": all vertices are coplanar, the part bounds no volume");
    I.hull.assign(nt, 0);
    // Breadth-first from each seed, one level at a time: the triangles of a level are
    // decided in parallel, each warm-started from the answer of the one that reached it.
    std::vector<uint32_t> start(nt, kNone), level, next, best;
    for (uint32_t seed = 0; seed < nt; ++seed) {
      if (start[seed] != kNone) continue;
      start[seed] = hull.any_vertex;
      level.assign(1, seed);
      while (!level.empty()) {
        best.resize(level.size());
        tbb::parallel_for(size_t(0), level.size(), [&](size_t i) {
          const uint32_t t = level[i];
          best[i] = part::hull_extreme_vertex(hull, m.points, I.P(t, 0), I.P(t, 1), I.P(t, 2),
                                              start[t]);
          I.hull[t] = exact::orient3d(I.P(t, 0), I.P(t, 1), I.P(t, 2), m.points[best[i]]) !=
                      Sign::kPositive;
        });
        interruption_point();  // triangles left undecided when cancelled
        next.clear();
        for (size_t i = 0; i < level.size(); ++i)
          for (uint32_t u : m.neighbor[level[i]])
            if (start[u] == kNone) {
              start[u] = best[i];
              next.push_back(u);
            }
        level.swap(next);
      }
    }
  }

  // 2. Concave regions: edge-connected components of non-hull triangles.
  I.region.assign(nt, -1);
  for (uint32_t seed = 0; seed < nt; ++seed) {
    if (I.hull[seed] || I.region[seed] >= 0) continue;
    ConcaveRegion r;
    r.id = static_cast<uint32_t>(I.regions.size());
    r.is_void = m.shell_is_void[m.shell[seed]];
    I.region[seed] = static_cast<int32_t>(r.id);
    r.triangles.push_back(seed);
    for (size_t qi = 0; qi < r.triangles.size(); ++qi)
      for (uint32_t u : m.neighbor[r.triangles[qi]])
        if (!I.hull[u] && I.region[u] < 0) {
          I.region[u] = static_cast<int32_t>(r.id);
          r.triangles.push_back(u);
        }
    std::sort(r.triangles.begin(), r.triangles.end());
    I.regions.push_back(std::move(r));
  }

  // 3. Features.
  {
    const double theta = options.feature_angle_degrees * M_PI / 180.0;
    const double k = theta >= M_PI ? -1.0 : std::cos(theta);
    std::vector<uint32_t> tri_group(nt, kNone);
    for (uint32_t t = 0; t < nt; ++t) tri_group[t] = face_group[m.triangle_face[t]];
    UnionFind uf(nt);
    // Triangles of one input face, and of one user group, always belong together.
    std::vector<uint32_t> face_first(m.input_face_count, kNone), group_first(group_names.size(), kNone);
    for (uint32_t t = 0; t < nt; ++t) {
      uint32_t f = m.triangle_face[t];
      if (face_first[f] == kNone) face_first[f] = t; else uf.unite(face_first[f], t);
      uint32_t g = tri_group[t];
      if (g != kNone) {
        if (group_first[g] == kNone) group_first[g] = t; else uf.unite(group_first[g], t);
      }
    }
    // The edges whose normals turn by at most the feature angle, each from its smaller
    // triangle, tested in parallel; united after (the roots do not depend on the order).
    std::vector<std::array<bool, 3>> smooth(nt, {false, false, false});
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, nt, 1024), [&](const tbb::blocked_range<uint32_t>& range) {
      for (uint32_t t = range.begin(); t != range.end(); ++t) {
        if (tri_group[t] != kNone) continue;
        for (int i = 0; i < 3; ++i) {
          const uint32_t u = m.neighbor[t][i];
          if (u <= t || tri_group[u] != kNone || m.triangle_face[u] == m.triangle_face[t]) continue;
          if (I.hull[t] != I.hull[u] || I.region[t] != I.region[u]) continue;
          smooth[t][i] = exact::normals_within(I.P(t, 0), I.P(t, 1), I.P(t, 2), I.P(u, 0), I.P(u, 1), I.P(u, 2), k);
        }
      }
    });
    interruption_point();
    for (uint32_t t = 0; t < nt; ++t)
      for (int i = 0; i < 3; ++i)
        if (smooth[t][i]) uf.unite(t, m.neighbor[t][i]);
    // Roots are the smallest members, so features come in order of smallest triangle.
    std::vector<uint32_t> feature_of_root(nt, kNone);
    for (uint32_t t = 0; t < nt; ++t) {
      uint32_t r = uf.find(t);
      if (feature_of_root[r] == kNone) {
        feature_of_root[r] = static_cast<uint32_t>(I.features.size());
        Feature f;
        f.id = feature_of_root[r];
        f.automatic = tri_group[t] == kNone;
        f.name = f.automatic ? "F" + std::to_string(f.id) : group_names[tri_group[t]];
        f.on_hull = true;
        I.features.push_back(std::move(f));
      }
      Feature& f = I.features[feature_of_root[r]];
      f.triangles.push_back(t);
      if (!I.hull[t]) {
        if (f.on_hull) f.region = I.region[t];
        f.on_hull = false;
      }
    }
  }
  return Part(std::move(impl));
}

std::vector<uint32_t> Part::neighbor_occluders(std::span<const uint32_t> s) const {
  const Impl& I = *impl_;
  const SolidMesh& m = I.mesh;
  const IdSet in_s(s, m.triangles.size());
  // Across the concave edges of S: the far vertex of the neighbour strictly in front of t.
  std::vector<uint32_t> out = sorted_union(in_s.ids.size(), [&](size_t k, std::vector<uint32_t>& found) {
    const uint32_t t = in_s.ids[k];
    const Triangle& tr = m.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const uint32_t u = m.neighbor[t][i];
      if (in_s.contains(u)) continue;
      const Triangle& ur = m.triangles[u];
      uint32_t opp = ur[0];
      for (uint32_t v : ur)
        if (v != tr[i] && v != tr[(i + 1) % 3]) opp = v;
      if (exact::orient3d(I.P(t, 0), I.P(t, 1), I.P(t, 2), m.points[opp]) == Sign::kPositive) found.push_back(u);
    }
  });
  std::vector<uint32_t> verts;
  for (uint32_t t : in_s.ids) verts.insert(verts.end(), m.triangles[t].begin(), m.triangles[t].end());
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  // At the vertices of S: a face F whose closed front side holds every edge at the vertex.
  const std::vector<uint32_t> at_vertices = sorted_union(verts.size(), [&](size_t k, std::vector<uint32_t>& found) {
    const uint32_t v = verts[k];
    const Point3& pv = m.points[v];
    for (uint32_t j = I.vt_offset[v]; j < I.vt_offset[v + 1]; ++j) {
      const uint32_t f = I.vt[j];
      if (in_s.contains(f)) continue;
      bool covers = true;
      for (uint32_t e = I.vv_offset[v]; e < I.vv_offset[v + 1] && covers; ++e)
        // (w - v) . n_F >= 0: every edge at v on the closed front side of F.
        covers = exact::det_diff(I.P(f, 0), I.P(f, 1), I.P(f, 0), I.P(f, 2), pv, m.points[I.vv[e]]) != Sign::kNegative;
      if (covers) found.push_back(f);
    }
  });
  std::vector<uint32_t> merged;
  std::set_union(out.begin(), out.end(), at_vertices.begin(), at_vertices.end(), std::back_inserter(merged));
  return merged;
}

std::vector<uint32_t> Part::potential_occluders(
    std::span<const uint32_t> s, std::span<const uint32_t> neighbor,
    const std::function<bool(uint32_t)>& may_be_front_hit) const {
  const Impl& I = *impl_;
  const SolidMesh& m = I.mesh;
  IdSet in_s(s, m.triangles.size());
  IdSet in_n(neighbor, m.triangles.size());

  // S's non-hull triangles, per concave region.
  std::map<int32_t, std::vector<uint32_t>> s_by_region;
  for (uint32_t t : in_s.ids)
    if (I.region[t] >= 0) s_by_region[I.region[t]].push_back(t);

  std::vector<uint32_t> passed;
  for (auto& [r, s_r] : s_by_region) {
    std::vector<uint32_t> cand;
    for (uint32_t t : I.regions[r].triangles)
      if (!in_s.contains(t) && !in_n.contains(t)) cand.push_back(t);
    if (cand.empty()) continue;
    const part_internal::PotentiallyFacing facing(m, s_r, I.coordinate_bound);
    std::vector<uint8_t> ok(cand.size(), 0);
    tbb::parallel_for(size_t(0), cand.size(), [&](size_t ci) {
      interruption_point();  // one search of S's triangles per candidate
      ok[ci] = facing.faces(cand[ci]);
    });
    interruption_point();  // candidates left undecided when cancelled
    for (size_t ci = 0; ci < cand.size(); ++ci)
      if (ok[ci]) passed.push_back(cand[ci]);
  }
  std::sort(passed.begin(), passed.end());
  std::vector<uint32_t> out;
  Interruptions interruptions(16);
  for (uint32_t t : passed) {
    interruptions.tick();
    if (may_be_front_hit(t)) out.push_back(t);
  }
  return out;
}

StatusOr<std::map<std::string, std::vector<uint32_t>>> read_face_groups(
    const std::string& path, uint32_t face_count) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return NotFound(path + ": cannot open the face group file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_face_groups(ss.str(), face_count, path);
}

StatusOr<std::map<std::string, std::vector<uint32_t>>> parse_face_groups(
    std::string_view json, uint32_t face_count, const std::string& path) {
  google::protobuf::Struct root;
  auto st = google::protobuf::util::JsonStringToMessage(
      google::protobuf::StringPiece(json.data(), json.size()), &root);
  if (!st.ok())
    return InvalidArgument(path + ": not a JSON object of face groups: " +
                           std::string(st.message()));
  std::map<std::string, std::vector<uint32_t>> groups;
  std::map<uint32_t, std::string> owner;
  std::vector<std::string> names;  // sorted, so that messages do not depend on hashing
  for (const auto& field : root.fields()) names.push_back(field.first);
  std::sort(names.begin(), names.end());
  for (const std::string& name : names) {
    const google::protobuf::Value& value = root.fields().at(name);
    const std::string where = path + ": face group '" + name + "'";
    if (!value.has_list_value())
      return InvalidArgument(where + " is not a list of face indices");
    std::vector<uint32_t> faces;
    const auto& list = value.list_value();
    if (list.values_size() == 0) return InvalidArgument(where + " is empty");
    for (int i = 0; i < list.values_size(); ++i) {
      const auto& v = list.values(i);
      if (!v.has_number_value())
        return InvalidArgument(where + ": entry " + std::to_string(i) + " is not a number");
      const double d = v.number_value();
      if (!(d >= 0) || d != std::floor(d))
        return InvalidArgument(where + ": entry " + std::to_string(i) +
                               " is not a non-negative integer face index");
      if (d >= static_cast<double>(face_count))
        return InvalidArgument(where + ": face " + integer_text(d) +
                               " does not exist (the part has " + std::to_string(face_count) +
                               " faces)");
      const uint32_t f = static_cast<uint32_t>(d);
      auto [it, inserted] = owner.emplace(f, name);
      if (!inserted)
        return InvalidArgument(path + ": face " + std::to_string(f) +
                               (it->second == name ? " appears twice in face group '" + name + "'"
                                                   : " is in face groups '" + it->second +
                                                         "' and '" + name + "'"));
      faces.push_back(f);
    }
    groups.emplace(name, std::move(faces));
  }
  return groups;
}

}  // namespace gvm
