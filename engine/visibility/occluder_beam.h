// Which potential occluders can matter for the global occlusion of S at all.
//
// GVM(S) = L - Int(Q) with L = LVM(S + N_S) and Q the directions of segments from S to
// O_S. Whether u in L lies in Int(Q) depends only on Q near u, so a face F' whose
// segments from S all point farther than some margin > 0 from L can be left out without
// changing the GVM (for any margin). This keeps the faces whose segment directions may
// come within a small margin of L, decided with certified floating-point bounds that only
// ever keep a face in doubt.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "gvm/mesh.h"
#include "sphere/spherical_image.h"

namespace gvm {

std::vector<uint32_t> occluders_in_beam(const SolidMesh& mesh, std::span<const uint32_t> s,
                                        std::span<const uint32_t> o,
                                        const sphere::SphericalImage& lvm);

}  // namespace gvm
