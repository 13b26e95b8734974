// Faces for the first tier of the occlusion culling beside the largest ones: faces that
// cover what the largest leave of the occluded directions on the LVM.
//
// The tiers (occlusion_culling.h) leave a face out once it lies inside the union so far or
// misses what that leaves of the LVM (V). Taken by size alone, the first tier covers a part
// of the occluded directions only (prusa_extruder-idler F68: its 265 largest faces leave
// 1.264 of the LVM's 1.37 sr, the GVM being 1.155 sr), and each later tier meets V in
// hundreds of faces whose unions the next tiers carry along (5,231 faces in unions, group
// arrangements of 81 k vertices). A lattice of directions over the LVM shows where the
// occluded directions are that the largest faces do not cover; the largest face holding
// each such direction joins the first tier, after which V is close to the GVM and most
// later faces miss it (F68: 455 faces in the first tier leave 1.158 sr; 2,300 faces in
// unions, 31 k group vertices). The seeds only order the faces: any order gives the same
// union, and a wrong guess (a face the doubles place wrongly) costs time only.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sphere/spherical_image.h"
#include "visibility/face_estimate.h"

namespace gvm {

// Of faces[rest], the largest holding each of about `samples` lattice directions inside
// `needed` that some face of faces[rest] certainly holds and no face of faces[largest]
// does, without repeats, ascending.
std::vector<uint32_t> tier_seeds(std::span<const FaceEstimate> faces, std::span<const uint32_t> largest,
                                 std::span<const uint32_t> rest, const sphere::SphericalImage& needed,
                                 size_t samples);

}  // namespace gvm
