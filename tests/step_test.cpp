// STEP input: every STEP part of ../shared/data/step read, tessellated and welded into a
// closed valid solid with one record per B-rep face; broken files named; the B-rep faces as
// features; and the analysis of a STEP part equal to the analysis of its tessellation
// written as OFF with the B-rep faces as groups.
#include <google/protobuf/util/message_differencer.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stop_token>
#include <thread>

#include "gvm/analysis.h"
#include "gvm/analysis_proto.h"
#include "gvm/planner/plan.h"
#include "gvm/step.h"
#include "support/mesh_files.h"
#include "support/scratch_dir.h"

namespace gvm {
namespace {

std::string step_path(const std::string& name) { return std::string(GVM_SHARED_DIR) + "/data/step/" + name; }

struct GoodPart {
  const char* file;
  size_t brep_faces;                 // from ../shared/data/step/SOURCES.md
  const char* unit;
  std::array<double, 3> box_mm;      // bounding box size after conversion to mm
};

const GoodPart kGoodParts[] = {
    {"bug3883_xr2-ct-214_plate.stp", 18, "millimetre", {180, 150, 20}},
    {"bug3883_xr2-ct-214_l-bracket.stp", 16, "millimetre", {50, 60, 100}},
    {"bm2_ec_lever-A.stp", 49, "metre", {235, 249.9, 86}},
    {"bug27453_165-174_piattello.stp", 313, "millimetre", {114, 107, 74.5}},
    {"r103ec.stp", 146, "metre", {140.2, 153.9, 39}},
    {"trj6_k1-pe-203.stp", 52, "inch", {127, 48.26, 12.71}},
    {"bug32745_pmi1.stp", 30, "millimetre", {20, 10, 6}},
    {"trj10_b2-oc-214.stp", 251, "millimetre", {110.5, 98.02, 68}},
    {"bug25169_box-openshell.stp", 6, "millimetre", {20, 20, 20}},  // OCCT heals the open shell
};

std::array<double, 3> box_size(const RawMesh& mesh) {
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const Point3& p : mesh.points) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  }
  return {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
}

TEST(StepRead, EveryGoodPartIsAClosedValidSolidWithEveryBrepFace) {
  for (const GoodPart& g : kGoodParts) {
    SCOPED_TRACE(g.file);
    StatusOr<StepPart> part = read_step(step_path(g.file), {});
    ASSERT_TRUE(part.ok()) << part.status().message();
    EXPECT_EQ(part->cad_faces.size(), g.brep_faces);
    EXPECT_EQ(part->file_unit, g.unit);
    // Every B-rep face has triangles, and the mesh faces know theirs.
    ASSERT_EQ(part->face_cad.size(), part->mesh.faces.size());
    EXPECT_EQ(std::set<uint32_t>(part->face_cad.begin(), part->face_cad.end()).size(), g.brep_faces);
    // Closed, manifold, oriented outward, no self-intersection: our own validation.
    StatusOr<SolidMesh> solid = build_solid(part->mesh);
    EXPECT_TRUE(solid.ok()) << solid.status().message();
    // Millimetres whatever the file's unit (the sizes of SOURCES.md are OCCT's exact box,
    // the tessellation's points lie on the surfaces: within the deflection).
    const std::array<double, 3> size = box_size(part->mesh);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(size[i], g.box_mm[i], 0.01 * g.box_mm[i] + 0.2) << "axis " << i;
  }
}

TEST(StepRead, BrokenFilesAreRejectedNamingTheProblem) {
  auto message = [](const StatusOr<StepPart>& r) { return r.ok() ? std::string("(read)") : r.status().message(); };
  const StatusOr<StepPart> open = read_step(step_path("bug25415_part_of_hdrv8w64p254_4x2_1016x502h838p.stp"), {});
  EXPECT_EQ(open.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(message(open).find("no solid"), std::string::npos) << message(open);
  EXPECT_NE(message(open).find("free edges"), std::string::npos) << message(open);

  const StatusOr<StepPart> corrupted = read_step(step_path("bug32314_corrupted.stp"), {});
  EXPECT_NE(message(corrupted).find("11 solids"), std::string::npos) << message(corrupted);
  EXPECT_NE(message(corrupted).find("damaged"), std::string::npos) << message(corrupted);
  EXPECT_NE(message(corrupted).find("--solid N"), std::string::npos) << message(corrupted);
  StepOptions eleventh;
  eleventh.solid = 11;
  const std::string out_of_range = message(read_step(step_path("bug32314_corrupted.stp"), eleventh));
  EXPECT_NE(out_of_range.find("solid 11 asked for"), std::string::npos) << out_of_range;
  EXPECT_NE(out_of_range.find("(0..10)"), std::string::npos) << out_of_range;

  EXPECT_EQ(read_step(step_path("no-such-part.stp"), {}).status().code(), StatusCode::kNotFound);
  const StatusOr<StepPart> garbage = read_step(std::string_view("ISO-10303-21;\nHEADER;\ngarbage"), {}, "garbage.stp");
  EXPECT_NE(message(garbage).find("garbage.stp"), std::string::npos) << message(garbage);
  EXPECT_FALSE(garbage.ok());
  EXPECT_FALSE(read_step(std::string_view(""), {}, "empty.stp").ok());
}

TEST(StepRead, BytesInMemoryGiveTheSameMesh) {
  const std::string path = step_path("bug32745_pmi1.stp");
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  StatusOr<StepPart> a = read_step(path, {}), b = read_step(bytes, {}, "pmi1.stp");
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->mesh.faces, b->mesh.faces);
  ASSERT_EQ(a->mesh.points.size(), b->mesh.points.size());
  for (size_t i = 0; i < a->mesh.points.size(); ++i) {
    EXPECT_EQ(a->mesh.points[i].x, b->mesh.points[i].x);
    EXPECT_EQ(a->mesh.points[i].y, b->mesh.points[i].y);
    EXPECT_EQ(a->mesh.points[i].z, b->mesh.points[i].z);
  }
}

// A stop request ends the reading: before it starts, and while the largest shared STEP
// part (0.8 s to read and mesh) is being translated or meshed.
TEST(StepRead, AStopRequestEndsTheReading) {
  std::stop_source before;
  before.request_stop();
  StepOptions options;
  options.stop = before.get_token();
  StatusOr<StepPart> stopped = read_step(step_path("bug32745_pmi1.stp"), options);
  ASSERT_FALSE(stopped.ok());
  EXPECT_EQ(stopped.status().code(), StatusCode::kCancelled) << stopped.status().message();

  std::stop_source during;
  options.stop = during.get_token();
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    during.request_stop();
  });
  const auto start = std::chrono::steady_clock::now();
  stopped = read_step(step_path("bug27453_165-174_piattello.stp"), options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stopper.join();
  ASSERT_FALSE(stopped.ok());
  EXPECT_EQ(stopped.status().code(), StatusCode::kCancelled) << stopped.status().message();
  std::printf("piattello: stopped after 0.1 s, read_step returned after %.2f s\n", seconds);
}

// A face limit is checked before the mesh is built: on the B-rep faces before meshing, on
// BRepMesh's triangles before welding, naming the counts and the limit.
TEST(StepRead, AFaceLimitStopsTheReadingBeforeTheMeshIsBuilt) {
  StatusOr<StepPart> all = read_step(step_path("bug32745_pmi1.stp"), StepOptions{});
  ASSERT_TRUE(all.ok()) << all.status().message();
  const uint32_t faces = static_cast<uint32_t>(all->cad_faces.size());
  const uint32_t triangles = static_cast<uint32_t>(all->mesh.faces.size());
  ASSERT_LT(faces, triangles);
  StepOptions options;
  options.max_triangles = faces - 1;
  StatusOr<StepPart> few = read_step(step_path("bug32745_pmi1.stp"), options);
  ASSERT_FALSE(few.ok());
  EXPECT_EQ(few.status().code(), StatusCode::kResourceExhausted);
  EXPECT_NE(few.status().message().find(std::to_string(faces) + " B-rep faces"), std::string::npos)
      << few.status().message();
  options.max_triangles = triangles - 1;
  StatusOr<StepPart> meshed = read_step(step_path("bug32745_pmi1.stp"), options);
  ASSERT_FALSE(meshed.ok());
  EXPECT_EQ(meshed.status().code(), StatusCode::kResourceExhausted);
  EXPECT_NE(meshed.status().message().find("limit of " + std::to_string(triangles - 1)), std::string::npos)
      << meshed.status().message();
  options.max_triangles = triangles;
  EXPECT_TRUE(read_step(step_path("bug32745_pmi1.stp"), options).ok());
}

Analysis analyzed(AnalyzeRequest request) {
  auto a = analyze(request);
  EXPECT_TRUE(a.ok()) << a.status().message();
  return std::move(*a);
}

// The features are the B-rep faces, each with its CAD face; a STEP part analysed equals
// its tessellation analysed as an OFF file with the B-rep faces as groups, map for map.
void expect_same_as_its_tessellation(const std::string& file) {
  SCOPED_TRACE(file);
  StatusOr<StepPart> part = read_step(step_path(file), {});
  ASSERT_TRUE(part.ok()) << part.status().message();
  AnalyzeRequest from_step;
  from_step.part_path = step_path(file);
  const v1::Analysis step = to_proto(analyzed(from_step));
  ASSERT_EQ(static_cast<size_t>(step.features_size()), part->cad_faces.size());
  for (const v1::Feature& f : step.features()) {
    ASSERT_TRUE(f.has_cad_face()) << f.name();
    EXPECT_EQ(f.cad_face().index(), f.id()) << "features come in B-rep face order";
    for (uint32_t face : f.faces()) EXPECT_EQ(part->face_cad[face], f.cad_face().index());
    EXPECT_EQ(f.cad_face().surface_type(), name_of(part->cad_faces[f.id()].type));
  }
  EXPECT_EQ(step.part().cad_faces(), part->cad_faces.size());
  // A hole's GVM point is its B-rep axis, up to the rounding of the printed doubles.
  for (const v1::Feature& f : step.features()) {
    if (f.cad_face().surface_type() != "cylinder") continue;
    const v1::Vec3& a = f.cad_face().axis();
    for (const v1::Vec3& p : f.gvm().points()) {
      EXPECT_GT(std::fabs(p.x() * a.x() + p.y() * a.y() + p.z() * a.z()), 1 - 1e-12) << f.name();
    }
  }

  std::ostringstream groups;
  groups << "{";
  bool first = true;
  for (const auto& [name, faces] : brep_face_groups(*part)) {
    groups << (first ? "" : ",") << "\"" << name << "\":[";
    for (size_t i = 0; i < faces.size(); ++i) groups << (i ? "," : "") << faces[i];
    groups << "]";
    first = false;
  }
  groups << "}";
  AnalyzeRequest from_off;
  from_off.part_path = test::write_off(part->mesh, test::scratch_dir() / (file + ".off"));
  from_off.groups_json = groups.str();
  const v1::Analysis off = to_proto(analyzed(from_off));
  ASSERT_EQ(off.features_size(), step.features_size());
  ASSERT_EQ(off.regions_size(), step.regions_size());
  for (int i = 0; i < step.features_size(); ++i) {
    EXPECT_EQ(off.features(i).name(), step.features(i).name());
    EXPECT_EQ(off.features(i).faces_size(), step.features(i).faces_size());
    EXPECT_TRUE(google::protobuf::util::MessageDifferencer::Equals(off.features(i).gvm(), step.features(i).gvm()))
        << step.features(i).name();
    EXPECT_TRUE(google::protobuf::util::MessageDifferencer::Equals(off.features(i).lvm(), step.features(i).lvm()))
        << step.features(i).name();
  }
  for (int i = 0; i < step.regions_size(); ++i) {
    EXPECT_TRUE(google::protobuf::util::MessageDifferencer::Equals(off.regions(i).gvm(), step.regions(i).gvm()));
  }
}

// Two parts whose analysis takes about a second (the label-long test StepPlan.AllParts
// covers the rest).
TEST(StepAnalysis, FeaturesAreTheBrepFacesAndTheMapsThoseOfTheTessellation) {
  expect_same_as_its_tessellation("bug32745_pmi1.stp");
  expect_same_as_its_tessellation("bm2_ec_lever-A.stp");
}

// The planner on STEP parts: every feature (a B-rep face) planned in one setup whose exact
// direction is in its GVM, or unreachable with a reason.
TEST(StepPlan, SmallPartsArePlanned) {
  for (const char* file : {"bug25169_box-openshell.stp", "bug32745_pmi1.stp", "bm2_ec_lever-A.stp"}) {
    SCOPED_TRACE(file);
    AnalyzeRequest request;
    request.part_path = step_path(file);
    const Analysis analysis = analyzed(request);
    StatusOr<planner::SetupPlan> plan = planner::plan(analysis, {});
    ASSERT_TRUE(plan.ok()) << plan.status().message();
    const v1::Plan& p = plan->message;
    EXPECT_GE(p.setups_size(), 1);
    EXPECT_EQ(p.reached() + p.unreachable_count(), analysis.features().size());
    EXPECT_TRUE(p.optimal()) << p.lower_bound() << " < " << p.setups_size();
    for (const v1::PlannedSurface& s : p.surfaces()) {
      if (s.setup() < 0) continue;
      const Direction& d = plan->directions[s.setup()];
      ASSERT_TRUE(analysis.features()[s.id()].maps.gvm.has_value());
      EXPECT_TRUE(analysis.features()[s.id()].maps.gvm->contains(d)) << s.name();
    }
  }
}

// What a machinist expects of the shared parts, which BRepMesh's leaning facets denied: the
// plate in two setups, +z with its top, sides and hole walls and -z with its bottom; every
// hole wall of the L-bracket reached along its own axis; nothing of pmi1 unreachable (its
// counterbores' steps and bores from the top).
TEST(StepPlan, HoleWallsAreReachedAlongTheirAxes) {
  auto plan_of = [](const char* file) {
    AnalyzeRequest request;
    request.part_path = step_path(file);
    Analysis analysis = analyzed(request);
    StatusOr<planner::SetupPlan> plan = planner::plan(analysis, {});
    EXPECT_TRUE(plan.ok()) << plan.status().message();
    return std::pair{std::move(analysis), std::move(*plan)};
  };
  {
    auto [analysis, plan] = plan_of("bug3883_xr2-ct-214_plate.stp");
    EXPECT_EQ(plan.message.unreachable_count(), 0u);
    ASSERT_EQ(plan.directions.size(), 2u);
    EXPECT_TRUE(plan.message.optimal());
    for (const v1::PlannedSurface& s : plan.message.surfaces()) {
      const CadFace& cad = *analysis.features()[s.id()].cad_face;
      const auto u = plan.directions[s.setup()].unit();
      const bool bottom = cad.type == CadSurfaceType::kPlane && (*cad.axis)[2] < -0.5;
      EXPECT_EQ(u[2], bottom ? -1.0 : 1.0) << s.name();
    }
  }
  {
    auto [analysis, plan] = plan_of("bug3883_xr2-ct-214_l-bracket.stp");
    EXPECT_EQ(plan.message.unreachable_count(), 0u);
    for (const v1::PlannedSurface& s : plan.message.surfaces()) {
      const CadFace& cad = *analysis.features()[s.id()].cad_face;
      if (cad.type != CadSurfaceType::kCylinder) continue;
      const auto u = plan.directions[s.setup()].unit();
      const double along = u[0] * (*cad.axis)[0] + u[1] * (*cad.axis)[1] + u[2] * (*cad.axis)[2];
      EXPECT_EQ(std::fabs(along), 1.0) << s.name();
      // The wall's GVM is exactly its axis both ways.
      EXPECT_EQ(analysis.features()[s.id()].maps.gvm->cells().size(), 2u) << s.name();
    }
  }
  {
    auto [analysis, plan] = plan_of("bug32745_pmi1.stp");
    EXPECT_EQ(plan.message.unreachable_count(), 0u);
  }
}

// The plate's six through holes are each two half-cylinders about a vertical axis.
TEST(StepHoles, ThePlatesHolesAreFoundWithTheirAxes) {
  StepOptions options;
  options.group_holes = true;
  StatusOr<StepPart> part = read_step(step_path("bug3883_xr2-ct-214_plate.stp"), options);
  ASSERT_TRUE(part.ok()) << part.status().message();
  ASSERT_EQ(part->holes.size(), 6u);
  std::set<uint32_t> seen;
  for (const CadHole& h : part->holes) {
    EXPECT_EQ(h.faces.size(), 2u);
    EXPECT_EQ(h.radius, 5);
    EXPECT_EQ(std::fabs(h.axis[2]), 1);
    for (uint32_t f : h.faces) {
      EXPECT_EQ(part->cad_faces[f].type, CadSurfaceType::kCylinder);
      EXPECT_TRUE(seen.insert(f).second) << "face " << f << " is in two holes";
    }
  }
  EXPECT_EQ(read_step(step_path("bug3883_xr2-ct-214_plate.stp"), {})->holes.size(), 0u) << "only when asked";
}

// A hole's faces as one feature: by Def. 2, a direction sees the union of faces iff it sees
// each of them, so the hole's GVM is exactly the intersection of its faces' GVMs; every
// other feature keeps its face's GVM.
Analysis expect_holes_see_what_their_faces_see(const std::string& file, size_t holes) {
  SCOPED_TRACE(file);
  AnalyzeRequest by_face, by_hole;
  by_face.part_path = by_hole.part_path = step_path(file);
  by_hole.options.mutable_step()->set_group_holes(true);
  const Analysis faces = analyzed(by_face);
  Analysis grouped = analyzed(by_hole);
  std::map<uint32_t, const Surface*> of_cad_face;
  for (const Surface& f : faces.features()) of_cad_face[f.cad_face->index] = &f;
  size_t found = 0, faces_in_holes = 0;
  for (const Surface& f : grouped.features()) {
    if (f.cad_face.has_value() == f.cad_hole.has_value() || !f.maps.gvm) {
      ADD_FAILURE() << f.name << ": not exactly one of a B-rep face and a hole, or no GVM";
      continue;
    }
    if (f.cad_face) {
      EXPECT_EQ(*f.maps.gvm, *of_cad_face.at(f.cad_face->index)->maps.gvm) << f.name;
      continue;
    }
    ++found;
    faces_in_holes += f.cad_hole->faces.size();
    DirectionSet every_face = DirectionSet::full_sphere();
    for (uint32_t c : f.cad_hole->faces) {
      const Surface& face = *of_cad_face.at(c);
      every_face = every_face.intersection(*face.maps.gvm);
      EXPECT_TRUE(std::includes(f.faces.begin(), f.faces.end(), face.faces.begin(), face.faces.end())) << face.name;
    }
    EXPECT_EQ(*f.maps.gvm, every_face) << f.name << ": " << f.maps.gvm->description() << " vs "
                                       << every_face.description();
  }
  EXPECT_EQ(found, holes);
  EXPECT_EQ(grouped.features().size() + faces_in_holes - found, faces.features().size());
  return grouped;
}

TEST(StepHoles, AHolesGvmIsWhatEveryOneOfItsFacesSees) {
  expect_holes_see_what_their_faces_see("bug32745_pmi1.stp", 2);
  // The lever's two blind holes (wall and flat bottom) are reached along their axis only.
  const Analysis lever = expect_holes_see_what_their_faces_see("bm2_ec_lever-A.stp", 2);
  for (const Surface& f : lever.features()) {
    if (!f.cad_hole) continue;
    ASSERT_EQ(f.maps.gvm->dimension(), 0) << f.name;
    const std::array<double, 3>& a = f.cad_hole->axis;
    EXPECT_TRUE(*f.maps.gvm == DirectionSet::point(Direction(a[0], a[1], a[2])) ||
                *f.maps.gvm == DirectionSet::point(Direction(-a[0], -a[1], -a[2])))
        << f.name << ": " << f.maps.gvm->description();
  }
}

TEST(StepHoles, GroupingHolesNeedsBrepFeatures) {
  AnalyzeRequest request;
  request.part_path = step_path("bug32745_pmi1.stp");
  request.options.mutable_step()->set_group_holes(true);
  request.options.mutable_step()->set_features(v1::STEP_FEATURES_AUTO);
  auto a = analyze(request);
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(a.status().message().find("step.group_holes"), std::string::npos) << a.status().message();
}

TEST(StepAnalysis, AutoFeaturesGroupTheMesh) {
  AnalyzeRequest request;
  request.part_path = step_path("bug32745_pmi1.stp");
  request.options.mutable_step()->set_features(v1::STEP_FEATURES_AUTO);
  const v1::Analysis a = to_proto(analyzed(request));
  EXPECT_NE(a.features_size(), 30);
  for (const v1::Feature& f : a.features()) EXPECT_EQ(f.name(), "F" + std::to_string(f.id()));
}

}  // namespace
}  // namespace gvm
