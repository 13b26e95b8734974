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
// face's open inside (a great circle separates them: the arc's own circle, or the circle
// of a side of the face, with the arc's ends beyond it or on it), so that lies wholly
// inside or wholly outside R; and a point inside the face lies strictly inside a face
// already in R. Ends and vertices within the slack of a circle are decided exactly: CAD
// envelopes have many faces along the union's boundary, on its very circles. A face the
// doubles and those signs cannot decide is kept.
//
// The union matters only around the LVM (`needed`), and after each tier the exact set V
// of its directions outside the union's interior is known (sphere::outside_interior): a
// later face that misses V can change the GVM nowhere and is left out too. That a face
// misses V is decided the same way: no boundary arc, curve or point of V meets its open
// inside, and a point inside it lies outside the LVM or strictly inside a face already in
// the union; and the closed face misses V on the LVM's boundary (below).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/region_union.h"
#include "sphere/spherical_image.h"
#include "visibility/clip_window.h"

namespace gvm {

// The first tier holds 1/first_tier_share of the faces (at least min_first_tier), each next
// tier twice the one before. Tiers pay only when later faces lie inside earlier ones: in a
// large union (a second tier of large_tier faces or more) of which fewer than 1/pays_from
// of the second tier lies inside the first, the faces are merged in one union instead, as
// before the tiers. On piattello.stp's face 15 (103,001 faces, none inside another) the
// tiers left nothing out, and the groups of its later tiers grew past 11 GB where the
// groups of all its faces at once stay under 2 GB. Smaller unions keep their tiers: later
// tiers still leave faces out (prusa_y-rod-holder F16: 6% of tier 3, all of tier 5), and
// merging all at once there made the Prusa parts 2-17% slower. The first tier is small
// since faces are also left out when they miss what the tiers so far leave of the LVM,
// and each tier narrows that: 1/64 of the faces and at least 64 against 1/16 and 256 took
// 5% fewer instructions on prusa_extruder-idler's and prusa_y-rod-holder's slowest
// surfaces (large_tier scaled with it, so that the same unions count as large).
//
// From seed_from faces on (with `needed`), the first tier also holds the faces that cover
// what the largest leave of the occluded directions on `needed` (tier_seeds.h), found with
// seed_samples_per_face lattice directions per face. Measured in instructions, one thread
// (prusa_extruder-idler / prusa_y-rod-holder, G): no seeds 26.86 / 25.72; from 4,096 faces
// with 1 sample per face 23.03 / 22.74, with 2 23.42 / 23.78, with 1/2 23.90 / 22.50; from
// 2,048 faces 23.18 / 22.74; from 8,192 faces 23.49 / 28.3 before the largest faces took
// part (every direction of an LVM inside the first tier then asked the whole tree). Only
// up to seed_until faces: the pocket floor of gvm_make_pocket_part (110 k sliver faces
// around a wide LVM, thousands of boxes around each lattice direction) took 8-25 s
// instead of 4.5 with seeds.
struct TierPolicy {
  size_t first_tier_share = 64, min_first_tier = 64;
  size_t large_tier = 1024, pays_from = 8;
  size_t seed_from = 4096, seed_until = 65536, seed_samples_per_face = 1;
};

struct TieredUnionStatistics {
  size_t tiers = 0, faces = 0;
  size_t left_out = 0;     // inside the union of the tiers before theirs, or missing V (below)
  bool one_union = false;  // the tiers did not pay: all faces merged at once
  size_t not_needed = 0;   // faces of later tiers, left out once `needed` lay inside
};

// faces[i]: a projected face, a convex polygon counter-clockwise around its inside, inside
// an open hemisphere. union_of(indices) is the closed union of those faces (labelled from
// `reference`), clipped to `windows` if there are any (occluded_directions.h). Returns the
// same for faces[kept]: union_of(kept) itself when the tiers do not pay (TierPolicy).
//
// With `needed` (the LVM; `reference` then lies on none of its circles and points), the
// result holds only the same interior as the union of all faces on `needed`, which is all
// the GVM reads. Let R be the union of the tiers so far and V = needed - Int(R), a closed
// set. A face F whose open inside misses V, and which misses V on the boundary of `needed`,
// is left out: a direction of needed - V lies in Int(R) either way; at a direction x of V,
// the points F adds near x lie in its open inside (the union is closed and F's sides are
// nowhere dense), so outside V: inside Int(R), or outside `needed`, which near x means x
// is on its boundary, where F does not reach. Once V is empty, R is returned
// and the later tiers are not needed (prusa_y-rod-holder F16, whose GVM is empty: the
// first tier already held the whole LVM).
sphere::Region union_by_tiers(std::span<const std::vector<exact::ExactVec>> faces,
                              std::span<const uint32_t> kept, std::span<const ClipWindow> windows,
                              const std::function<sphere::Region(std::span<const uint32_t>)>& union_of,
                              const exact::ExactVec& reference, TieredUnionStatistics* stats = nullptr,
                              const TierPolicy& policy = {}, const sphere::SphericalImage* needed = nullptr);

}  // namespace gvm
