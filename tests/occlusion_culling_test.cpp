// The union built tier by tier, faces inside the earlier tiers left out, against
// brute-force membership in all the faces.
#include "visibility/occlusion_culling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numeric>
#include <random>
#include <vector>

#include "support/spherical_polygons.h"

namespace gvm {
namespace {

using namespace sphere;
using namespace sphere::test_polygons;

// Many triangles overlapping deeply: most small ones inside the union of the larger ones
// but inside none of them alone, some across its boundary.
std::vector<Polygon> overlapping_triangles(uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> centre(-5, 5), size(0.2, 1.2);
  std::vector<Polygon> faces;
  for (int i = 0; i < 150; ++i) faces.push_back(triangle_around(rng, centre(rng), centre(rng), 2.5, 0.5));
  for (int i = 0; i < 1500; ++i) faces.push_back(triangle_around(rng, 1.3 * centre(rng), 1.3 * centre(rng), size(rng), 0.5));
  return faces;
}

// The closed union of some of the faces, in groups merged up a tree, as occluded_directions
// builds it (without windows).
Region union_of(const std::vector<Polygon>& faces, std::span<const uint32_t> subset, const ExactVec& r) {
  std::vector<Region> groups;
  for (size_t g = 0; g < subset.size(); g += 64) {
    std::vector<Polygon> members;
    for (size_t k = g; k < std::min(subset.size(), g + 64); ++k) members.push_back(faces[subset[k]]);
    groups.push_back(positive_region(arcs_of(members), r, covering(members, r)));
  }
  return region_union(std::move(groups), r);
}

// The region against brute-force membership in the faces at sample directions away from
// every circle (and, when given, only those `considered`): counts of the directions
// checked inside and outside.
struct Checked {
  int inside = 0, outside = 0;
};

void check_against_faces(const std::vector<Polygon>& faces, const std::vector<DArc>& circles,
                         const Region& region, const D3& r, uint64_t seed, Checked& checked,
                         const std::function<bool(const D3&)>& considered = {}) {
  const std::vector<DArc> boundary = to_doubles(region.boundary);
  for (const D3& u : samples(seed, 3000)) {
    if ((considered && !considered(u)) || near_a_circle(circles, u)) continue;
    const std::optional<int> w = winding(boundary, r, u, region.contains_reference ? 1 : 0);
    if (!w) continue;
    const bool expected = covering(faces, v(u)) > 0;
    ASSERT_EQ(*w > 0, expected) << "at " << u[0] << " " << u[1] << " " << u[2];
    (expected ? checked.inside : checked.outside)++;
  }
}

TEST(OcclusionCulling, TheUnionByTiersIsTheUnionOfAllFaces) {
  const std::vector<Polygon> faces = overlapping_triangles(21);
  std::vector<uint32_t> all(faces.size());
  std::iota(all.begin(), all.end(), 0);
  const D3 r = unit_d({-3, 5, -17});
  TieredUnionStatistics stats;
  const Region region = union_by_tiers(
      faces, all, {}, [&](std::span<const uint32_t> subset) { return union_of(faces, subset, v(r)); }, v(r), &stats);
  EXPECT_EQ(stats.faces, faces.size());
  EXPECT_GT(stats.tiers, 2u);
  EXPECT_FALSE(stats.one_union);
  EXPECT_GT(stats.left_out, 300u) << "the test no longer leaves faces out";

  Checked checked;
  check_against_faces(faces, to_doubles(arcs_of(faces)), region, r, 5, checked);
  EXPECT_GT(checked.inside, 500);
  EXPECT_GT(checked.outside, 500);
}

TEST(OcclusionCulling, TiersStopOnceTheNeededSetLiesInsideAndNotBefore) {
  std::vector<Polygon> faces = overlapping_triangles(21);
  faces.push_back({v(-6, -6, 8), v(6, -6, 8), v(0, 8, 8)});  // the largest: in the first tier
  std::vector<uint32_t> all(faces.size());
  std::iota(all.begin(), all.end(), 0);
  const D3 r = unit_d({-3, 5, -17});
  auto unite = [&](std::span<const uint32_t> subset) { return union_of(faces, subset, v(r)); };
  // Inside the largest triangle: the later tiers are not needed, and around the needed
  // square the union is still right.
  const SphericalImage middle = image_of(square(-0.5, -0.5, 0.5, 0.5));
  ASSERT_GT(covering(faces, v(0, 0, 1)), 0);
  TieredUnionStatistics stats;
  const Region region = union_by_tiers(faces, all, {}, unite, v(r), &stats, {}, &middle);
  EXPECT_GT(stats.not_needed, 500u);
  Checked checked;
  check_against_faces(faces, to_doubles(arcs_of(faces)), region, r, 5, checked, [](const D3& u) {
    return u[2] > 0 && std::fabs(8 * u[0] / u[2]) < 1.5 && std::fabs(8 * u[1] / u[2]) < 1.5;
  });
  EXPECT_GT(checked.inside, 20);
  // A square across the edge of the union, one away from it, or the hemisphere around
  // the union's middle never lies inside.
  for (const SphericalImage& needed : {image_of(square(5, 5, 9, 9)), image_of(square(20, 20, 21, 21)),
                                       SphericalImage::hemisphere(v(0, 0, 1))}) {
    union_by_tiers(faces, all, {}, unite, v(r), &stats, {}, &needed);
    EXPECT_EQ(stats.not_needed, 0u);
    EXPECT_GT(stats.tiers, 2u);
  }
}

TEST(OcclusionCulling, FacesThatMissWhatTheUnionLeavesOfTheNeededSetAreLeftOut) {
  // A square across the edge of the union: after each tier only the faces that may meet
  // its part outside the union's interior are kept, and the union is still right on it.
  const std::vector<Polygon> faces = overlapping_triangles(21);
  std::vector<uint32_t> all(faces.size());
  std::iota(all.begin(), all.end(), 0);
  const D3 r = unit_d({-3, 5, -17});
  auto unite = [&](std::span<const uint32_t> subset) { return union_of(faces, subset, v(r)); };
  TieredUnionStatistics whole, around;
  union_by_tiers(faces, all, {}, unite, v(r), &whole);
  const SphericalImage needed = image_of(square(5, 5, 9, 9));
  const Region region = union_by_tiers(faces, all, {}, unite, v(r), &around, {}, &needed);
  EXPECT_EQ(around.not_needed, 0u);
  EXPECT_GT(around.left_out, whole.left_out + 500) << "the test no longer leaves faces out of reach";
  Checked checked;
  check_against_faces(faces, to_doubles(arcs_of(faces)), region, r, 9, checked, [](const D3& u) {
    return u[2] > 0 && 8 * u[0] / u[2] > 5 && 8 * u[0] / u[2] < 9 && 8 * u[1] / u[2] > 5 && 8 * u[1] / u[2] < 9;
  });
  EXPECT_GT(checked.inside, 20);
  EXPECT_GT(checked.outside, 20);
}

TEST(OcclusionCulling, FacesThatDoNotLieInsideOthersAreMergedInOneUnion) {
  // Small triangles scattered far apart: the second tier finds nothing inside the first.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> centre(-6, 6);
  std::vector<Polygon> faces;
  for (int i = 0; i < 1200; ++i) faces.push_back(triangle_around(rng, centre(rng), centre(rng), 0.05, 0.5));
  std::vector<uint32_t> all(faces.size());
  std::iota(all.begin(), all.end(), 0);
  const D3 r = unit_d({-3, 5, -17});
  std::vector<size_t> calls;
  auto union_counted = [&](std::span<const uint32_t> subset) {
    calls.push_back(subset.size());
    return union_of(faces, subset, v(r));
  };
  TieredUnionStatistics stats;
  // Kept in tiers while the union is small (the default policy: a second tier of 1,024
  // faces or more), merged at once when it counts as large.
  union_by_tiers(faces, all, {}, union_counted, v(r), &stats);
  EXPECT_FALSE(stats.one_union);
  EXPECT_GT(calls.size(), 2u);
  calls.clear();
  const Region region = union_by_tiers(faces, all, {}, union_counted, v(r), &stats, {.large_tier = 128});
  EXPECT_TRUE(stats.one_union);
  EXPECT_EQ(stats.left_out, 0u);
  ASSERT_EQ(calls.size(), 2u);  // the first tier, then all faces at once
  EXPECT_EQ(calls.back(), faces.size());

  Checked checked;
  check_against_faces(faces, to_doubles(arcs_of(faces)), region, r, 7, checked);
  EXPECT_GT(checked.inside + checked.outside, 1000);
  EXPECT_GT(checked.inside, 0);
}

TEST(OcclusionCulling, ClippedToWindowsTheUnionIsRightInsideThem) {
  // A hemisphere around a tilted axis: four windows, the union clipped to each.
  const std::vector<Polygon> faces = overlapping_triangles(8);
  const D3 axis = unit_d({0.3, -0.2, 1});
  const std::vector<ClipWindow> windows = ClipWindow::covering(SphericalImage::hemisphere(v(axis)));
  ASSERT_EQ(windows.size(), 4u);
  const D3 r = unit_d({-3, 5, -17});
  auto clipped_union = [&](std::span<const uint32_t> subset) {
    std::vector<Region> parts;
    for (const ClipWindow& w : windows) {
      std::vector<Polygon> members;
      for (uint32_t i : subset) members.push_back(faces[i]);
      std::optional<std::vector<ArrangementArc>> arcs = w.clip(arcs_of(members), covering(members, w.corner(0)));
      if (!arcs) return union_of(faces, subset, v(r));  // degenerate: unclipped
      parts.push_back(positive_region(*arcs, v(r), w.contains_strictly(v(r)) ? covering(members, v(r)) : 0));
    }
    return region_union(std::move(parts), v(r));
  };
  std::vector<uint32_t> all(faces.size());
  std::iota(all.begin(), all.end(), 0);
  TieredUnionStatistics stats;
  const Region region = union_by_tiers(faces, all, windows, clipped_union, v(r), &stats);
  EXPECT_GT(stats.left_out, 300u);

  std::vector<DArc> circles = to_doubles(arcs_of(faces));
  for (const ClipWindow& w : windows) {
    for (const ExactVec& n : w.normals()) circles.push_back({{}, {}, unit_d(n.unit())});
  }
  Checked checked;  // only the hemisphere matters
  check_against_faces(faces, circles, region, r, 6, checked, [&](const D3& u) { return dot_d(u, axis) >= 0; });
  EXPECT_GT(checked.inside + checked.outside, 1000);
}

TEST(OcclusionCulling, FacesAlongTheBoundaryOfWhatIsLeftAreLeftOutButNotAtTheRim) {
  // Needed: the square [-2, 2]^2; the first tier, the largest face A = [-4, 0] x [-2, 2],
  // leaves V = [0, 2] x [-2, 2]. Faces whose open insides miss V but which share V's side
  // x = 0 (CAD envelopes run along the union's boundary on the same circles) change the
  // union's interior nowhere on the square: the small squares inside A along x = 0, and F,
  // which sticks out of A on the left, outside the square. G touches V only on the
  // square's own side x = 2, where with K inside the square it makes that side interior:
  // it must be kept.
  const Polygon a = square(-4, -2, 0, 2), f = square(-5, -1, 0, 1), g = square(2, -1, 3, 1), k = square(1.5, -1, 2, 1);
  std::vector<Polygon> faces = {a, f, g, k};
  for (int j = -8; j < 8; ++j) faces.push_back(square(-0.5, j / 4.0, 0, (j + 1) / 4.0));
  std::vector<uint32_t> all(faces.size());
  std::iota(all.begin(), all.end(), 0);
  const D3 r = unit_d({-3, 5, -17});
  auto unite = [&](std::span<const uint32_t> subset) { return union_of(faces, subset, v(r)); };
  const SphericalImage needed = image_of(square(-2, -2, 2, 2));
  TieredUnionStatistics stats;
  const TierPolicy one_face_first{.first_tier_share = 1 << 20, .min_first_tier = 1};
  const Region region = union_by_tiers(faces, all, {}, unite, v(r), &stats, one_face_first, &needed);
  EXPECT_GT(stats.tiers, 2u);
  EXPECT_EQ(stats.left_out, 17u);  // F and the 16 squares along x = 0

  Checked checked;
  check_against_faces(faces, to_doubles(arcs_of(faces)), region, r, 4, checked, [](const D3& u) {
    return u[2] > 0 && std::fabs(8 * u[0] / u[2]) < 2 && std::fabs(8 * u[1] / u[2]) < 2;
  });
  EXPECT_GT(checked.inside, 20);
  EXPECT_GT(checked.outside, 20);
  // The square's side x = 2 between K and G lies inside the union.
  SphericalImage side;
  side.add_curve({v(2, -0.5, 8), v(2, 0.5, 8), cross(v(2, -0.5, 8), v(2, 0.5, 8))});
  EXPECT_TRUE(outside_interior(side, region, v(r)).is_empty());
}

}  // namespace
}  // namespace gvm
