#include "visibility/global_visibility_map.h"

#include <spdlog/spdlog.h>

#include <array>

#include "sphere/arrangement.h"
#include "visibility/occluder_beam.h"

namespace gvm {
namespace {

using exact::ExactVec;
using sphere::Arrangement;
using sphere::ArrangementArc;
using sphere::ArrangementPoint;

constexpr int kLvm = 0;        // layer of LVM(S + N_S): coverage 1 inside its 2-cells
constexpr int kOcclusion = 1;  // layer of the projected envelope: number of faces over u

ExactVec diff(const SolidMesh& mesh, uint32_t q, uint32_t p) {
  return ExactVec::from_point(mesh.points[q]) - ExactVec::from_point(mesh.points[p]);
}

// The cells of the LVM as arrangement input: face boundaries with weight 1 (the face on
// their left), curves with weight 0 (they only mark where the LVM is), points.
void add_lvm(const sphere::SphericalImage& lvm, std::vector<ArrangementArc>& arcs,
             std::vector<ArrangementPoint>& points) {
  auto add_arc = [&](const sphere::Arc& arc, int weight) {
    std::vector<ExactVec> v = sphere::split_arc(arc);
    for (size_t i = 0; i + 1 < v.size(); ++i) {
      arcs.push_back({v[i], v[i + 1], arc.normal, kLvm, weight});
    }
  };
  for (const sphere::Face& f : lvm.faces()) {
    for (const sphere::Loop& loop : f.loops) {
      for (const sphere::Arc& arc : loop.arcs) add_arc(arc, 1);
    }
  }
  for (const sphere::Arc& arc : lvm.curves()) add_arc(arc, 0);
  for (const ExactVec& p : lvm.points()) points.push_back({p, kLvm});
}

// A direction on none of the given great circles and none of the points: the reference at
// which coverage is counted directly. Small integer directions are tried in turn; finitely
// many circles cannot contain them all.
ExactVec generic_direction(const std::vector<ExactVec>& circles,
                           const std::vector<ExactVec>& points) {
  for (int k = 1;; ++k) {
    ExactVec r = ExactVec::from_point({double(2 * k + 1), double(-3 * k - 5), double(7 * k + 2)});
    bool ok = true;
    for (const ExactVec& n : circles) {
      if (exact::sign_dot(r, n) == Sign::kZero) {
        ok = false;
        break;
      }
    }
    for (size_t i = 0; ok && i < points.size(); ++i) ok = !exact::parallel(r, points[i]);
    if (ok) return r;
  }
}

}  // namespace

std::optional<sphere::SphericalImage> global_visibility_map(
    const SolidMesh& mesh, std::span<const uint32_t> s, std::span<const uint32_t> o,
    const sphere::SphericalImage& lvm, GlobalOcclusionStatistics* stats,
    size_t max_border_arcs) {
  if (lvm.is_empty() || o.empty()) return lvm;
  const std::vector<uint32_t> beam = occluders_in_beam(mesh, s, o, lvm);
  if (stats) stats->occluders_in_beam = beam.size();
  if (beam.empty()) return lvm;
  const EffectiveMinkowskiEnvelope eme =
      compute_effective_minkowski_envelope(mesh, s, beam, /*keep_faces=*/true);

  spdlog::debug("global occlusion: |S| {} |O| {} ({} in the beam): {} tentative, {} kept, {} envelope faces, {} "
                "patches, {} border arcs",
                s.size(), o.size(), beam.size(), eme.statistics.tentative_faces, eme.statistics.kept_faces,
                eme.statistics.envelope_faces, eme.statistics.patches,
                eme.statistics.border_edges);
  if (stats) stats->envelope = eme.statistics;
  if (eme.border.size() > max_border_arcs) return std::nullopt;
  std::vector<ArrangementArc> arcs;
  std::vector<ArrangementPoint> points;
  add_lvm(lvm, arcs, points);
  for (const EnvelopeBorderEdge& e : eme.border) {
    ExactVec a = diff(mesh, e.q0, e.p0), b = diff(mesh, e.q1, e.p1);
    arcs.push_back({a, b, exact::cross(a, b), kOcclusion, e.multiplicity});
  }

  // Coverage at a reference direction, counted face by face: a back-facing face projects
  // to the convex polygon to the left of its edges (its vertices run counter-clockwise
  // around the outward normal, seen from outside the sphere).
  std::vector<std::vector<ExactVec>> face_vertices;
  std::vector<ExactVec> circles;
  for (const ArrangementArc& a : arcs) circles.push_back(a.normal);
  for (const EnvelopeFace& f : eme.faces) {
    std::vector<ExactVec> v;
    for (auto [q, p] : f.vertices) v.push_back(diff(mesh, q, p));
    for (size_t i = 0; i < v.size(); ++i) circles.push_back(exact::cross(v[i], v[(i + 1) % v.size()]));
    face_vertices.push_back(std::move(v));
  }
  std::vector<ExactVec> point_dirs;
  for (const auto& p : points) point_dirs.push_back(p.p);
  const ExactVec r = generic_direction(circles, point_dirs);
  int coverage[2] = {0, 0};
  coverage[kLvm] = !lvm.faces().empty() && lvm.contains(r) ? 1 : 0;
  for (const auto& v : face_vertices) {
    bool inside = true;
    for (size_t i = 0; i < v.size() && inside; ++i) {
      inside = exact::sign_det(v[i], v[(i + 1) % v.size()], r) == Sign::kPositive;
    }
    coverage[kOcclusion] += inside;
  }

  Arrangement arr(arcs, points, 2, r, coverage);
  const auto& faces = arr.faces();
  const auto& half = arr.half_edges();
  auto in_lvm_face = [&](uint32_t f) { return faces[f].coverage[kLvm] > 0; };
  auto occluded_face = [&](uint32_t f) { return faces[f].coverage[kOcclusion] > 0; };
  auto face_in = [&](uint32_t f) { return in_lvm_face(f) && !occluded_face(f); };
  // A cell is in Int(GOM) iff every face around it is covered.
  auto edge_in = [&](uint32_t e) {
    uint32_t left = half[2 * e].face, right = half[2 * e + 1].face;
    bool in_lvm = (arr.edges()[e].arc_layers & (1u << kLvm)) || in_lvm_face(left) ||
                  in_lvm_face(right);
    return in_lvm && !(occluded_face(left) && occluded_face(right));
  };
  auto vertex_in = [&](uint32_t v) {
    const auto& vert = arr.vertices()[v];
    bool in_lvm = (vert.point_layers & (1u << kLvm)) != 0;
    bool all_occluded = true;
    for (uint32_t h : vert.out) {
      in_lvm |= (arr.edges()[half[h].edge].arc_layers & (1u << kLvm)) != 0;
      in_lvm |= in_lvm_face(half[h].face);
      all_occluded &= occluded_face(half[h].face);
    }
    if (vert.out.empty()) all_occluded = occluded_face(0);
    return in_lvm && !all_occluded;
  };
  sphere::SphericalImage gvm = arr.extract(face_in, edge_in, vertex_in);
  if (stats) {
    stats->arrangement_vertices = arr.vertices().size();
    stats->arrangement_edges = arr.edges().size();
    stats->arrangement_faces = faces.size();
  }
  return gvm;
}

}  // namespace gvm
