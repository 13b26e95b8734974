// Visibility maps of one surface S of a part (paper Algorithm 1, steps 2-7): its occluders
// N_S and O_S, LVM(S + N_S), and GVM(S) where it follows without global occlusion.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "gvm/analysis.h"
#include "gvm/part.h"
#include "sphere/spherical_image.h"
#include "visibility/global_visibility_map.h"

namespace gvm {

struct SurfaceVisibility {
  Occluders occluders;
  sphere::SphericalImage lvm;                 // LVM(S + N_S)
  std::optional<sphere::SphericalImage> gvm;  // set when known exactly
  GvmStatus status = GvmStatus::kGlobalOcclusionNotComputed;
  GlobalOcclusionStatistics statistics;
};

// S is a set of triangles of the part (ascending, unique). With `global_occlusion`, the
// occlusion by O_S is computed too, by `method`.
SurfaceVisibility compute_surface_visibility(
    const Part& part, std::span<const uint32_t> s, bool global_occlusion = false,
    OcclusionMethod method = OcclusionMethod::kEffectiveMinkowskiEnvelope);

}  // namespace gvm
