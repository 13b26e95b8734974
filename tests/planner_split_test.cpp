// Automatic features that no one direction sees whole are planned in pieces that each
// have a common direction: a block whose flat top is joined, by fillets turning 20 degrees
// at a time, to side walls that lean in by 5 degrees under it -- one automatic feature
// (normals turn by less than 30 degrees across every edge), whose own faces have no
// common direction (the walls face down and every way around, the top faces up). Split by
// default into the top with its fillets (reached from +z) and the walls (from -z, beside
// the bottom), nothing unreachable; whole with --no-split, an undercut of its own shape.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "gvm/analysis.h"
#include "gvm/planner/plan.h"
#include "support/mesh_files.h"
#include "support/scratch_dir.h"

namespace gvm {
namespace {

// Rings of four corners (+-w, +-w, z) from the top down; consecutive rings are joined by
// four trapezoids, exactly planar (each side's two edges are parallel to an axis).
RawMesh capped_block() {
  std::vector<std::array<double, 2>> ring = {{10, 20}};  // (w, z)
  for (const double degrees : {20.0, 40.0, 60.0, 80.0, 95.0}) {
    const double phi = degrees * M_PI / 180, length = degrees < 90 ? 1.5 : 12;
    ring.push_back({ring.back()[0] + length * std::cos(phi), ring.back()[1] - length * std::sin(phi)});
  }
  RawMesh raw;
  for (const auto& [w, z] : ring) {
    for (const auto& [sx, sy] : {std::pair{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}) raw.points.push_back({sx * w, sy * w, z});
  }
  auto corner = [](size_t r, int k) { return static_cast<uint32_t>(4 * r + (k % 4)); };
  raw.faces.push_back({corner(0, 0), corner(0, 1), corner(0, 2), corner(0, 3)});  // the top, counter-clockwise from +z
  for (size_t r = 0; r + 1 < ring.size(); ++r) {
    for (int k = 0; k < 4; ++k) raw.faces.push_back({corner(r, k), corner(r + 1, k), corner(r + 1, k + 1), corner(r, k + 1)});
  }
  const size_t last = ring.size() - 1;
  raw.faces.push_back({corner(last, 3), corner(last, 2), corner(last, 1), corner(last, 0)});  // the bottom
  return raw;
}

struct Capped {
  Capped() {
    AnalyzeRequest request;
    request.part_path = test::write_off(capped_block(), test::scratch_dir() / "capped_block.off");
    auto a = analyze(request);
    EXPECT_TRUE(a.ok()) << a.status().message();
    analysis.emplace(std::move(*a));
  }
  std::optional<Analysis> analysis;
};

const Capped& capped() {
  static const Capped c;
  return c;
}

planner::SetupPlan plan(v1::PlanOptions options) {
  auto p = planner::plan(*capped().analysis, options);
  EXPECT_TRUE(p.ok()) << p.status().message();
  return std::move(*p);
}

TEST(PlannerSplit, TheBlockHasTwoFeaturesTheCapOneOfThemWithoutAnOwnDirection) {
  const Analysis& a = *capped().analysis;
  ASSERT_EQ(a.features().size(), 2u);  // the cap (top, fillets, walls) and the bottom
  const Surface& cap = a.features()[0];
  EXPECT_TRUE(cap.automatic);
  EXPECT_EQ(cap.faces.size(), 21u);
  auto own = a.own_lvm(cap.faces);
  ASSERT_TRUE(own.ok());
  EXPECT_TRUE(own->is_empty());
  // Two pieces with a common direction each (no fewer can be: the whole has none), which
  // make up the feature: the top with its fillets and the two walls they still allow (the
  // walls lean 5 degrees, the fillets leave 10), and the other two walls.
  const auto pieces = a.visible_pieces(cap.faces);
  ASSERT_EQ(pieces.size(), 2u);
  std::vector<uint32_t> all;
  for (const auto& piece : pieces) {
    all.insert(all.end(), piece.begin(), piece.end());
    auto lvm = a.own_lvm(piece);
    ASSERT_TRUE(lvm.ok());
    EXPECT_FALSE(lvm->is_empty());
  }
  std::sort(all.begin(), all.end());
  EXPECT_EQ(all, cap.faces);
  EXPECT_EQ(pieces[0].size(), 19u);
  EXPECT_EQ(pieces[1].size(), 2u);
  // With the faces beside them: LVM(S + N_S), what the GVM is cut from, has a direction.
  for (const auto& piece : pieces) {
    auto maps = a.surface_of(piece);
    ASSERT_TRUE(maps.ok());
    EXPECT_FALSE(maps->maps.lvm.is_empty());
  }
}

// Along the seeds' normals: the top with its fillets (all of which face up a little), then
// the walls (leaning in by 5 degrees, facing down a little), each seen along its seed's
// normal with its N_S.
TEST(PlannerSplit, AlongTheSeedsNormalsTheTopTakesItsFillets) {
  const Analysis& a = *capped().analysis;
  const Surface& cap = a.features()[0];
  const auto pieces = a.visible_pieces(cap.faces, Analysis::Growth::kAlongSeedNormal);
  ASSERT_GE(pieces.size(), 2u);
  const auto top = std::find_if(pieces.begin(), pieces.end(), [](const auto& p) { return p.front() == 0; });
  ASSERT_NE(top, pieces.end());
  EXPECT_EQ(top->size(), 17u);  // the top and four rings of fillets
  auto maps = a.surface_of(*top);
  ASSERT_TRUE(maps.ok());
  EXPECT_TRUE(maps->maps.lvm.contains(Direction(0, 0, 1)));
  size_t faces = 0;
  for (const auto& piece : pieces) faces += piece.size();
  EXPECT_EQ(faces, cap.faces.size());
}

TEST(PlannerSplit, AFeatureOverTheLimitStaysWholeAndSaysSo) {
  v1::PlanOptions options;
  options.set_split_max_faces(20);  // the cap has 21
  const planner::SetupPlan p = plan(options);
  ASSERT_EQ(p.message.unreachable_size(), 1);
  EXPECT_EQ(p.message.unreachable(0).reason(), v1::UNREACHABLE_REASON_SELF_OCCLUDED);
  EXPECT_NE(p.message.unreachable(0).detail().find("not split into pieces: 21 faces, more than 20"), std::string::npos)
      << p.message.unreachable(0).detail();
  options.set_split_max_faces(21);
  EXPECT_EQ(plan(options).message.unreachable_size(), 0);
}

TEST(PlannerSplit, AFeatureWrappingOverItsRimIsPlannedPieceByPiece) {
  const planner::SetupPlan p = plan({});
  EXPECT_EQ(p.message.unreachable_size(), 0);
  EXPECT_EQ(p.message.reached(), 2u);
  ASSERT_EQ(p.message.setups_size(), 2);
  EXPECT_TRUE(p.message.optimal());
  const v1::PlannedSurface& cap = p.message.surfaces(0);
  ASSERT_TRUE(cap.has_pieces());
  EXPECT_EQ(cap.pieces().count(), 2u);
  EXPECT_EQ(cap.pieces().setups_size(), 2);
  EXPECT_EQ(cap.setup(), -1);  // not whole in any setup
  // Each piece in a setup whose exact direction lies in the piece's own GVM.
  const Analysis& a = *capped().analysis;
  int pieces = 0;
  for (int k = 0; k < p.message.setups_size(); ++k) {
    for (const auto& r : p.message.setups(k).reach()) {
      if (!r.has_piece()) continue;
      ++pieces;
      auto piece = a.surface_of(std::vector<uint32_t>(r.faces().begin(), r.faces().end()));
      ASSERT_TRUE(piece.ok());
      EXPECT_TRUE(piece->maps.gvm->contains(p.directions[k]));
    }
  }
  EXPECT_EQ(pieces, 2);
}

TEST(PlannerSplit, NoSplitKeepsTheFeatureWholeAndUnreachable) {
  v1::PlanOptions options;
  options.set_no_split(true);
  const planner::SetupPlan p = plan(options);
  ASSERT_EQ(p.message.unreachable_size(), 1);
  EXPECT_EQ(p.message.unreachable(0).feature(), 0u);
  EXPECT_EQ(p.message.unreachable(0).reason(), v1::UNREACHABLE_REASON_SELF_OCCLUDED);
  EXPECT_NE(p.message.unreachable(0).detail().find("an undercut of its own shape"), std::string::npos);
  EXPECT_FALSE(p.message.surfaces(0).has_pieces());
}

// A user group is kept whole (unless --split): the same faces named as a group.
TEST(PlannerSplit, UserGroupsAreKeptWhole) {
  RawMesh raw = capped_block();
  for (uint32_t f = 0; f < raw.faces.size(); ++f) raw.groups[f + 1 < raw.faces.size() ? "cap" : "bottom"].push_back(f);
  AnalyzeRequest request;
  request.part_path = test::write_obj(raw, test::scratch_dir() / "capped_block_groups.obj");
  auto a = analyze(request);
  ASSERT_TRUE(a.ok()) << a.status().message();
  auto p = planner::plan(*a, {});
  ASSERT_TRUE(p.ok());
  ASSERT_EQ(p->message.unreachable_size(), 1);
  EXPECT_EQ(p->message.unreachable(0).reason(), v1::UNREACHABLE_REASON_SELF_OCCLUDED);
}

}  // namespace
}  // namespace gvm
