// The closure of the occluded directions in two passes -- a first over the nearest
// occluders, a second only near what that leaves of the LVM -- against the convex
// decomposition, which unites the maps of every pair of S and O in one pass. Real thread
// flanks (occt_TR12J_OCC: two triangles, about 9,000 occluders in the beam, a quarter-sphere
// LVM) are where the two passes are taken.
#include <gtest/gtest.h>

#include <string>

#include "gvm/part.h"
#include "support/shared_parts.h"
#include "sphere/set_operations.h"
#include "visibility/surface_visibility.h"

namespace gvm {
namespace {

TEST(OcclusionPasses, TwoPassGvmsAreTheConvexDecompositions) {
  if (!test::has_shared_part("occt_TR12J_OCC.stl")) GTEST_SKIP() << "no occt_TR12J_OCC.stl";
  auto part = test::analyze_shared_part("occt_TR12J_OCC.stl");
  ASSERT_TRUE(part.ok()) << part.status().message();
  int two_pass = 0, visible = 0;
  for (const Feature& f : part->features()) {
    if (f.triangles.size() != 2 || two_pass == 3) continue;
    const SurfaceVisibility eme = compute_surface_visibility(*part, f.triangles, true);
    if (eme.statistics.first_pass_occluders == 0) continue;
    ++two_pass;
    const SurfaceVisibility convex =
        compute_surface_visibility(*part, f.triangles, true, OcclusionMethod::kConvexDecomposition);
    ASSERT_TRUE(eme.gvm && convex.gvm) << f.name;
    EXPECT_TRUE(sphere::is_subset(*eme.gvm, *convex.gvm)) << f.name << ": " << eme.gvm->description();
    EXPECT_TRUE(sphere::is_subset(*convex.gvm, *eme.gvm)) << f.name << ": " << convex.gvm->description();
    visible += !eme.gvm->is_empty();
  }
  EXPECT_EQ(two_pass, 3);
  EXPECT_GT(visible, 0);  // not only empty maps compared
}

}  // namespace
}  // namespace gvm
