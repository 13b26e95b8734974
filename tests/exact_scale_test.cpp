// Scaling a part by 2^k changes no exact predicate and no direction, so every map must be
// identical, cell for cell: on the degenerate test parts and the shared parts, scaled by
// 2^-120, 2^-60, 2^60 and 2^120 (exact in doubles), against the part as it is. The
// shared parts up to ~10k faces whose analysis takes minutes run in the `long` preset
// (DISABLED_ here, run there with --gtest_also_run_disabled_tests).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "exact/dyadic.h"
#include "exact/exact_vec.h"
#include "gvm/analysis.h"
#include "support/mesh_files.h"
#include "support/scratch_dir.h"
#include "support/test_parts.h"

namespace gvm {
namespace {

constexpr int kExponents[] = {-120, -60, 60, 120};

RawMesh scaled(RawMesh raw, int k) {
  for (Point3& p : raw.points) {
    const Point3 q = {std::ldexp(p.x, k), std::ldexp(p.y, k), std::ldexp(p.z, k)};
    EXPECT_EQ((Point3{std::ldexp(q.x, -k), std::ldexp(q.y, -k), std::ldexp(q.z, -k)}), p) << "2^" << k << " not exact";
    p = q;
  }
  return raw;
}

Analysis analyzed(const RawMesh& raw, const std::string& name) {
  AnalyzeRequest request;
  request.part_path = test::write_off(raw, test::scratch_dir() / (name + ".off"));
  request.options.set_threads(2);
  auto analysis = analyze(request);
  EXPECT_TRUE(analysis.ok()) << name << ": " << analysis.status().message();
  return std::move(*analysis);
}

void expect_same_surfaces(const std::vector<Surface>& a, const std::vector<Surface>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t i = 0; i < a.size(); ++i) {
    const std::string where = what + " " + a[i].name + " #" + std::to_string(i);
    ASSERT_EQ(a[i].faces, b[i].faces) << where;
    EXPECT_EQ(a[i].maps.status, b[i].maps.status) << where;
    EXPECT_TRUE(a[i].maps.lvm == b[i].maps.lvm) << where << ": LVM " << a[i].maps.lvm.description() << " against "
                                                << b[i].maps.lvm.description();
    ASSERT_EQ(a[i].maps.gvm.has_value(), b[i].maps.gvm.has_value()) << where;
    if (a[i].maps.gvm) {
      EXPECT_TRUE(*a[i].maps.gvm == *b[i].maps.gvm)
          << where << ": GVM " << a[i].maps.gvm->description() << " against " << b[i].maps.gvm->description();
      EXPECT_TRUE(b[i].maps.gvm->is_subset_of(b[i].maps.lvm)) << where << ": a GVM outside its LVM";
    }
  }
}

// The maps of `raw` scaled by every exponent equal those of `raw`, and the part as drawn
// and summarized is the scaled one, at its own scale.
void expect_scale_invariant(const RawMesh& raw, const std::string& name) {
  const Analysis base = analyzed(raw, name);
  for (int k : kExponents) {
    const std::string what = name + " * 2^" + std::to_string(k);
    const RawMesh big = scaled(raw, k);
    const Analysis other = analyzed(big, name + "_" + std::to_string(k));
    expect_same_surfaces(base.regions(), other.regions(), what + " region");
    expect_same_surfaces(base.features(), other.features(), what + " feature");
    EXPECT_EQ(other.part().box_max.x, std::ldexp(base.part().box_max.x, k)) << what;
    EXPECT_EQ(other.mesh().points.front().x, std::ldexp(base.mesh().points.front().x, k)) << what;
  }
}

// The machined block on its own: its five analyses take half an hour under ASan, where the
// small parts already run every scaled code path.
TEST(ExactScale, DegenerateTestParts) {
  for (const test::NamedTestPart& p : test::all_test_parts())
    if (p.name != "machined_block") expect_scale_invariant(p.make({}), p.name);
}

TEST(ExactScale, MachinedBlock) {
  const auto parts = test::all_test_parts();
  const auto block = std::find_if(parts.begin(), parts.end(), [](const auto& p) { return p.name == "machined_block"; });
  ASSERT_NE(block, parts.end());
  expect_scale_invariant(block->make({}), block->name);
}

class ScaledSharedPart : public ::testing::TestWithParam<const char*> {};

TEST_P(ScaledSharedPart, ScaledByPowersOfTwo) {
  auto raw = read_raw_mesh(std::string(GVM_SHARED_DIR) + "/data/parts/" + GetParam());
  ASSERT_TRUE(raw.ok()) << raw.status().message();
  std::string name = GetParam();
  expect_scale_invariant(*raw, name.substr(0, name.find('.')));
}

// Analysed in a few seconds each, together about a minute with their 4 scalings.
INSTANTIATE_TEST_SUITE_P(ExactScale, ScaledSharedPart,
                         ::testing::Values("trimesh_7_8ths_cube.stl", "prusa_plug-aligner.stl",
                                           "trimesh_20mm-xyz-cube.stl", "prusa_endstop-block.stl",
                                           "occt_shape.stl", "occt_brep_mal_tige.off", "trimesh_round.stl",
                                           "trimesh_plate_holes.STL", "occt_sh1.stl", "trimesh_1002_tray_bottom.STL",
                                           "occt_brep_Pump_Nut.off", "prusa_y-motor-holder.stl"));

// The rest of the shared parts up to ~10k faces (minutes each with the scalings).
INSTANTIATE_TEST_SUITE_P(DISABLED_ExactScaleLong, ScaledSharedPart,
                         ::testing::Values("trimesh_featuretype_from_step.off", "prusa_rpi-zero-frame.stl",
                                           "trimesh_ADIS16480.STL", "prusa_x-end-idler.stl",
                                           "prusa_x-end-motor.stl", "prusa_extruder-idler.stl",
                                           "prusa_y-rod-holder.stl"));

// The doubles the filters and the arrangement's boxes rely on stay certified far outside
// a part's own range: unit estimates and units of vectors whose coordinates over- or
// underflow when squared.
TEST(ExactScale, UnitEstimatesHoldAtAnyMagnitude) {
  for (int k : {-1000, -600, -520, -300, 0, 300, 500, 600, 1000}) {
    const double s = std::ldexp(1.0, k);
    const auto v = exact::ExactVec::from_point({3 * s, -4 * s, 12 * s});
    const std::array<double, 3> expect = {3.0 / 13, -4.0 / 13, 12.0 / 13};
    const auto u = v.unit();
    const auto e = exact::unit_estimate(v);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(u[i], expect[i], 1e-15) << "2^" << k;
      EXPECT_LE(std::fabs(e.unit[i] - expect[i]), e.radius + 1e-16) << "2^" << k;
    }
    EXPECT_LT(e.radius, 1e-12) << "2^" << k;
    // A degree-4 construction (a cross product of cross products) far beyond the range.
    const auto a = exact::cross(exact::cross(v, exact::ExactVec::from_point({s, 0, 0})),
                                exact::cross(v, exact::ExactVec::from_point({0, s, 0})));
    const auto w = a.unit();
    EXPECT_NEAR(w[0] * w[0] + w[1] * w[1] + w[2] * w[2], 1, 1e-15) << "2^" << k;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(w[i], expect[i], 1e-15) << "2^" << k;  // a is a multiple of v
  }
}

}  // namespace
}  // namespace gvm
