// The union of many envelope faces built tier by tier, largest faces first, each tier
// without the faces that already lie inside the union of the tiers before it.
//
// After redundant_faces.h, the faces left still overlap deeply: on occt_TR12J_OCC F234,
// 97% of the 60,964 faces lie inside the closure of the occluded directions, which has
// 1,504 boundary arcs, while their groups' arrangements hold 1.4 M vertices. The exact
// union R of the largest faces is most of that closure; a face of a later tier that lies
// inside R changes nothing and is left out.
//
// "Inside R" is decided conservatively, in double precision with a slack far above the
// rounding of the estimates (as redundant_faces.h decides): no boundary arc of R meets the
// face (a great circle separates them: the arc's own circle, or the circle of a side of
// the face, with the arc's ends beyond it), so the face lies wholly inside or wholly
// outside R; and a point inside the face lies strictly inside a face already in R. A face
// the doubles cannot decide is kept.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/region_union.h"
#include "visibility/clip_window.h"

namespace gvm {

struct TieredUnionStatistics {
  size_t tiers = 0, faces = 0, left_out = 0;
};

// faces[i]: a projected face, a convex polygon counter-clockwise around its inside, inside
// an open hemisphere. union_of(indices) is the closed union of those faces (labelled from
// `reference`), clipped to `windows` if there are any (occluded_directions.h). Returns the
// same for faces[kept].
sphere::Region union_by_tiers(std::span<const std::vector<exact::ExactVec>> faces,
                              std::span<const uint32_t> kept, std::span<const ClipWindow> windows,
                              const std::function<sphere::Region(std::span<const uint32_t>)>& union_of,
                              const exact::ExactVec& reference, TieredUnionStatistics* stats = nullptr);

}  // namespace gvm
