// Queries on a finished analysis: accessors, and the maps and blockers of any set of
// faces, computed on demand from the part it owns (its pieces: pieces.cpp).
#include <algorithm>
#include <chrono>
#include <numeric>

#include "analysis/analysis_impl.h"
#include "exact/exact_vec.h"
#include "exact/predicates.h"
#include "parallel/interrupt.h"
#include "sphere/local_visibility_map.h"
#include "visibility/occlusion_probe.h"

namespace gvm {
namespace analysis_internal {

OcclusionMethod method_of(const v1::AnalyzeOptions& options) {
  return options.occlusion_method() == v1::OCCLUSION_METHOD_CONVEX_DECOMPOSITION
             ? OcclusionMethod::kConvexDecomposition
             : OcclusionMethod::kEffectiveMinkowskiEnvelope;
}

std::vector<uint32_t> input_faces(const SolidMesh& mesh, std::span<const uint32_t> triangles) {
  std::vector<uint32_t> faces;
  faces.reserve(triangles.size());
  for (uint32_t t : triangles) faces.push_back(mesh.triangle_face[t]);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

SurfaceMaps surface_maps(const SolidMesh& mesh, SurfaceVisibility vis, double seconds) {
  SurfaceMaps out;
  out.lvm = DirectionSet(std::make_shared<const sphere::SphericalImage>(std::move(vis.lvm)));
  if (vis.gvm) {
    out.gvm = DirectionSet(std::make_shared<const sphere::SphericalImage>(std::move(*vis.gvm)));
  }
  out.status = vis.status;
  SurfaceStatistics& s = out.statistics;
  s.neighbor_occluders = static_cast<uint32_t>(input_faces(mesh, vis.occluders.neighbor).size());
  s.potential_occluders = static_cast<uint32_t>(input_faces(mesh, vis.occluders.potential).size());
  const GlobalOcclusionStatistics& g = vis.statistics;
  s.envelope_ran = g.envelope.tentative_faces > 0;
  s.pairwise_ran = g.convex.pairs > 0;
  s.envelope_border_arcs = g.envelope.border_edges;
  s.envelope_faces = g.envelope.envelope_faces;
  s.envelope_patches = g.envelope.patches;
  s.first_pass_occluders = g.first_pass_occluders;
  s.pairwise_maps = g.convex.maps;
  s.pairwise_map_arcs = g.convex.map_arcs;
  s.arrangement_vertices = g.arrangement_vertices;
  s.occluded_boundary_arcs = g.occluded_boundary_arcs;
  s.seconds = seconds;
  return out;
}

exact::ExactVec normal_of(const SolidMesh& mesh, uint32_t t) {
  const Triangle& tri = mesh.triangles[t];
  return exact::triangle_normal(mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]);
}

// Triangles a and b lie in one plane with one orientation.
bool coplanar_alike(const SolidMesh& mesh, uint32_t a, uint32_t b) {
  const Triangle& ta = mesh.triangles[a];
  for (uint32_t v : mesh.triangles[b]) {
    if (exact::orient3d(mesh.points[ta[0]], mesh.points[ta[1]], mesh.points[ta[2]], mesh.points[v]) !=
        Sign::kZero) {
      return false;
    }
  }
  return exact::sign_dot(normal_of(mesh, a), normal_of(mesh, b)) == Sign::kPositive;
}

std::optional<Direction> common_plane_normal(const SolidMesh& mesh,
                                             std::span<const uint32_t> triangles) {
  if (triangles.empty()) return std::nullopt;
  for (uint32_t t : triangles) {
    if (!coplanar_alike(mesh, triangles.front(), t)) return std::nullopt;
  }
  return Direction(std::make_shared<const exact::ExactVec>(normal_of(mesh, triangles.front())));
}

// Triangles of the given input faces, or the first face that is not in the part.
StatusOr<std::vector<uint32_t>> triangles_of(const SolidMesh& mesh, std::span<const uint32_t> faces) {
  std::vector<char> wanted(mesh.input_face_count, 0);
  for (uint32_t f : faces) {
    if (f >= mesh.input_face_count) {
      return InvalidArgument("face " + std::to_string(f) + " does not exist (the part has " +
                             std::to_string(mesh.input_face_count) + " faces)");
    }
    wanted[f] = 1;
  }
  std::vector<uint32_t> out;
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (wanted[mesh.triangle_face[t]]) out.push_back(t);
  }
  return out;
}

}  // namespace analysis_internal

using namespace analysis_internal;

Analysis::Analysis(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

const PartSummary& Analysis::part() const { return impl_->summary; }
const SolidMesh& Analysis::mesh() const { return impl_->input_mesh; }
const std::vector<Surface>& Analysis::regions() const { return impl_->regions; }
const std::vector<Surface>& Analysis::features() const { return impl_->features; }
const AnalysisTiming& Analysis::timing() const { return impl_->timing; }
const v1::AnalyzeOptions& Analysis::options() const { return impl_->options; }
uint32_t Analysis::surfaces_with_potential_occluders() const {
  return impl_->surfaces_with_potential_occluders;
}

StatusOr<Surface> Analysis::surface_of(std::span<const uint32_t> faces) const {
  const SolidMesh& mesh = impl_->part.mesh();
  auto tris = triangles_of(mesh, faces);
  if (!tris.ok()) return tris.status();
  if (tris->empty()) return InvalidArgument("no faces given");
  const auto t0 = std::chrono::steady_clock::now();
  std::optional<SurfaceVisibility> computed;
  try {
    computed.emplace(compute_surface_visibility(impl_->part, *tris, !impl_->options.lvm_only(),
                                                method_of(impl_->options)));
  } catch (const Interrupted&) {
    return Status(StatusCode::kCancelled, "surface maps cancelled");
  }
  SurfaceVisibility& vis = *computed;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Surface out;
  out.faces = input_faces(mesh, *tris);
  out.planar_normal = common_plane_normal(mesh, *tris);
  out.maps = surface_maps(mesh, std::move(vis), seconds);
  return out;
}

std::vector<uint32_t> Analysis::blocking_faces(std::span<const uint32_t> faces,
                                               const Direction& u) const {
  const SolidMesh& mesh = impl_->part.mesh();
  auto tris = triangles_of(mesh, faces);
  if (!tris.ok() || tris->empty()) return {};
  try {
    // Only faces of O_S can block a direction of LVM(S + N_S) (Def. 5).
    const SurfaceVisibility vis = compute_surface_visibility(impl_->part, *tris, false);
    if (vis.occluders.potential.empty()) return {};
    const OcclusionProbe probe(mesh, *tris, vis.occluders.potential);
    std::vector<uint32_t> blockers = probe.blockers(u.exact());
    interruption_point();
    return input_faces(mesh, blockers);
  } catch (const Interrupted&) {
    return {};
  }
}

StatusOr<DirectionSet> Analysis::own_lvm(std::span<const uint32_t> faces) const {
  const SolidMesh& mesh = impl_->part.mesh();
  auto tris = triangles_of(mesh, faces);
  if (!tris.ok()) return tris.status();
  std::vector<exact::ExactVec> normals;
  for (uint32_t t : *tris) normals.push_back(normal_of(mesh, t));
  return DirectionSet(std::make_shared<const sphere::SphericalImage>(sphere::local_visibility_map(normals)));
}

std::vector<uint32_t> Analysis::neighbor_faces(std::span<const uint32_t> faces) const {
  const SolidMesh& mesh = impl_->part.mesh();
  auto tris = triangles_of(mesh, faces);
  if (!tris.ok() || tris->empty()) return {};
  return input_faces(mesh, impl_->part.neighbor_occluders(*tris));
}

}  // namespace gvm
