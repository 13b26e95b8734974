#include "visibility/effective_minkowski_envelope.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <tuple>

#include <tbb/parallel_for.h>

#include "exact/predicates.h"
#include "parallel/interrupt.h"
#include "visibility/direction_window.h"
#include "visibility/surface_topology.h"

namespace gvm {
namespace {

// Signs seen in a critical set.
struct CriticalSet {
  bool positive = false, negative = false;
  void add(Sign s) {
    positive |= s == Sign::kPositive;
    negative |= s == Sign::kNegative;
  }
  bool mixed() const { return positive && negative; }
};

// Orientation of a kept tentative face with plane normal n (a chosen orientation of the
// tentative normal): +1 when its outward normal is n, -1 when it is -n, 0 when the face
// is tangent to the origin or front-facing (not in the envelope). `sigma` is the sign of
// n . x for a point x of the face (the side of the origin is -sigma).
int envelope_orientation(const CriticalSet& c, Sign sigma) {
  if (sigma == Sign::kZero) return 0;  // plane through the origin: projects to an arc
  int s = static_cast<int>(sigma);
  // Lemma 2: volume on the side where the critical values point, outward the other way.
  // {0,0}: taken as back-facing (the paper's convention for non-general position).
  int outward = c.positive ? -1 : (c.negative ? 1 : s);
  // Back-facing to the origin c: the origin lies behind the face, i.e. x . n_out > 0.
  return outward == s ? outward : 0;
}

// One oriented edge of an envelope face, keyed by its parents.
struct EdgeRef {
  // kind 0: V_O + (-E_S) = (q - a) -> (q - b), keyed (q, a, b) with a < b;
  // kind 1: E_O + (-V_S) = (c - p) -> (d - p), keyed (c, d, p) with c < d.
  uint32_t kind, x, y, z;
  int32_t sign;
  uint32_t face;
  auto key() const { return std::tie(kind, x, y, z); }
};

class Builder {
 public:
  explicit Builder(bool keep_faces) : keep_faces_(keep_faces) {}

  // Adds a kept, back-facing face with vertices (q_i, p_i) counter-clockwise around its
  // outward normal.
  void add_face(std::span<const std::pair<uint32_t, uint32_t>> cycle) {
    const uint32_t face = faces_++;
    const auto* v = cycle.data();
    const size_t n = cycle.size();
    for (size_t i = 0; i < n; ++i) {
      auto [q0, p0] = v[i];
      auto [q1, p1] = v[(i + 1) % n];
      if (q0 == q1) {
        edges_.push_back({0, q0, std::min(p0, p1), std::max(p0, p1), p0 < p1 ? 1 : -1, face});
      } else {
        edges_.push_back({1, std::min(q0, q1), std::max(q0, q1), p0, q0 < q1 ? 1 : -1, face});
      }
    }
    if (keep_faces_) out_.faces.push_back({std::vector(cycle.begin(), cycle.end())});
  }

  EffectiveMinkowskiEnvelope finish(EnvelopeStatistics stats) {
    std::sort(edges_.begin(), edges_.end(),
              [](const EdgeRef& a, const EdgeRef& b) { return a.key() < b.key(); });
    std::vector<uint32_t> parent(faces_);
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](uint32_t f) {
      while (parent[f] != f) f = parent[f] = parent[parent[f]];
      return f;
    };
    for (size_t i = 0; i < edges_.size();) {
      size_t j = i;
      int32_t net = 0;
      for (; j < edges_.size() && edges_[j].key() == edges_[i].key(); ++j) {
        net += edges_[j].sign;
        parent[find(edges_[j].face)] = find(edges_[i].face);
      }
      if (net != 0) out_.border.push_back(border_edge(edges_[i], net));
      i = j;
    }
    for (uint32_t f = 0; f < faces_; ++f) stats.patches += find(f) == f;
    stats.envelope_faces = faces_;
    stats.border_edges = out_.border.size();
    out_.statistics = stats;
    return std::move(out_);
  }

 private:
  static EnvelopeBorderEdge border_edge(const EdgeRef& e, int32_t net) {
    EnvelopeBorderEdge b = e.kind == 0 ? EnvelopeBorderEdge{e.x, e.y, e.x, e.z, net}
                                       : EnvelopeBorderEdge{e.x, e.z, e.y, e.z, net};
    if (net < 0) {  // walk it the other way so the multiplicity is positive
      std::swap(b.q0, b.q1);
      std::swap(b.p0, b.p1);
      b.multiplicity = -net;
    }
    return b;
  }

  bool keep_faces_;
  uint32_t faces_ = 0;
  std::vector<EdgeRef> edges_;
  EffectiveMinkowskiEnvelope out_;
};

// Envelope faces found by one chunk of the enumeration, in enumeration order.
struct Partial {
  struct Face {
    uint8_t n = 0;
    std::array<std::pair<uint32_t, uint32_t>, 4> v;
  };
  std::vector<Face> faces;
  uint64_t tentative = 0, outside_window = 0, kept = 0;
  void add(std::initializer_list<std::pair<uint32_t, uint32_t>> cycle) {
    Face f;
    f.n = static_cast<uint8_t>(cycle.size());
    std::copy(cycle.begin(), cycle.end(), f.v.begin());
    faces.push_back(f);
  }
};

// Runs body(i, partial) for i in [0, n) in parallel, in fixed chunks whose results are
// kept in chunk order: the envelope does not depend on the thread count.
template <class Body>
void for_each_chunked(size_t n, std::vector<Partial>& out, const Body& body) {
  constexpr size_t kChunk = 8;
  const size_t chunks = (n + kChunk - 1) / kChunk, base = out.size();
  out.resize(base + chunks);
  tbb::parallel_for(size_t{0}, chunks, [&](size_t c) {
    for (size_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i) {
      interruption_point();  // one i runs over every vertex or edge of the other side
      body(i, out[base + c]);
    }
  });
  interruption_point();  // chunks left undone when cancelled
}

}  // namespace

std::vector<EnvelopeBorderEdge> border_chain(std::span<const EnvelopeFace> faces) {
  Builder builder(/*keep_faces=*/false);
  for (const EnvelopeFace& f : faces) builder.add_face(f.vertices);
  return builder.finish({}).border;
}

EffectiveMinkowskiEnvelope compute_effective_minkowski_envelope(const SolidMesh& mesh,
                                                                std::span<const uint32_t> s,
                                                                std::span<const uint32_t> o,
                                                                bool keep_faces,
                                                                const DirectionWindow* window) {
  const SurfaceTopology ts(mesh, s), to(mesh, o);
  const auto& P = mesh.points;
  std::vector<Partial> parts;
  // The window's rows of the points of O and S, and of S's edges, so that the test of one
  // tentative face is a few comparisons.
  const size_t K = window ? window->row_size() : 0;
  auto row = [&](std::initializer_list<uint32_t> vertices, bool largest, double* out) {
    if (K) window->row(mesh, vertices, largest, out);
  };
  auto point_rows = [&](std::span<const uint32_t> points, bool largest) {
    std::vector<double> out(points.size() * K);
    for (size_t i = 0; i < points.size(); ++i) row({points[i]}, largest, &out[i * K]);
    return out;
  };
  using Side = WindowRows::Side;
  const WindowRows o_vertex(window, to.vertices().size(), point_rows(to.vertices(), true), Side::occluder);
  const WindowRows s_vertex(window, ts.vertices().size(), point_rows(ts.vertices(), false), Side::surface);
  std::vector<double> s_edge_min(ts.edges().size() * K);
  for (size_t i = 0; i < ts.edges().size(); ++i) row({ts.edges()[i].a, ts.edges()[i].b}, false, &s_edge_min[i * K]);
  const WindowRows s_edge(window, ts.edges().size(), std::move(s_edge_min), Side::surface);
  // Pairs the window rules out are counted, not visited.
  auto visit_meeting = [](const WindowRows& rows, const std::vector<double>& other, Partial& out, auto&& visit) {
    size_t visited = 0;
    rows.for_each_meeting(other.data(), [&](size_t i) {
      ++visited;
      visit(i);
      return true;
    });
    out.tentative += rows.size();
    out.outside_window += rows.size() - visited;
  };

  // VF: V_O + (-F_S). Normal n = (b - a) x (c - a) of F_S; the face (q-a, q-b, q-c) has
  // normal n; volume directions are O's edges at q.
  for_each_chunked(s.size(), parts, [&](size_t si, Partial& out) {
    const Triangle& f = mesh.triangles[s[si]];
    const exact::PlaneSide plane(P[f[0]], P[f[1]], P[f[2]]);
    std::vector<double> p_min(K);
    row({f[0], f[1], f[2]}, false, p_min.data());
    visit_meeting(o_vertex, p_min, out, [&](size_t i) {
      const uint32_t q = to.vertices()[i];
      CriticalSet crit;
      for (uint32_t w : to.neighbors(i)) {
        crit.add(plane.along(P[q], P[w]));
        if (crit.mixed()) break;
      }
      if (crit.mixed()) return;
      ++out.kept;
      int orient = envelope_orientation(crit, plane(P[q]));
      if (orient > 0) out.add({{q, f[0]}, {q, f[1]}, {q, f[2]}});
      if (orient < 0) out.add({{q, f[2]}, {q, f[1]}, {q, f[0]}});
    });
  });

  // FV: F_O + (-V_S). Normal n of F_O; volume directions are -(w - p) for S's edges at p.
  for_each_chunked(o.size(), parts, [&](size_t oi, Partial& out) {
    const Triangle& f = mesh.triangles[o[oi]];
    const exact::PlaneSide plane(P[f[0]], P[f[1]], P[f[2]]);
    std::vector<double> q_max(K);
    row({f[0], f[1], f[2]}, true, q_max.data());
    visit_meeting(s_vertex, q_max, out, [&](size_t i) {
      const uint32_t p = ts.vertices()[i];
      CriticalSet crit;
      for (uint32_t w : ts.neighbors(i)) {
        crit.add(plane.along(P[w], P[p]));
        if (crit.mixed()) break;
      }
      if (crit.mixed()) return;
      ++out.kept;
      int orient = envelope_orientation(crit, plane.along(P[p], P[f[0]]));
      if (orient > 0) out.add({{f[0], p}, {f[1], p}, {f[2], p}});
      if (orient < 0) out.add({{f[2], p}, {f[1], p}, {f[0], p}});
    });
  });

  // EE: E_O + (-E_S), a parallelogram with normal n = (q1 - q0) x (p1 - p0); volume
  // directions are the inface directions of E_O in O and of -E_S in -S.
  for_each_chunked(to.edges().size(), parts, [&](size_t ei, Partial& out) {
    const auto& eo = to.edges()[ei];
    const Point3 &q0 = P[eo.a], &q1 = P[eo.b];
    std::vector<double> q_max(K);
    row({eo.a, eo.b}, true, q_max.data());
    visit_meeting(s_edge, q_max, out, [&](size_t j) {
      const auto& es = ts.edges()[j];
      const Point3 &p0 = P[es.a], &p1 = P[es.b];
      const exact::DifferenceDet normal(q0, q1, p0, p1);
      CriticalSet crit;
      for (int k = 0; k < eo.face_count && !crit.mixed(); ++k) crit.add(normal(q0, P[eo.opposite[k]]));
      for (int k = 0; k < es.face_count && !crit.mixed(); ++k) crit.add(normal(P[es.opposite[k]], p0));
      if (crit.mixed()) return;
      // Parallel edges give n = 0: every value, sigma included, is zero and the
      // "parallelogram" is a segment, dropped as tangent below.
      ++out.kept;
      int orient = envelope_orientation(crit, normal(p0, q0));
      // (q0-p0, q1-p0, q1-p1, q0-p1) runs counter-clockwise around -n.
      if (orient < 0) out.add({{eo.a, es.a}, {eo.b, es.a}, {eo.b, es.b}, {eo.a, es.b}});
      if (orient > 0) out.add({{eo.a, es.b}, {eo.b, es.b}, {eo.b, es.a}, {eo.a, es.a}});
    });
  });

  EnvelopeStatistics stats;
  Builder builder(keep_faces);
  for (const Partial& part : parts) {
    stats.tentative_faces += part.tentative;
    stats.kept_faces += part.kept;
    stats.outside_window += part.outside_window;
    for (const Partial::Face& f : part.faces) builder.add_face({f.v.data(), f.n});
  }
  return builder.finish(stats);
}

}  // namespace gvm
