// The planner on exact parts with hand-derived answers, through its public API: a block
// with a through hole along x, a pocket from +z and a slot along y, in three rational
// rotations; and the options it refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include "gvm/analysis.h"
#include "gvm/planner/plan.h"
#include "support/assertions.h"
#include "support/mesh_files.h"
#include "support/scratch_dir.h"
#include "support/test_parts.h"

namespace gvm {
namespace {

struct Block {
  // `merged`: these faces' groups become one feature named "merged".
  explicit Block(int rotation, const std::vector<std::string>& merged = {}) : options{.rotation = rotation} {
    RawMesh raw = test::machined_block_part(options);
    for (const std::string& name : merged) {
      auto& into = raw.groups["merged"];
      into.insert(into.end(), raw.groups[name].begin(), raw.groups[name].end());
      raw.groups.erase(name);
    }
    const std::string path =
        test::write_obj(raw, test::scratch_dir() / ("block" + std::to_string(rotation) + std::to_string(merged.size()) + ".obj"));
    AnalyzeRequest request;
    request.part_path = path;
    auto a = analyze(request);
    EXPECT_TRUE(a.ok()) << a.status().message();
    analysis.emplace(std::move(*a));
  }

  const Surface& feature(const std::string& name) const {
    for (const Surface& f : analysis->features()) {
      if (f.name == name) return f;
    }
    ADD_FAILURE() << "no feature " << name;
    return analysis->features().front();
  }
  Direction axis(double x, double y, double z) const {
    const Point3 p = test::rotated(options, {x, y, z});
    return Direction(p.x, p.y, p.z);
  }

  test::TestPartOptions options;
  std::optional<Analysis> analysis;
};

// One analysis per rotation for all the tests (the hole's floor alone takes seconds).
const Block& block(int rotation) {
  static std::map<int, std::unique_ptr<Block>> cache;
  std::unique_ptr<Block>& b = cache[rotation];
  if (!b) b = std::make_unique<Block>(rotation);
  return *b;
}

planner::SetupPlan plan(const Block& b, v1::PlanOptions options = {}) {
  auto p = planner::plan(*b.analysis, options);
  EXPECT_TRUE(p.ok()) << p.status().message();
  return p.ok() ? std::move(*p) : planner::SetupPlan{};
}

// The setup a surface is planned in (whole), or -1.
int setup_of(const planner::SetupPlan& p, uint32_t id) {
  for (int k = 0; k < p.message.setups_size(); ++k) {
    const auto& f = p.message.setups(k).features();
    if (std::find(f.begin(), f.end(), id) != f.end()) return k;
  }
  return -1;
}

// Every surface planned in a setup has the setup's exact direction in its tool
// directions (setup and probe modes), decided exactly; each surface is in one setup.
void expect_assignments_exact(const Block& b, const planner::SetupPlan& p) {
  ASSERT_EQ(p.directions.size(), size_t(p.message.setups_size()));
  std::set<uint32_t> seen;
  for (int k = 0; k < p.message.setups_size(); ++k) {
    for (uint32_t id : p.message.setups(k).features()) {
      EXPECT_TRUE(seen.insert(id).second) << "feature " << id << " in two setups";
      const Surface& s = b.analysis->features()[id];
      ASSERT_TRUE(s.maps.gvm.has_value());
      EXPECT_TRUE(s.maps.gvm->contains(p.directions[k])) << s.name << " in setup " << k;
    }
  }
}

class MachinedBlock : public ::testing::TestWithParam<int> {};

// +z is the pocket floor's only direction; the hole's four faces each see two short arcs
// at +-x (floor and ceiling tilted up or down in the x-z plane, the sides in the x-y
// plane), so +-x is all they share. +z also reaches the top, the pocket walls (their arcs
// end at +z), the slot and the sides (grazing), +-x the bottom: two setups, and the floor
// and the hole, which share no direction, prove that bound.
TEST_P(MachinedBlock, TwoSetupsExactlyAlongThePocketFloorAndTheHole) {
  const Block& b = block(GetParam());
  const planner::SetupPlan p = plan(b);
  ASSERT_EQ(p.message.setups_size(), 2);
  EXPECT_TRUE(p.message.optimal());
  EXPECT_EQ(p.message.lower_bound(), 2u);
  EXPECT_EQ(p.message.unreachable_size(), 0);
  EXPECT_EQ(p.message.reached(), b.analysis->features().size());
  expect_assignments_exact(b, p);

  const int floor = setup_of(p, b.feature("pocket_floor").id);
  const int hole = setup_of(p, b.feature("hole_floor").id);
  ASSERT_GE(floor, 0);
  ASSERT_GE(hole, 0);
  EXPECT_NE(floor, hole);
  EXPECT_TRUE(p.directions[floor] == b.axis(0, 0, 1));
  EXPECT_TRUE(p.directions[hole] == b.axis(1, 0, 0) || p.directions[hole] == b.axis(-1, 0, 0));
  for (const char* name : {"hole_y0", "hole_y1", "hole_ceiling"}) {
    EXPECT_EQ(setup_of(p, b.feature(name).id), hole) << name;
  }
  EXPECT_TRUE(p.message.setups(floor).exact_alignment());
  EXPECT_EQ(p.message.setups(floor).clearance_degrees(), 0);
  for (const auto& r : p.message.setups(hole).reach()) {
    if (b.analysis->features()[r.feature()].name.rfind("hole", 0) == 0) EXPECT_TRUE(r.exact_alignment());
  }
}

// Along their own normals only, the six faces of the block need six setups, exactly the
// six axes; the walls of the pocket, the hole and the slot are never met square.
TEST_P(MachinedBlock, PlanarNormalsNeedSixSetupsAndLeaveTheWalls) {
  const Block& b = block(GetParam());
  v1::PlanOptions options;
  options.set_planar_normal(true);
  const planner::SetupPlan p = plan(b, options);
  ASSERT_EQ(p.message.setups_size(), 6);
  EXPECT_TRUE(p.message.optimal());
  expect_assignments_exact(b, p);
  for (const Direction& axis : {b.axis(1, 0, 0), b.axis(-1, 0, 0), b.axis(0, 1, 0), b.axis(0, -1, 0),
                                b.axis(0, 0, 1), b.axis(0, 0, -1)}) {
    EXPECT_EQ(std::count(p.directions.begin(), p.directions.end(), axis), 1);
  }
  std::set<std::string> unreachable;
  for (const auto& u : p.message.unreachable()) {
    EXPECT_EQ(u.reason(), v1::UNREACHABLE_REASON_NOT_ALONG_NORMAL) << u.detail();
    EXPECT_TRUE(test::Has(u.detail(), "normal"));
    unreachable.insert(b.analysis->features()[u.feature()].name);
  }
  EXPECT_EQ(unreachable, (std::set<std::string>{"hole_y0", "hole_y1", "hole_floor", "hole_ceiling", "pocket_x0",
                                                "pocket_x1", "pocket_y0", "pocket_y1", "slot_x0", "slot_x1"}));
  EXPECT_TRUE(p.directions[setup_of(p, b.feature("pocket_floor").id)] == b.axis(0, 0, 1));
  EXPECT_TRUE(p.directions[setup_of(p, b.feature("slot_floor").id)] == b.axis(0, 0, 1));
}

// On a 4-axis indexer one axis reaches everything: its circle must hold the floor's +z and
// meet the hole floor's arcs, which lie in the x-z plane off +z, so it is that plane: the
// axis is +-y exactly.
TEST_P(MachinedBlock, OneRotaryAxisAlongY) {
  const Block& b = block(GetParam());
  v1::PlanOptions options;
  options.set_mode(v1::PLAN_MODE_ROTARY);
  const planner::SetupPlan p = plan(b, options);
  ASSERT_EQ(p.message.setups_size(), 1);
  EXPECT_TRUE(p.message.optimal());
  EXPECT_TRUE(parallel(p.directions[0], b.axis(0, 1, 0)));
  const v1::Setup& s = p.message.setups(0);
  EXPECT_EQ(s.features_size(), int(b.analysis->features().size()));
  // The chosen table angle turns the tool from rotary_zero about the axis onto the
  // feature's GVM (its arcs and points included: within rounding of them).
  const std::array<double, 3> a = p.directions[0].unit();
  const auto& z = s.rotary_zero();
  const std::array<double, 3> e2 = {a[1] * z.z() - a[2] * z.y(), a[2] * z.x() - a[0] * z.z(),
                                    a[0] * z.y() - a[1] * z.x()};
  auto tool = [&](double degrees) {
    const double r = degrees * M_PI / 180;
    return std::array<double, 3>{std::cos(r) * z.x() + std::sin(r) * e2[0], std::cos(r) * z.y() + std::sin(r) * e2[1],
                                 std::cos(r) * z.z() + std::sin(r) * e2[2]};
  };
  for (const auto& r : s.reach()) {
    const Surface& f = b.analysis->features()[r.feature()];
    ASSERT_GT(r.rotary_angles_size(), 0) << f.name;
    EXPECT_GT(f.maps.gvm->approx_signed_clearance(tool(r.rotary_angle_degrees())), -1e-9) << f.name;
    for (const auto& range : r.rotary_angles()) {
      EXPECT_GT(f.maps.gvm->approx_signed_clearance(tool(range.from_degrees())), -1e-9) << f.name;
      EXPECT_GT(f.maps.gvm->approx_signed_clearance(tool(range.to_degrees())), -1e-9) << f.name;
    }
  }
  const auto& floor = s.reach(std::find_if(s.reach().begin(), s.reach().end(), [&](const auto& r) {
                                return b.analysis->features()[r.feature()].name == "pocket_floor";
                              }) - s.reach().begin());
  EXPECT_EQ(floor.rotary_angles_size(), 1);
  EXPECT_EQ(floor.rotary_angles(0).from_degrees(), floor.rotary_angles(0).to_degrees());
}

INSTANTIATE_TEST_SUITE_P(Rotations, MachinedBlock, ::testing::Values(0, 1, 2));

// With the default head (A 0..105, B -180..180, every 7.5 degrees) and a 5 degree cone:
// the pocket floor only at A 0, the hole only at A 90 exactly along +-x (its floor's arcs
// tilt 7.1 degrees at most, less than a step), the bottom only
// at A 97.5 or 105, each slot wall only tilted towards its own side by 5 degrees or more
// while its cone stays under the opposite rim (3 deep, 4 wide): five orientations that
// pairwise serve nothing in common, and five suffice (the sides and the top ride along).
TEST(MachinedBlockProbe, FiveHeadOrientations) {
  const Block& b = block(0);
  v1::PlanOptions options;
  options.set_mode(v1::PLAN_MODE_PROBE);
  const planner::SetupPlan p = plan(b, options);
  ASSERT_EQ(p.message.setups_size(), 5);
  EXPECT_TRUE(p.message.optimal());
  EXPECT_EQ(p.message.unreachable_size(), 0);
  expect_assignments_exact(b, p);
  const v1::Setup& floor = p.message.setups(setup_of(p, b.feature("pocket_floor").id));
  EXPECT_EQ(floor.head_a_degrees(), 0);
  const v1::Setup& hole = p.message.setups(setup_of(p, b.feature("hole_floor").id));
  EXPECT_EQ(hole.head_a_degrees(), 90);
  EXPECT_EQ(std::fabs(hole.head_b_degrees()) == 180 || hole.head_b_degrees() == 0, true);
  EXPECT_GE(p.message.setups(setup_of(p, b.feature("bottom").id)).head_a_degrees(), 97.5);
  // Every 2-dimensional GVM holds the cone: clearance at least 5 degrees.
  for (const auto& s : p.message.setups()) {
    for (const auto& r : s.reach()) {
      if (b.analysis->features()[r.feature()].maps.gvm->dimension() == 2) EXPECT_GE(r.clearance_degrees(), 5);
    }
  }
}

// The concave regions: the hole (its faces share only +-x), the pocket (+z) and the slot
// (the half circle through +z): two setups.
TEST(MachinedBlockRegions, TwoSetups) {
  const Block& b = block(0);
  v1::PlanOptions options;
  options.set_surfaces(v1::PLAN_SURFACES_REGIONS);
  const planner::SetupPlan p = plan(b, options);
  EXPECT_EQ(p.message.surfaces_size(), 3);
  ASSERT_EQ(p.message.setups_size(), 2);
  EXPECT_TRUE(p.message.optimal());
  for (int k = 0; k < 2; ++k) {
    for (uint32_t id : p.message.setups(k).features()) {
      EXPECT_TRUE(b.analysis->regions()[id].maps.gvm->contains(p.directions[k]));
    }
  }
}

// The floors of the pocket and of the hole as one feature: together they could only be
// seen along +z (LVM(S + N_S) = {+z}), where the hole's ceiling blocks them. Unreachable
// whole, the ceiling named; with --split each floor in its own setup, and the feature
// reached piece by piece.
TEST(MachinedBlockSplit, TwoFloorsAsOneFeatureArePlannedPieceByPiece) {
  const Block b(0, {"pocket_floor", "hole_floor"});
  const uint32_t merged = b.feature("merged").id;
  const planner::SetupPlan whole = plan(b);
  ASSERT_EQ(whole.message.unreachable_size(), 1);
  const v1::Unreachable& u = whole.message.unreachable(0);
  EXPECT_EQ(u.feature(), merged);
  EXPECT_EQ(u.reason(), v1::UNREACHABLE_REASON_OCCLUDED);
  EXPECT_EQ(std::vector<uint32_t>(u.blocking_features().begin(), u.blocking_features().end()),
            std::vector<uint32_t>{b.feature("hole_ceiling").id});
  EXPECT_TRUE(test::Has(u.detail(), "hole_ceiling"));
  EXPECT_EQ(u.probed_direction().z(), 1);

  v1::PlanOptions options;
  options.set_split(true);
  const planner::SetupPlan split = plan(b, options);
  EXPECT_EQ(split.message.unreachable_size(), 0);
  const v1::PlannedSurface& planned = split.message.surfaces(static_cast<int>(merged));
  ASSERT_EQ(planned.id(), merged);
  EXPECT_EQ(planned.pieces().count(), 2u);
  EXPECT_EQ(planned.pieces().setups_size(), 2);
  int pieces = 0;
  for (int k = 0; k < split.message.setups_size(); ++k) {
    for (const auto& r : split.message.setups(k).reach()) {
      if (r.faces_size() == 0) continue;
      ++pieces;
      EXPECT_EQ(r.feature(), merged);
      std::vector<uint32_t> faces(r.faces().begin(), r.faces().end());
      auto piece = b.analysis->surface_of(faces);
      ASSERT_TRUE(piece.ok());
      EXPECT_TRUE(piece->maps.gvm->contains(split.directions[k]));
    }
  }
  EXPECT_EQ(pieces, 2);
}

TEST(PlannerOptions, BadOptionsNameTheirField) {
  auto error = [](const v1::PlanOptions& o) { return planner::validate(o).message(); };
  v1::PlanOptions mode;
  mode.set_mode(static_cast<v1::PlanMode>(17));
  EXPECT_TRUE(test::Has(error(mode), "mode"));
  v1::PlanOptions cone;
  cone.set_mode(v1::PLAN_MODE_PROBE);
  cone.set_cone_degrees(90);
  EXPECT_TRUE(test::Has(error(cone), "cone_degrees"));
  v1::PlanOptions step;
  step.set_mode(v1::PLAN_MODE_PROBE);
  step.mutable_head()->set_a_max_degrees(90);
  step.mutable_head()->set_b_max_degrees(90);
  EXPECT_TRUE(test::Has(error(step), "step"));
  v1::PlanOptions a_range = step;
  a_range.mutable_head()->set_step_degrees(5);
  a_range.mutable_head()->set_a_min_degrees(100);
  EXPECT_TRUE(test::Has(error(a_range), "A range"));
  v1::PlanOptions misplaced;
  misplaced.set_cone_degrees(3);
  EXPECT_TRUE(test::Has(error(misplaced), "probe mode only"));
  v1::PlanOptions clearance;
  clearance.set_min_clearance_degrees(-1);
  EXPECT_TRUE(test::Has(error(clearance), "min_clearance_degrees"));
  v1::PlanOptions up;
  up.set_mode(v1::PLAN_MODE_PROBE);
  up.mutable_part_up();
  EXPECT_TRUE(test::Has(error(up), "part_up"));
  EXPECT_TRUE(planner::validate(v1::PlanOptions{}).ok());
}

TEST(PlannerOptions, DefaultsOfTheProbeHead) {
  v1::PlanOptions o;
  o.set_mode(v1::PLAN_MODE_PROBE);
  const v1::PlanOptions d = planner::with_defaults(o);
  EXPECT_EQ(d.head().a_max_degrees(), 105);
  EXPECT_EQ(d.head().b_min_degrees(), -180);
  EXPECT_EQ(d.head().step_degrees(), 7.5);
  EXPECT_EQ(d.cone_degrees(), 5);
  EXPECT_EQ(d.part_up().z(), 1);
  EXPECT_EQ(planner::with_defaults(v1::PlanOptions{}).mode(), v1::PLAN_MODE_SETUP);
}

}  // namespace
}  // namespace gvm
