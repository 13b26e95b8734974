// Exact GVMs of the degenerate machining features users care most about, by the
// envelope; the convex-decomposition baseline must give the same GVM for each of them.
#include <gtest/gtest.h>

#include "exact/exact_vec.h"
#include "gvm/part.h"
#include "support/test_parts.h"
#include "visibility/surface_visibility.h"

namespace gvm {
namespace {

using exact::ExactVec;

struct Built {
  RawMesh raw;
  Part part;
};

Built build(RawMesh raw) {
  auto solid = build_solid(raw);
  EXPECT_TRUE(solid.ok()) << solid.status().message();
  auto part = Part::analyze(std::move(*solid), PartOptions{});
  EXPECT_TRUE(part.ok());
  return {std::move(raw), std::move(*part)};
}

// The visibility of S by the envelope, after checking that convex decomposition gives
// the same GVM, cell for cell.
SurfaceVisibility visibility(const Part& part, std::span<const uint32_t> s) {
  SurfaceVisibility eme = compute_surface_visibility(part, s, true);
  SurfaceVisibility convex =
      compute_surface_visibility(part, s, true, OcclusionMethod::kConvexDecomposition);
  EXPECT_EQ(eme.gvm.has_value(), convex.gvm.has_value());
  if (eme.gvm && convex.gvm) {
    EXPECT_TRUE(*eme.gvm == *convex.gvm)
        << "envelope: " << eme.gvm->description() << "\nconvex:   " << convex.gvm->description();
  }
  return eme;
}

// The rotation the test parts apply, for expected directions.
ExactVec rotated(const test::TestPartOptions& o, double x, double y, double z) {
  return ExactVec::from_point(test::rotated(o, {x, y, z}));
}

class Variants : public ::testing::TestWithParam<test::TestPartOptions> {};

TEST_P(Variants, PocketWallSeesAnArcUpToTheOppositeRim) {
  const auto o = GetParam();
  Built b = build(test::pocket_part(o));
  auto s = test::triangles_of(b.part.mesh(), b.raw, {"wall_x0"});
  SurfaceVisibility vis = visibility(b.part, s);
  ASSERT_TRUE(vis.gvm.has_value());
  const sphere::SphericalImage& g = *vis.gvm;
  EXPECT_EQ(g.dimension(), 1) << g.description();
  ASSERT_EQ(g.curves().size(), 1u) << g.description();
  // From the bottom of the wall the ray just grazes the opposite rim: dir (4, 0, 4), up
  // to straight out of the pocket (both endpoints included).
  ExactVec a = rotated(o, 1, 0, 1), z = rotated(o, 0, 0, 1);
  sphere::SphericalImage expected;
  expected.add_curve({a, z, exact::cross(a, z)});
  EXPECT_TRUE(g == expected) << g.description();
  EXPECT_TRUE(g.points().empty());
}

sphere::SphericalImage gvm_of(const Built& b, std::initializer_list<std::string> names) {
  auto s = test::triangles_of(b.part.mesh(), b.raw, names);
  EXPECT_FALSE(s.empty());
  SurfaceVisibility vis = visibility(b.part, s);
  EXPECT_TRUE(vis.gvm.has_value());
  return vis.gvm ? *vis.gvm : sphere::SphericalImage{};
}

sphere::SphericalImage arc(const ExactVec& from, const ExactVec& to, const ExactVec& normal) {
  sphere::SphericalImage img;
  img.add_curve({from, to, normal});
  return img;
}

TEST_P(Variants, SlotFloorSeesTheHalfCircleInItsPlaneOfSymmetry) {
  const auto o = GetParam();
  Built b = build(test::slot_part(o));
  // The groove runs along y: the directions in the plane x = const, from -y over +z to +y.
  auto expected = arc(rotated(o, 0, -1, 0), rotated(o, 0, 1, 0), rotated(o, -1, 0, 0));
  for (auto names : {std::initializer_list<std::string>{"floor"},
                     std::initializer_list<std::string>{"floor", "wall_x0", "wall_x1"}}) {
    sphere::SphericalImage g = gvm_of(b, names);
    EXPECT_TRUE(g == expected) << g.description();
  }
}

TEST_P(Variants, ThroughHoleWallsSeeTheTwoAxisDirections) {
  const auto o = GetParam();
  Built b = build(test::through_hole_part(o));
  sphere::SphericalImage g = gvm_of(b, {"wall_x0", "wall_x1", "wall_y0", "wall_y1"});
  sphere::SphericalImage expected;
  expected.add_point(rotated(o, 0, 0, 1));
  expected.add_point(rotated(o, 0, 0, -1));
  EXPECT_TRUE(g == expected) << g.description();
}

TEST_P(Variants, PocketFloorSeesOneDirection) {
  const auto o = GetParam();
  Built b = build(test::pocket_part(o));
  auto expected = sphere::SphericalImage::point(rotated(o, 0, 0, 1));
  for (auto names : {std::initializer_list<std::string>{"floor"},
                     std::initializer_list<std::string>{"floor", "wall_x0", "wall_x1", "wall_y0",
                                                        "wall_y1"}}) {
    sphere::SphericalImage g = gvm_of(b, names);
    EXPECT_TRUE(g == expected) << g.description();
  }
}

TEST_P(Variants, StepFloorSeesALuneBetweenTheStepEdgeDirections) {
  const auto o = GetParam();
  Built b = build(test::step_part(o));
  sphere::SphericalImage g = gvm_of(b, {"step_floor"});
  // {u . z >= 0, u . x >= 0}: bounded by the half circle through +x and the one through +z.
  ExactVec py = rotated(o, 0, 1, 0), my = rotated(o, 0, -1, 0);
  sphere::Loop loop;
  loop.arcs.push_back({my, py, rotated(o, 0, 0, 1)});
  loop.arcs.push_back({py, my, rotated(o, 1, 0, 0)});
  sphere::SphericalImage expected;
  expected.add_face({{loop}, true});
  EXPECT_TRUE(g == expected) << g.description();
  EXPECT_NEAR(g.area(), 3.14159265358979323846, 1e-12);
}

TEST_P(Variants, ClosedTSlotLipUndersidesAreNeverVisible) {
  const auto o = GetParam();
  Built b = build(test::tslot_closed_part(o));
  for (const char* lip : {"lip_underside_0", "lip_underside_1"}) {
    sphere::SphericalImage g = gvm_of(b, {lip});
    EXPECT_TRUE(g.is_empty()) << lip << ": " << g.description();
  }
}

// A face bounded by the minor arcs through the given vertices, counter-clockwise seen from
// outside.
sphere::Face polygon(const std::vector<ExactVec>& v, bool convex) {
  sphere::Loop loop;
  for (size_t k = 0; k < v.size(); ++k) {
    const ExactVec& a = v[k];
    const ExactVec& b = v[(k + 1) % v.size()];
    loop.arcs.push_back({a, b, exact::cross(a, b)});
  }
  return {{loop}, convex};
}

TEST_P(Variants, DraftedPocketFloorSeesASphericalSquare) {
  const auto o = GetParam();
  Built b = build(test::drafted_pocket_part(o));
  // Walls leaning out 1 in 4 have normals (+-4, 0, 1) and (0, +-4, 1); adjacent ones meet
  // at the directions (+-1, +-1, 4), the corners of the floor's GVM.
  sphere::SphericalImage expected;
  expected.add_face(polygon({rotated(o, 1, 1, 4), rotated(o, -1, 1, 4), rotated(o, -1, -1, 4),
                             rotated(o, 1, -1, 4)},
                            true));
  for (auto names : {std::initializer_list<std::string>{"floor"},
                     std::initializer_list<std::string>{"floor", "wall_x0", "wall_x1", "wall_y0",
                                                        "wall_y1"}}) {
    sphere::SphericalImage g = gvm_of(b, names);
    EXPECT_TRUE(g == expected) << g.description();
    EXPECT_TRUE(g.contains(rotated(o, 0, 0, 1)));
    EXPECT_FALSE(g.contains(rotated(o, 1, 0, 3)));
  }
}

TEST_P(Variants, OpenTSlotLipUndersideSeesOutOfBothEnds) {
  const auto o = GetParam();
  Built b = build(test::tslot_open_part(o));
  // Channel x in [3, 9], z in [2, 5], length 10 along y; lip 0 spans x in [3, 5] at z = 5.
  // A ray from the far end of the lip leaves through the open end iff it descends at most
  // 3 (floor edge) and moves at most 4 towards the far wall (from the lip tip) over 10:
  // near +y the GVM is {u_x >= 0, u_z <= 0, 3 u_y + 10 u_z >= 0, 4 u_y - 10 u_x >= 0},
  // the quadrilateral +y, (4, 10, 0), (4, 10, -3), (0, 10, -3); the same mirrored at -y.
  sphere::SphericalImage expected;
  expected.add_face(polygon({rotated(o, 0, 1, 0), rotated(o, 4, 10, 0), rotated(o, 4, 10, -3),
                             rotated(o, 0, 10, -3)},
                            false));
  expected.add_face(polygon({rotated(o, 0, -1, 0), rotated(o, 0, -10, -3),
                             rotated(o, 4, -10, -3), rotated(o, 4, -10, 0)},
                            false));
  sphere::SphericalImage g = gvm_of(b, {"lip_underside_0"});
  EXPECT_TRUE(g == expected) << g.description();
  EXPECT_EQ(g.faces().size(), 2u) << g.description();
  EXPECT_TRUE(g.contains(rotated(o, 1, 10, -1)));   // inside the +y quadrilateral
  EXPECT_TRUE(g.contains(rotated(o, 4, -10, -3)));  // a corner of the -y one
  EXPECT_FALSE(g.contains(rotated(o, 1, 1, -1)));   // hits the floor
  EXPECT_FALSE(g.contains(rotated(o, 5, 10, 0)));   // reaches the far wall first
}

TEST_P(Variants, TwoDisjointPocketsTogetherAndAFaceWithoutOccluders) {
  const auto o = GetParam();
  Built b = build(test::two_pockets_part(o));
  auto s = test::triangles_of(b.part.mesh(), b.raw, {"floor_0", "floor_1"});
  SurfaceVisibility vis = visibility(b.part, s);
  ASSERT_TRUE(vis.gvm.has_value());
  EXPECT_TRUE(*vis.gvm == sphere::SphericalImage::point(rotated(o, 0, 0, 1)))
      << vis.gvm->description();
  // The step floor has no potential occluders: its GVM is its LVM, exactly.
  Built step = build(test::step_part(o));
  auto floor = test::triangles_of(step.part.mesh(), step.raw, {"step_floor"});
  SurfaceVisibility fv = visibility(step.part, floor);
  EXPECT_EQ(fv.status, GvmStatus::kExactNoPotentialOccluders);
  EXPECT_TRUE(fv.occluders.potential.empty());
  ASSERT_TRUE(fv.gvm.has_value());
  EXPECT_TRUE(*fv.gvm == fv.lvm);
}

// A blind pocket with a groove round its walls at mid-depth (a square circlip groove):
// looking straight in, the rays from the floor and the lower walls run along the upper
// walls and only touch the groove's rims, while every direction around the axis is
// blocked. Int(Phi(O + (-S))) holds the axis; the occlusion probe gives it back.
TEST_P(Variants, GroovedPocketFloorAndLowerWallsStillSeeTheAxis) {
  const auto o = GetParam();
  Built b = build(test::grooved_pocket_part(o));
  const auto axis = sphere::SphericalImage::point(rotated(o, 0, 0, 1));
  sphere::SphericalImage floor = gvm_of(b, {"floor"});
  EXPECT_TRUE(floor == axis) << floor.description();
  sphere::SphericalImage lower = gvm_of(b, {"lower_x0", "lower_x1", "lower_y0", "lower_y1"});
  EXPECT_TRUE(lower == axis) << lower.description();
  // The upper walls see out of the pocket, but not down: those rays run along the lower
  // walls into the floor's concave rim, where they enter the solid.
  sphere::SphericalImage upper = gvm_of(b, {"upper_x0", "upper_x1", "upper_y0", "upper_y1"});
  EXPECT_TRUE(upper == axis) << upper.description();
  // The groove's floor and ceiling face each other: never visible.
  EXPECT_TRUE(gvm_of(b, {"groove_floor"}).is_empty());
  EXPECT_TRUE(gvm_of(b, {"groove_ceiling"}).is_empty());
  // One lower wall alone sees an arc, from the axis to the direction grazing the
  // opposite rim from the wall's bottom edge (4 across, 6 up).
  sphere::SphericalImage wall = gvm_of(b, {"lower_x0"});
  const ExactVec z = rotated(o, 0, 0, 1), rim = rotated(o, 2, 0, 3);
  EXPECT_TRUE(wall == arc(rim, z, exact::cross(rim, z))) << wall.description();
}

// The grooved pocket with a vertex in the middle of the rim on x = 4, strictly inside the
// strips the rays from the lower wall x0 sweep up along +z: they pass that vertex without
// entering the solid (its cone is the wedge behind the upper wall and above the groove
// ceiling, and +z runs along the wall), so every GVM is the grooved pocket's.
TEST_P(Variants, RaysPassingARimVertexInTheirPlaneDoNotEnterThere) {
  const auto o = GetParam();
  Built b = build(test::grooved_pocket_rim_vertex_part(o));
  const auto axis = sphere::SphericalImage::point(rotated(o, 0, 0, 1));
  sphere::SphericalImage lower = gvm_of(b, {"lower_x0", "lower_x1", "lower_y0", "lower_y1"});
  EXPECT_TRUE(lower == axis) << lower.description();
  sphere::SphericalImage floor_and_lower =
      gvm_of(b, {"floor", "lower_x0", "lower_x1", "lower_y0", "lower_y1"});
  EXPECT_TRUE(floor_and_lower == axis) << floor_and_lower.description();
  sphere::SphericalImage wall = gvm_of(b, {"lower_x0"});
  const ExactVec z = rotated(o, 0, 0, 1), rim = rotated(o, 2, 0, 3);
  EXPECT_TRUE(wall == arc(rim, z, exact::cross(rim, z))) << wall.description();
}

// A slot with a groove round its walls at mid-height, its upper walls in the planes of the
// lower ones: the floor with its lower walls sees the half circle of the plain slot, the
// rays along it running in the walls' planes past the groove (the arc lies in the planes
// of triangles of S, and every direction off it is blocked by the groove's ceiling).
TEST_P(Variants, GroovedSlotFloorAndLowerWallsSeeTheHalfCircle) {
  const auto o = GetParam();
  Built b = build(test::grooved_slot_part(o));
  auto expected = arc(rotated(o, 0, -1, 0), rotated(o, 0, 1, 0), rotated(o, -1, 0, 0));
  for (auto names : {std::initializer_list<std::string>{"floor"},
                     std::initializer_list<std::string>{"floor", "lower_x0", "lower_x1"},
                     std::initializer_list<std::string>{"lower_x0", "lower_x1"}}) {
    sphere::SphericalImage g = gvm_of(b, names);
    EXPECT_TRUE(g == expected) << g.description();
  }
}

// Zero clearance inside a 2-cell of the LVM: the floor of a pocket whose walls lean out
// and back in to an opening of exactly the floor's outline. Every direction off the axis
// is blocked by the overhang; along the axis the rays from the floor's rim run up past the
// opening's rim, touching it. The floor's LVM is the cone the lower walls leave (a 2-cell),
// and the axis lies inside it, where the occluded cells only meet: a seam.
TEST_P(Variants, FlaredPocketFloorSeesTheAxisThroughAnOpeningOfItsOwnSize) {
  const auto o = GetParam();
  Built b = build(test::flared_pocket_part(o));
  auto s = test::triangles_of(b.part.mesh(), b.raw, {"floor"});
  SurfaceVisibility vis = visibility(b.part, s);
  ASSERT_TRUE(vis.gvm.has_value());
  EXPECT_EQ(vis.lvm.dimension(), 2) << vis.lvm.description();
  EXPECT_TRUE(*vis.gvm == sphere::SphericalImage::point(rotated(o, 0, 0, 1))) << vis.gvm->description();
  // The lower walls face up and in, but their rays along the axis run into the overhang.
  sphere::SphericalImage with_walls = gvm_of(b, {"floor", "lower_x0", "lower_x1", "lower_y0", "lower_y1"});
  EXPECT_TRUE(with_walls.is_empty()) << with_walls.description();
}

// The same section as a slot through the part (10 long): the two lips are the occluders,
// and the directions they leave, in the slot's plane of symmetry, are exactly where their
// occluded cells meet, inside the floor's LVM (a 2-cell). The floor sees that half circle
// as far as (0, +-5, 2), where the ray from the floor's far end rises to the mouth (4)
// over the slot's length; flatter, the rays leave through the slot's open ends, in a 2-cell
// at each end. The same with a boss on the top whose face is flush with the mouth's edge
// (the rays from the floor's edge run up along it).
TEST_P(Variants, FlaredSlotFloorSeesTheHalfCircleBetweenTheLips) {
  const auto o = GetParam();
  for (auto make : {test::flared_slot_part, test::flared_slot_boss_part}) {
    Built b = build(make(o));
    auto s = test::triangles_of(b.part.mesh(), b.raw, {"floor"});
    SurfaceVisibility vis = visibility(b.part, s);
    ASSERT_TRUE(vis.gvm.has_value());
    const sphere::SphericalImage& g = *vis.gvm;
    EXPECT_EQ(vis.lvm.dimension(), 2) << vis.lvm.description();
    ASSERT_EQ(g.curves().size(), 1u) << b.raw.source << ": " << g.description();
    const sphere::Arc& seam = g.curves()[0];
    EXPECT_TRUE(exact::parallel(seam.normal, rotated(o, 1, 0, 0))) << g.description();
    for (const ExactVec& d : {rotated(o, 0, -5, 2), rotated(o, 0, 5, 2), rotated(o, 0, 0, 1)}) {
      EXPECT_TRUE(sphere::arc_contains(seam, d)) << g.description();
    }
    EXPECT_FALSE(sphere::arc_contains(seam, rotated(o, 0, 6, 2))) << g.description();
    EXPECT_EQ(g.faces().size(), 2u) << g.description();
    EXPECT_TRUE(g.contains(rotated(o, 0, 10, 1)));
    EXPECT_TRUE(g.contains(rotated(o, 0, -10, 1)));
    for (int sx : {-1, 1}) {
      for (int sy : {-1, 0, 1}) EXPECT_FALSE(g.contains(rotated(o, sx, sy, 100))) << sx << " " << sy;
    }
  }
}

// The benchmark's round flared pocket with its opening exactly the floor's 16-gon
// (`gvm_make_pocket_part 16 4 0`, checked in): the floor's LVM is a 2-cell of 2.09 sr and
// its GVM the axis alone. (The floor with the pocket wall has an empty LVM.)
TEST(FlaredPocketBenchmarkPart, FloorSeesTheAxis) {
  auto solid = load_solid(std::string(GVM_TEST_DATA_DIR) + "/flared_pocket_16_4_0.off");
  ASSERT_TRUE(solid.ok()) << solid.status().message();
  std::vector<uint32_t> floor;
  for (uint32_t t = 0; t < solid->triangles.size(); ++t) {
    bool on_floor = true;
    for (uint32_t v : solid->triangles[t]) on_floor = on_floor && solid->points[v].z == -15;
    if (on_floor) floor.push_back(t);
  }
  ASSERT_EQ(floor.size(), 16u);
  auto part = Part::analyze(std::move(*solid), PartOptions{});
  ASSERT_TRUE(part.ok());
  SurfaceVisibility vis = visibility(*part, floor);
  ASSERT_TRUE(vis.gvm.has_value());
  EXPECT_EQ(vis.lvm.dimension(), 2);
  EXPECT_TRUE(*vis.gvm == sphere::SphericalImage::point(ExactVec::from_point({0, 0, 1}))) << vis.gvm->description();
}

INSTANTIATE_TEST_SUITE_P(Gvm, Variants,
                         ::testing::Values(test::TestPartOptions{0, false, false},
                                           test::TestPartOptions{1, false, false},
                                           test::TestPartOptions{2, true, false}),
                         [](const auto& info) {
                           const test::TestPartOptions& o = info.param;
                           return std::string(o.rotation == 0   ? "Axes"
                                              : o.rotation == 1 ? "Rotated"
                                                                : "RotatedTwice") +
                                  (o.split ? "Split" : "");
                         });

}  // namespace
}  // namespace gvm
