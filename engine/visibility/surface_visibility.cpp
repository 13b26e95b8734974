#include "visibility/surface_visibility.h"

#include "exact/exact_vec.h"
#include "sphere/local_visibility_map.h"

namespace gvm {
namespace {

exact::ExactVec normal_of(const SolidMesh& mesh, uint32_t t) {
  const Triangle& tri = mesh.triangles[t];
  return exact::triangle_normal(mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]);
}

bool touches_void(const SolidMesh& mesh, std::span<const uint32_t> s) {
  for (uint32_t t : s) {
    if (mesh.shell_is_void[mesh.shell[t]]) return true;
  }
  return false;
}

}  // namespace

SurfaceVisibility compute_surface_visibility(const Part& part, std::span<const uint32_t> s,
                                             bool global_occlusion, OcclusionMethod method) {
  const SolidMesh& mesh = part.mesh();
  SurfaceVisibility out;
  out.occluders.neighbor = part.neighbor_occluders(s);

  std::vector<exact::ExactVec> normals;
  normals.reserve(s.size() + out.occluders.neighbor.size());
  for (uint32_t t : s) normals.push_back(normal_of(mesh, t));
  for (uint32_t t : out.occluders.neighbor) normals.push_back(normal_of(mesh, t));
  out.lvm = sphere::local_visibility_map(normals);

  if (touches_void(mesh, s)) {
    // A ray leaving a void face stays in the bounded void until it enters the solid.
    out.status = GvmStatus::kEmptyVoid;
    out.gvm = sphere::SphericalImage::empty();
    return out;
  }
  if (out.lvm.dimension() < 0) {
    out.status = GvmStatus::kExactNoPotentialOccluders;
    out.gvm = out.lvm;
    return out;
  }
  // Condition (3) of Def. 5, from LVM(S + N_S): F' can only block S if some direction of
  // the LVM meets it from the front, i.e. the LVM is not inside F''s closed hemisphere.
  out.occluders.potential = part.potential_occluders(
      s, out.occluders.neighbor,
      [&](uint32_t t) { return !out.lvm.within_closed_hemisphere(normal_of(mesh, t)); });
  if (out.occluders.potential.empty()) {
    out.status = GvmStatus::kExactNoPotentialOccluders;
    out.gvm = out.lvm;
  } else if (global_occlusion) {
    out.gvm = global_visibility_map(mesh, s, out.occluders.potential, out.lvm, method,
                                    &out.statistics);
    out.status = GvmStatus::kGlobalOcclusionComputed;
  } else {
    out.status = GvmStatus::kGlobalOcclusionNotComputed;
  }
  return out;
}

}  // namespace gvm
