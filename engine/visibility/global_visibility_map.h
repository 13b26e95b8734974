// GVM(S) = LVM(S + N_S) - GOM(S, O_S) (paper Eq. 6), with GOM(S, O_S) the interior of the
// projection of the effective Minkowski envelope of O_S + (-S) (Eq. 7). The projected
// envelope's closed region is built by unions of groups of faces (sphere/region_union.h),
// then overlaid with the LVM in one exact arrangement; the difference is non-regularized:
// arcs and points of the LVM that no open occlusion covers survive. Directions of Int(GOM)
// whose rays only graze O_S are visible (Def. 2 of the paper): the occlusion probe
// decides the arcs and points of the LVM in there, and the seams inside its 2-cells
// (seam_candidates.h), so that the GVM is Def. 2 exactly. An LVM without 2-cells (a slot's
// arc, a through hole's axis) needs no closure at all: with the envelope method the probe
// decides all of it.
#pragma once

#include <cstdint>
#include <span>

#include "gvm/mesh.h"
#include "sphere/spherical_image.h"
#include "visibility/convex_decomposition.h"
#include "visibility/effective_minkowski_envelope.h"

namespace gvm {

// How the occluded directions Phi(O_S + (-S)) are produced; the rest (exact arrangement,
// unions, non-regularized difference) is shared, so both give the same GVM.
enum class OcclusionMethod {
  kEffectiveMinkowskiEnvelope,  // paper Sec. 4
  kConvexDecomposition,         // pairwise occlusion maps (paper's reference [18])
};

struct GlobalOcclusionStatistics {
  uint64_t occluders_in_beam = 0;       // faces of O_S that can meet S near the LVM
  uint64_t first_pass_occluders = 0;    // of those, the nearest, when the closure took two passes
  EnvelopeStatistics envelope;           // with the envelope
  ConvexDecompositionStatistics convex;  // with convex decomposition
  uint64_t occluded_boundary_arcs = 0;   // boundary of the closure of Phi(O_S + (-S)), as computed (occlusion_culling.h)
  // #Arrng in the paper's tables: vertices of every arrangement built (the unions and
  // the final overlay with the LVM).
  uint64_t arrangement_vertices = 0;
};

sphere::SphericalImage global_visibility_map(
    const SolidMesh& mesh, std::span<const uint32_t> s, std::span<const uint32_t> o,
    const sphere::SphericalImage& lvm,
    OcclusionMethod method = OcclusionMethod::kEffectiveMinkowskiEnvelope,
    GlobalOcclusionStatistics* stats = nullptr);

}  // namespace gvm
