// Where LVM(S + N_S) has no 2-cell (slots, through holes, walls seen only along them), the
// GVM comes from the occlusion probe alone; the convex decomposition still unites every
// pairwise map and asks the probe only inside their interior. Both must give the same set
// on real parts, arcs cut short and isolated points included.
#include <gtest/gtest.h>

#include <cctype>
#include <string>

#include "gvm/part.h"
#include "sphere/set_operations.h"
#include "support/shared_parts.h"
#include "visibility/surface_visibility.h"

namespace gvm {
namespace {

class ProbedLvm : public ::testing::TestWithParam<std::string> {};

TEST_P(ProbedLvm, GvmsAreTheConvexDecompositions) {
  if (!test::has_shared_part(GetParam())) GTEST_SKIP() << "no " << GetParam();
  auto part = test::analyze_shared_part(GetParam());
  ASSERT_TRUE(part.ok()) << part.status().message();
  int compared = 0, cut_short = 0;
  for (const Feature& f : part->features()) {
    const SurfaceVisibility local = compute_surface_visibility(*part, f.triangles);
    if (local.lvm.dimension() > 1 || local.occluders.potential.empty()) continue;
    const SurfaceVisibility eme = compute_surface_visibility(*part, f.triangles, true);
    const SurfaceVisibility convex =
        compute_surface_visibility(*part, f.triangles, true, OcclusionMethod::kConvexDecomposition);
    ASSERT_TRUE(eme.gvm && convex.gvm) << f.name;
    EXPECT_TRUE(sphere::is_subset(*eme.gvm, *convex.gvm)) << f.name << ": " << eme.gvm->description();
    EXPECT_TRUE(sphere::is_subset(*convex.gvm, *eme.gvm)) << f.name << ": " << convex.gvm->description();
    ++compared;
    // Neither empty nor the whole LVM: the probe had pieces to find.
    cut_short += !eme.gvm->is_empty() && !sphere::is_subset(eme.lvm, *eme.gvm);
  }
  EXPECT_GE(compared, 10);
  EXPECT_GE(cut_short, 3);
}

INSTANTIATE_TEST_SUITE_P(SharedParts, ProbedLvm,
                         ::testing::Values("prusa_y-motor-holder.stl", "trimesh_ADIS16480.STL"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param.substr(0, info.param.find('.'));
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

}  // namespace
}  // namespace gvm
