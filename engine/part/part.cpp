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
#include "exact/predicates.h"
#include "parallel/interrupt.h"
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

// The solid mesh's topology as build_solid makes it (a caller may have built it by hand).
Status check_topology(const SolidMesh& mesh, const std::string& src) {
  const size_t nt = mesh.triangles.size();
  if (nt == 0) return InvalidArgument(src + ": the part has no triangles");
  if (mesh.neighbor.size() != nt || mesh.triangle_face.size() != nt || mesh.shell.size() != nt)
    return FailedPrecondition(src + ": the solid mesh has no topology (use build_solid)");
  for (size_t t = 0; t < nt; ++t) {
    for (int i = 0; i < 3; ++i)
      if (mesh.triangles[t][i] >= mesh.points.size() || mesh.neighbor[t][i] >= nt)
        return FailedPrecondition(src + ": triangle " + std::to_string(t) + " has an invalid vertex or neighbor");
    if (mesh.triangle_face[t] >= mesh.input_face_count || mesh.shell[t] >= mesh.shell_is_void.size())
      return FailedPrecondition(src + ": triangle " + std::to_string(t) + " has an invalid input face or shell");
  }
  return Status();
}

// The user's face groups: valid, disjoint input faces; the group of each input face.
struct FaceGroups {
  std::vector<uint32_t> of_face;
  std::vector<std::string> names;
};

StatusOr<FaceGroups> user_face_groups(const SolidMesh& mesh, const PartOptions& options, const std::string& src) {
  FaceGroups groups{std::vector<uint32_t>(mesh.input_face_count, kNone), {}};
  for (const auto& [name, faces] : options.face_groups) {
    if (faces.empty()) return InvalidArgument(src + ": face group '" + name + "' is empty");
    const uint32_t g = static_cast<uint32_t>(groups.names.size());
    groups.names.push_back(name);
    for (uint32_t f : faces) {
      if (f >= mesh.input_face_count)
        return InvalidArgument(src + ": face group '" + name + "' names face " + std::to_string(f) +
                               ", but the part has " + std::to_string(mesh.input_face_count) + " faces");
      if (groups.of_face[f] != kNone)
        return InvalidArgument(src + ": face " + std::to_string(f) + " is in face groups '" +
                               groups.names[groups.of_face[f]] + "' and '" + name + "'");
      groups.of_face[f] = g;
    }
  }
  return groups;
}

// Hull facets. A triangle is a hull facet iff every vertex lies on the closed negative
// side of its plane, i.e. iff the maximum of n . x over the convex hull's vertices is
// attained on the triangle's plane. The maximum is found exactly by hill climbing on the
// hull graph, warm-started from the answer of a neighboring triangle. `used`: the vertices
// of some triangle.
StatusOr<std::vector<uint8_t>> hull_facets(const SolidMesh& m, const std::vector<uint32_t>& used,
                                           const std::string& src) {
  const part::ConvexHull hull = part::convex_hull(m.points, used);
  if (hull.facets.empty()) return InvalidArgument(src + ": all vertices are coplanar, the part bounds no volume");
  const size_t nt = m.triangles.size();
  auto P = [&](uint32_t t, int i) -> const Point3& { return m.points[m.triangles[t][i]]; };
  std::vector<uint8_t> on_hull(nt, 0);
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
        best[i] = part::hull_extreme_vertex(hull, m.points, P(t, 0), P(t, 1), P(t, 2), start[t]);
        on_hull[t] = exact::orient3d(P(t, 0), P(t, 1), P(t, 2), m.points[best[i]]) != Sign::kPositive;
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
  return on_hull;
}

// Concave regions: the edge-connected components of the triangles off the hull; the
// region of each triangle (-1 on the hull).
std::vector<ConcaveRegion> concave_regions(const SolidMesh& m, const std::vector<uint8_t>& on_hull,
                                           std::vector<int32_t>& region) {
  std::vector<ConcaveRegion> regions;
  region.assign(m.triangles.size(), -1);
  for (uint32_t seed = 0; seed < m.triangles.size(); ++seed) {
    if (on_hull[seed] || region[seed] >= 0) continue;
    ConcaveRegion r;
    r.id = static_cast<uint32_t>(regions.size());
    r.is_void = m.shell_is_void[m.shell[seed]];
    region[seed] = static_cast<int32_t>(r.id);
    r.triangles.push_back(seed);
    for (size_t qi = 0; qi < r.triangles.size(); ++qi)
      for (uint32_t u : m.neighbor[r.triangles[qi]])
        if (!on_hull[u] && region[u] < 0) {
          region[u] = static_cast<int32_t>(r.id);
          r.triangles.push_back(u);
        }
    std::sort(r.triangles.begin(), r.triangles.end());
    regions.push_back(std::move(r));
  }
  return regions;
}

// Features: the triangles of one input face, and of one user group, always together;
// otherwise edge-connected triangles of one region (or of the hull) whose normals turn by
// at most the feature angle across the edge between them.
std::vector<Feature> features_of(const SolidMesh& m, const std::vector<uint8_t>& on_hull,
                                 const std::vector<int32_t>& region, const FaceGroups& groups,
                                 double feature_angle_degrees) {
  const size_t nt = m.triangles.size();
  const double theta = feature_angle_degrees * M_PI / 180.0;
  const double k = theta >= M_PI ? -1.0 : std::cos(theta);
  auto P = [&](uint32_t t, int i) -> const Point3& { return m.points[m.triangles[t][i]]; };
  std::vector<uint32_t> tri_group(nt, kNone);
  for (uint32_t t = 0; t < nt; ++t) tri_group[t] = groups.of_face[m.triangle_face[t]];
  UnionFind uf(nt);
  std::vector<uint32_t> face_first(m.input_face_count, kNone), group_first(groups.names.size(), kNone);
  for (uint32_t t = 0; t < nt; ++t) {
    const uint32_t f = m.triangle_face[t];
    if (face_first[f] == kNone) face_first[f] = t; else uf.unite(face_first[f], t);
    const uint32_t g = tri_group[t];
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
        if (on_hull[t] != on_hull[u] || region[t] != region[u]) continue;
        smooth[t][i] = exact::normals_within(P(t, 0), P(t, 1), P(t, 2), P(u, 0), P(u, 1), P(u, 2), k);
      }
    }
  });
  interruption_point();
  for (uint32_t t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i)
      if (smooth[t][i]) uf.unite(t, m.neighbor[t][i]);
  // Roots are the smallest members, so features come in order of smallest triangle.
  std::vector<Feature> features;
  std::vector<uint32_t> feature_of_root(nt, kNone);
  for (uint32_t t = 0; t < nt; ++t) {
    const uint32_t r = uf.find(t);
    if (feature_of_root[r] == kNone) {
      feature_of_root[r] = static_cast<uint32_t>(features.size());
      Feature f;
      f.id = feature_of_root[r];
      f.automatic = tri_group[t] == kNone;
      f.name = f.automatic ? "F" + std::to_string(f.id) : groups.names[tri_group[t]];
      f.on_hull = true;
      features.push_back(std::move(f));
    }
    Feature& f = features[feature_of_root[r]];
    f.triangles.push_back(t);
    if (!on_hull[t]) {
      if (f.on_hull) f.region = region[t];
      f.on_hull = false;
    }
  }
  return features;
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
  const std::string src = mesh.source.empty() ? std::string("part") : mesh.source;
  if (Status s = check_topology(mesh, src); !s.ok()) return s;
  StatusOr<FaceGroups> groups = user_face_groups(mesh, options, src);
  if (!groups.ok()) return groups.status();

  auto impl = std::make_unique<Impl>();
  Impl& I = *impl;
  I.mesh = std::move(mesh);
  const SolidMesh& m = I.mesh;
  const size_t nt = m.triangles.size(), nv = m.points.size();
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
  std::vector<uint32_t> used;
  used.reserve(nv);
  for (uint32_t v = 0; v < nv; ++v)
    if (I.vt_offset[v + 1] > I.vt_offset[v]) used.push_back(v);
  StatusOr<std::vector<uint8_t>> hull = hull_facets(m, used, src);
  if (!hull.ok()) return hull.status();
  I.hull = std::move(*hull);
  I.regions = concave_regions(m, I.hull, I.region);
  I.features = features_of(m, I.hull, I.region, *groups, options.feature_angle_degrees);
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
