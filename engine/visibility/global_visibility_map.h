// GVM(S) = LVM(S + N_S) - GOM(S, O_S) (paper Eq. 6), with GOM(S, O_S) the interior of the
// projection of the effective Minkowski envelope of O_S + (-S) (Eq. 7). The LVM and the
// projected envelope border are overlaid in one exact arrangement; the difference is
// non-regularized: arcs and points of the LVM that no open occlusion covers survive.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "gvm/mesh.h"
#include "sphere/spherical_image.h"
#include "visibility/effective_minkowski_envelope.h"

namespace gvm {

struct GlobalOcclusionStatistics {
  uint64_t occluders_in_beam = 0;     // faces of O_S that can meet S near the LVM
  EnvelopeStatistics envelope;
  uint64_t arrangement_vertices = 0;  // #Arrng in the paper's tables
  uint64_t arrangement_edges = 0;
  uint64_t arrangement_faces = 0;
};

// Nothing when the envelope's border has more than `max_border_arcs` arcs: its
// arrangement would take too long (see the README); the caller keeps the LVM as a bound.
std::optional<sphere::SphericalImage> global_visibility_map(
    const SolidMesh& mesh, std::span<const uint32_t> s, std::span<const uint32_t> o,
    const sphere::SphericalImage& lvm, GlobalOcclusionStatistics* stats = nullptr,
    size_t max_border_arcs = 4000000);

}  // namespace gvm
