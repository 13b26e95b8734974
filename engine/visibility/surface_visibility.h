// Visibility maps of one surface S of a part (paper Algorithm 1, steps 2-7): its occluders
// N_S and O_S, LVM(S + N_S), and GVM(S) where it follows without global occlusion.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "gvm/part.h"
#include "sphere/spherical_image.h"
#include "visibility/global_visibility_map.h"

namespace gvm {

enum class GvmKind {
  kExactNoPotentialOccluders,   // O_S empty: GVM = LVM(S + N_S)
  kGlobalOcclusionNotComputed,  // O_S not empty: LVM(S + N_S) only bounds the GVM
  kGlobalOcclusionComputed,     // GVM = LVM(S + N_S) - GOM(S, O_S) by the envelope
  kEmptyVoid,                   // S touches an internal void: never visible
};

struct SurfaceVisibility {
  Occluders occluders;
  sphere::SphericalImage lvm;                 // LVM(S + N_S)
  std::optional<sphere::SphericalImage> gvm;  // set when known exactly
  GvmKind kind = GvmKind::kGlobalOcclusionNotComputed;
  GlobalOcclusionStatistics statistics;
};

// S is a set of triangles of the part (ascending, unique). With `global_occlusion`, the
// occlusion by O_S is computed too, by `method`.
SurfaceVisibility compute_surface_visibility(
    const Part& part, std::span<const uint32_t> s, bool global_occlusion = false,
    OcclusionMethod method = OcclusionMethod::kEffectiveMinkowskiEnvelope);

}  // namespace gvm
