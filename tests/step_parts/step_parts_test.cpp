// The faithful STEP tessellation on machined parts built as exact B-reps (brep_parts.h),
// in their own frame and rotated onto oblique axes, against answers derived by hand:
//   - a through hole's walls see exactly +-axis (two points), a blind hole's walls and
//     bottom only its opening (one point), a hole under a roof only the open end;
//   - a counterbore: the bore +-axis, the counterbore's wall and its step the opening;
//   - a countersink: the bore +-axis, the cone a cap around the opening;
//   - a through slot: the floor exactly the half great circle from one end of the slot
//     over the opening to the other; each wall a 2-cell bounded by that half circle;
//   - an L-bracket: each hole's walls +-its own axis.
// Every point of a GVM must lie within the stated angle of the B-rep's axis (the frame
// distance in the part's StepTessellation), and the tessellation must keep every relation.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "brep_parts.h"
#include "gvm/analysis.h"

namespace gvm::test {
namespace {

struct Case {
  Part part;
  Rotation rotation;
  const char* rotation_name;
  friend void PrintTo(const Case& c, std::ostream* os) { *os << name_of(c.part) << ", " << c.rotation_name; }
};

double angle_between(const Vec& a, const Vec& b) {
  const double c = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const Vec x = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return std::atan2(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), c);
}

Vec unit(Vec v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

Vec neg(const Vec& v) { return {-v[0], -v[1], -v[2]}; }

class StepParts : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    bytes_ = step_bytes(GetParam().part, GetParam().rotation);
    AnalyzeRequest request;
    request.part_bytes = bytes_;
    request.part_format = MeshFormat::kStep;
    request.part_name = std::string(name_of(GetParam().part)) + "_" + GetParam().rotation_name + ".stp";
    request.options.set_threads(2);
    auto a = analyze(request);
    ASSERT_TRUE(a.ok()) << a.status().message();
    analysis_ = std::make_unique<Analysis>(std::move(*a));
    const StepTessellation& t = analysis_->part().tessellation;
    ASSERT_TRUE(t.faithful);
    // The stated distance, computed from the B-rep's doubles, and a margin for the doubles
    // of the directions compared here.
    tolerance_ = t.max_direction_angle + 1e-12;
  }

  // The direction in the part's rotated frame of a direction given in its own frame.
  Vec R(const Vec& v) const { return unit(rotate(GetParam().rotation, v)); }
  Vec local(const std::array<double, 3>& v) const {
    const Rotation& r = GetParam().rotation;
    return {r[0][0] * v[0] + r[1][0] * v[1] + r[2][0] * v[2], r[0][1] * v[0] + r[1][1] * v[1] + r[2][1] * v[2],
            r[0][2] * v[0] + r[1][2] * v[1] + r[2][2] * v[2]};
  }

  // The features of B-rep faces of a type whose axis or normal (in the part's own frame)
  // is `axis` and that `where` accepts (given the face's location in the part's own frame).
  std::vector<const Surface*> faces(CadSurfaceType type, const Vec& axis,
                                    std::function<bool(const Vec&, double)> where = nullptr) const {
    std::vector<const Surface*> out;
    for (const Surface& f : analysis_->features()) {
      if (!f.cad_face || f.cad_face->type != type || !f.cad_face->axis) continue;
      const Vec a = local(*f.cad_face->axis);
      if (std::min(angle_between(a, axis), angle_between(a, neg(axis))) > 1e-9) continue;
      if (where && !where(local(*f.cad_face->location), f.cad_face->radius)) continue;
      out.push_back(&f);
    }
    return out;
  }

  // The GVM is exactly these points, each within the frame distance of its expected direction.
  void expect_points(const Surface& s, const std::vector<Vec>& expected) const {
    ASSERT_TRUE(s.maps.gvm) << s.name;
    const std::vector<DirectionSet> cells = s.maps.gvm->cells();
    ASSERT_EQ(cells.size(), expected.size()) << s.name << ": " << s.maps.gvm->description();
    for (const DirectionSet& c : cells) ASSERT_EQ(c.dimension(), 0) << s.name << ": " << s.maps.gvm->description();
    for (const Vec& e : expected) {
      double best = 10;
      for (const DirectionSet& c : cells) best = std::min(best, angle_between(c.witness().unit(), e));
      EXPECT_LE(best, tolerance_) << s.name << ": " << s.maps.gvm->description();
    }
  }

  // u is in the set or within the frame distance of it.
  bool reaches(const DirectionSet& set, const Vec& u) const { return angle_between(set.snap(u).unit(), u) <= tolerance_ + 1e-15; }

  std::string bytes_;
  std::unique_ptr<Analysis> analysis_;
  double tolerance_ = 0;
};

const Vec kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};

TEST_P(StepParts, HandDerivedMaps) {
  auto radius = [](double r) { return [r](const Vec&, double rr) { return std::fabs(rr - r) < 1e-9; }; };
  auto at_z = [](double z) { return [z](const Vec& p, double) { return std::fabs(p[2] - z) < 1e-6; }; };
  switch (GetParam().part) {
    case Part::kThroughHole: {
      const auto walls = faces(CadSurfaceType::kCylinder, kZ, radius(4));
      ASSERT_FALSE(walls.empty());
      for (const Surface* w : walls) expect_points(*w, {R(kZ), R(neg(kZ))});
      break;
    }
    case Part::kBlindHole: {
      const auto walls = faces(CadSurfaceType::kCylinder, kZ, radius(4));
      ASSERT_FALSE(walls.empty());
      for (const Surface* w : walls) expect_points(*w, {R(kZ)});
      const auto bottom = faces(CadSurfaceType::kPlane, kZ, at_z(4));
      ASSERT_EQ(bottom.size(), 1u);
      expect_points(*bottom[0], {R(kZ)});
      break;
    }
    case Part::kCounterbore: {
      for (const Surface* w : faces(CadSurfaceType::kCylinder, kZ, radius(3))) expect_points(*w, {R(kZ), R(neg(kZ))});
      for (const Surface* w : faces(CadSurfaceType::kCylinder, kZ, radius(6))) expect_points(*w, {R(kZ)});
      const auto step = faces(CadSurfaceType::kPlane, kZ, at_z(6));
      ASSERT_EQ(step.size(), 1u);
      expect_points(*step[0], {R(kZ)});
      ASSERT_FALSE(faces(CadSurfaceType::kCylinder, kZ, radius(3)).empty());
      ASSERT_FALSE(faces(CadSurfaceType::kCylinder, kZ, radius(6)).empty());
      break;
    }
    case Part::kCountersink: {
      const auto bore = faces(CadSurfaceType::kCylinder, kZ, radius(3));
      ASSERT_FALSE(bore.empty());
      for (const Surface* w : bore) expect_points(*w, {R(kZ), R(neg(kZ))});
      const auto cone = faces(CadSurfaceType::kCone, kZ);
      ASSERT_EQ(cone.size(), 1u);
      ASSERT_TRUE(cone[0]->maps.gvm);
      EXPECT_EQ(cone[0]->maps.gvm->dimension(), 2);
      EXPECT_GT(cone[0]->maps.gvm->approx_signed_clearance(R(kZ)), 0.5);  // a cap of about 45 degrees
      EXPECT_LT(cone[0]->maps.gvm->approx_signed_clearance(R(unit({1, 0, 0.5}))), 0);
      break;
    }
    case Part::kThroughSlot: {
      const auto floor = faces(CadSurfaceType::kPlane, kZ, at_z(6));
      ASSERT_EQ(floor.size(), 1u);
      const DirectionSet& gvm = *floor[0]->maps.gvm;
      EXPECT_EQ(gvm.dimension(), 1) << gvm.description();
      for (const Vec& u : {R(kX), R(neg(kX)), R(kZ), R(unit({1, 0, 1})), R(unit({-3, 0, 1}))})
        EXPECT_TRUE(reaches(gvm, u)) << gvm.description();
      EXPECT_FALSE(reaches(gvm, R(unit({0, 0.01, 1})))) << gvm.description();
      EXPECT_FALSE(reaches(gvm, R(unit({1, 0, -0.01})))) << gvm.description();
      for (const DirectionSet& arc : gvm.cells()) {
        ASSERT_EQ(arc.dimension(), 1);
        // On the great circle normal to the walls, within the frame distance.
        EXPECT_LE(std::fabs(M_PI / 2 - angle_between(arc.witness().unit(), R(kY))), tolerance_);
      }
      const auto walls = faces(CadSurfaceType::kPlane, kY, [](const Vec& p, double) {
        return std::fabs(p[1] - 11) < 1e-6 || std::fabs(p[1] - 19) < 1e-6;
      });
      ASSERT_EQ(walls.size(), 2u);
      for (const Surface* w : walls) {
        const DirectionSet& g = *w->maps.gvm;
        EXPECT_EQ(g.dimension(), 2) << w->name << ": " << g.description();
        for (const Vec& u : {R(kX), R(neg(kX)), R(kZ)}) EXPECT_TRUE(reaches(g, u)) << w->name << ": " << g.description();
        const Vec inward = R(local(*w->cad_face->axis)[1] > 0 ? unit({0, 1, 1}) : unit({0, -1, 1}));
        EXPECT_GT(g.approx_signed_clearance(inward), 0) << w->name << ": " << g.description();
      }
      break;
    }
    case Part::kLBracket: {
      const auto along_z = faces(CadSurfaceType::kCylinder, kZ), along_y = faces(CadSurfaceType::kCylinder, kY);
      ASSERT_FALSE(along_z.empty());
      ASSERT_FALSE(along_y.empty());
      for (const Surface* w : along_z) expect_points(*w, {R(kZ), R(neg(kZ))});
      for (const Surface* w : along_y) expect_points(*w, {R(kY), R(neg(kY))});
      break;
    }
    case Part::kBlockedHole: {
      const auto walls = faces(CadSurfaceType::kCylinder, kZ, radius(4));
      ASSERT_FALSE(walls.empty());
      for (const Surface* w : walls) expect_points(*w, {R(neg(kZ))});
      break;
    }
  }
}

// Every relation of the B-rep kept: no point off its plane or ruling, no face left to
// BRepMesh. A rational rotation's directions are kept exactly (up to the rounding of its
// fractions in the file) and the points stay where the B-rep has them; a generic one's
// within 1e-7 rad, the points moved onto its coarser lattices by less than 1% of the
// deflection.
TEST_P(StepParts, TheTessellationKeepsEveryRelation) {
  const StepTessellation& t = analysis_->part().tessellation;
  EXPECT_TRUE(t.inexact.empty()) << t.inexact.size() << " relations, first on face " << t.inexact[0].cad_face;
  EXPECT_TRUE(t.brepmesh_faces.empty()) << "face " << t.brepmesh_faces[0].first << ": " << t.brepmesh_faces[0].second;
  const bool generic = std::string(GetParam().rotation_name) == "generic";
  const double deflection = analysis_->part().linear_deflection;
  EXPECT_LE(t.max_direction_angle, generic ? 1e-7 : 1e-12);
  EXPECT_LT(t.max_node_displacement, (generic ? 1e-2 : 1e-9) * deflection);
  if (GetParam().part != Part::kThroughSlot) EXPECT_GT(t.ruled_faces, 0u);
}

// The relations hold at every deflection: a counterbore and a slot on oblique axes meshed
// finely and coarsely keep their exact answers.
TEST(StepPartsDeflection, TheRelationsHoldAtEveryDeflection) {
  for (auto [linear, angle] : {std::pair{0.005, 5.0}, std::pair{0.5, 30.0}}) {
    for (Part part : {Part::kCounterbore, Part::kThroughSlot}) {
      SCOPED_TRACE(std::string(name_of(part)) + " at " + std::to_string(linear) + " mm, " + std::to_string(angle) + " deg");
      const std::string bytes = step_bytes(part, kOblique);
      AnalyzeRequest request;
      request.part_bytes = bytes;
      request.part_format = MeshFormat::kStep;
      request.part_name = "part.stp";
      request.options.mutable_step()->set_linear_deflection(linear);
      request.options.mutable_step()->set_angular_deflection_degrees(angle);
      auto a = analyze(request);
      ASSERT_TRUE(a.ok()) << a.status().message();
      const StepTessellation& t = a->part().tessellation;
      EXPECT_TRUE(t.inexact.empty());
      EXPECT_TRUE(t.brepmesh_faces.empty());
      for (const Surface& f : a->features()) {
        if (!f.cad_face || !f.maps.gvm) continue;
        const Vec axis = unit(*f.cad_face->axis);
        if (part == Part::kCounterbore && f.cad_face->type == CadSurfaceType::kCylinder) {
          // The bore sees both ways, the counterbore only out of its opening: points all.
          EXPECT_EQ(f.maps.gvm->dimension(), 0) << f.name;
          for (const DirectionSet& c : f.maps.gvm->cells())
            EXPECT_LE(std::min(angle_between(c.witness().unit(), axis), angle_between(c.witness().unit(), neg(axis))),
                      t.max_direction_angle + 1e-12);
        }
      }
      if (part == Part::kThroughSlot) {
        int arcs = 0;
        for (const Surface& f : a->features()) arcs += f.maps.gvm && f.maps.gvm->dimension() == 1;
        EXPECT_EQ(arcs, 1);  // the floor's half circle
      }
    }
  }
}

// The same check fails without the faithful tessellation: BRepMesh's facets of an oblique
// hole lean off its axis, and the walls see nothing.
TEST(StepPartsBrepMesh, TheObliqueHoleIsLostWithoutTheFaithfulTessellation) {
  const std::string bytes = step_bytes(Part::kThroughHole, kOblique);
  AnalyzeRequest request;
  request.part_bytes = bytes;
  request.part_format = MeshFormat::kStep;
  request.part_name = "through_hole_oblique.stp";
  request.options.mutable_step()->set_brepmesh_only(true);
  auto a = analyze(request);
  ASSERT_TRUE(a.ok()) << a.status().message();
  EXPECT_FALSE(a->part().tessellation.faithful);
  int walls = 0, lost = 0;
  for (const Surface& f : a->features())
    if (f.cad_face && f.cad_face->type == CadSurfaceType::kCylinder) ++walls, lost += f.maps.gvm->is_empty();
  EXPECT_GT(walls, 0);
  EXPECT_EQ(lost, walls);
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (Part p : {Part::kThroughHole, Part::kBlindHole, Part::kCounterbore, Part::kCountersink, Part::kThroughSlot,
                 Part::kLBracket, Part::kBlockedHole})
    for (auto [r, name] : {std::pair{kIdentity, "axes"}, std::pair{kOblique, "oblique"}, std::pair{kAboutX, "about_x"},
                           std::pair{generic_rotation(), "generic"}})
      out.push_back({p, r, name});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Made, StepParts, ::testing::ValuesIn(cases()), [](const auto& info) {
  return std::string(name_of(info.param.part)) + "_" + info.param.rotation_name;
});

}  // namespace
}  // namespace gvm::test
