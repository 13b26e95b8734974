// Part analysis on exact test parts: hull facets, concave regions, features, N_S, O_S,
// face group files.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <random>
#include <set>

#include "exact/predicates.h"
#include "gvm/part.h"
#include "support/scratch_dir.h"
#include "support/test_parts.h"

namespace gvm {
namespace {

using test::TestPartOptions;

std::vector<TestPartOptions> all_options() {
  std::vector<TestPartOptions> out;
  for (int rot = 0; rot < 3; ++rot)
    for (int mode = 0; mode < 3; ++mode) {
      TestPartOptions o;
      o.rotation = rot;
      o.split = mode == 1;
      o.quads = mode == 2;
      out.push_back(o);
    }
  return out;
}

std::string describe(const std::string& name, const TestPartOptions& o) {
  return name + " rot=" + std::to_string(o.rotation) + (o.split ? " split" : "") +
         (o.quads ? " quads" : "");
}

SolidMesh solid(const RawMesh& raw) {
  auto s = build_solid(raw);
  EXPECT_TRUE(s.ok()) << s.status().message();
  return s.ok() ? std::move(s).value() : SolidMesh{};
}

Part analyze(const RawMesh& raw, PartOptions opt = {}) {
  auto p = Part::analyze(solid(raw), opt);
  EXPECT_TRUE(p.ok()) << p.status().message();
  return std::move(p).value();
}

// Brute force: a triangle is a hull facet iff every vertex is on its closed negative side.
std::vector<bool> brute_force_hull(const SolidMesh& m) {
  std::vector<bool> used(m.points.size(), false);
  for (const Triangle& t : m.triangles)
    for (uint32_t v : t) used[v] = true;
  std::vector<bool> out(m.triangles.size(), true);
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const Triangle& tr = m.triangles[t];
    for (size_t v = 0; v < m.points.size() && out[t]; ++v)
      if (used[v] && exact::orient3d(m.points[tr[0]], m.points[tr[1]], m.points[tr[2]],
                                     m.points[v]) == Sign::kPositive)
        out[t] = false;
  }
  return out;
}

std::vector<uint32_t> sorted_union(std::vector<uint32_t> a, const std::vector<uint32_t>& b) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  return a;
}

// Feature partition as sets of input faces (comparable across rotations).
std::set<std::set<uint32_t>> face_partition(const Part& p) {
  std::set<std::set<uint32_t>> out;
  for (const Feature& f : p.features()) {
    std::set<uint32_t> faces;
    for (uint32_t t : f.triangles) faces.insert(p.mesh().triangle_face[t]);
    out.insert(faces);
  }
  return out;
}

std::set<std::set<uint32_t>> group_partition(const RawMesh& raw) {
  std::set<std::set<uint32_t>> out;
  for (const auto& [name, faces] : raw.groups) out.insert({faces.begin(), faces.end()});
  return out;
}

// O_S straight from the definition, for cross-checking the pruned search.
std::vector<uint32_t> brute_force_potential(const Part& p, const std::vector<uint32_t>& s,
                                            const std::vector<uint32_t>& n) {
  const SolidMesh& m = p.mesh();
  auto P = [&](uint32_t t, int i) -> const Point3& { return m.points[m.triangles[t][i]]; };
  std::vector<uint32_t> out;
  for (uint32_t f = 0; f < m.triangles.size(); ++f) {
    if (p.is_hull(f) || std::binary_search(s.begin(), s.end(), f) ||
        std::binary_search(n.begin(), n.end(), f))
      continue;
    for (uint32_t fs : s) {
      if (p.region_of(fs) != p.region_of(f)) continue;
      bool c1 = false, c2 = false;
      for (int k = 0; k < 3; ++k) {
        c1 |= exact::orient3d(P(f, 0), P(f, 1), P(f, 2), P(fs, k)) == Sign::kPositive;
        c2 |= exact::orient3d(P(fs, 0), P(fs, 1), P(fs, 2), P(f, k)) != Sign::kNegative;
      }
      if (c1 && c2) {
        out.push_back(f);
        break;
      }
    }
  }
  return out;
}

bool triangle_mode(const TestPartOptions& o) { return !o.split && !o.quads; }

bool subset(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
  return std::includes(b.begin(), b.end(), a.begin(), a.end());
}

std::vector<uint32_t> minus(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
  std::vector<uint32_t> out;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

const auto kAll = [](uint32_t) { return true; };

TEST(PartHull, MatchesBruteForceOnTestParts) {
  for (const auto& tp : test::all_test_parts())
    for (const TestPartOptions& o : all_options()) {
      RawMesh raw = tp.make(o);
      Part p = analyze(raw);
      auto bf = brute_force_hull(p.mesh());
      for (uint32_t t = 0; t < bf.size(); ++t)
        ASSERT_EQ(p.is_hull(t), bf[t]) << describe(tp.name, o) << " triangle " << t;
    }
}

TEST(PartHull, BoxIsAllHull) {
  Part p = analyze(test::box_part({.rotation = 2, .split = true}));
  for (uint32_t t = 0; t < p.mesh().triangles.size(); ++t) EXPECT_TRUE(p.is_hull(t));
  EXPECT_TRUE(p.regions().empty());
  EXPECT_EQ(p.features().size(), 6u);
  for (const Feature& f : p.features()) {
    EXPECT_TRUE(f.on_hull);
    EXPECT_EQ(f.region, -1);
  }
}

// The concave surfaces of each part, by group name: exactly the non-hull triangles, in
// the expected number of regions.
TEST(PartRegions, TestPartsHaveTheExpectedRegions) {
  struct Case {
    std::string part;
    std::vector<std::vector<std::string>> regions;
  };
  const std::vector<Case> cases = {
      {"slot", {{"floor", "wall_x0", "wall_x1"}}},
      {"through_hole", {{"wall_x0", "wall_x1", "wall_y0", "wall_y1"}}},
      {"pocket", {{"floor", "wall_x0", "wall_x1", "wall_y0", "wall_y1"}}},
      {"drafted_pocket", {{"floor", "wall_x0", "wall_x1", "wall_y0", "wall_y1"}}},
      {"step", {{"step_floor", "riser"}}},
      {"tslot_open",
       {{"floor", "wall_x0", "wall_x1", "lip_underside_0", "lip_underside_1", "neck_x0",
         "neck_x1"}}},
      {"tslot_closed",
       {{"floor", "wall_x0", "wall_x1", "lip_underside_0", "lip_underside_1", "neck_x0",
         "neck_x1", "end_y0", "end_y1"}}},
      {"two_pockets",
       {{"floor_0", "p0_wall_x0", "p0_wall_x1", "p0_wall_y0", "p0_wall_y1"},
        {"floor_1", "p1_wall_x0", "p1_wall_x1", "p1_wall_y0", "p1_wall_y1"}}},
  };
  std::map<std::string, test::NamedTestPart> parts;
  for (const auto& tp : test::all_test_parts()) parts.emplace(tp.name, tp);
  for (const Case& c : cases)
    for (const TestPartOptions& o : all_options()) {
      RawMesh raw = parts.at(c.part).make(o);
      Part p = analyze(raw);
      ASSERT_EQ(p.regions().size(), c.regions.size()) << describe(c.part, o);
      std::vector<uint32_t> all_concave;
      for (size_t r = 0; r < c.regions.size(); ++r) {
        std::vector<uint32_t> expect;
        for (const std::string& g : c.regions[r]) {
          ASSERT_TRUE(raw.groups.count(g)) << c.part << " has no group " << g;
          expect = sorted_union(expect, test::triangles_of_faces(p.mesh(), raw.groups.at(g)));
        }
        EXPECT_EQ(p.regions()[r].triangles, expect) << describe(c.part, o) << " region " << r;
        EXPECT_FALSE(p.regions()[r].is_void);
        for (uint32_t t : expect) EXPECT_EQ(p.region_of(t), int32_t(r));
        all_concave = sorted_union(all_concave, expect);
      }
      for (uint32_t t = 0; t < p.mesh().triangles.size(); ++t)
        EXPECT_EQ(!p.is_hull(t), std::binary_search(all_concave.begin(), all_concave.end(), t))
            << describe(c.part, o) << " triangle " << t;
    }
}

TEST(PartRegions, VoidShellIsItsOwnRegion) {
  for (const TestPartOptions& o : all_options()) {
    RawMesh raw = test::pocket_with_void_part(o);
    Part p = analyze(raw);
    const SolidMesh& m = p.mesh();
    ASSERT_EQ(p.regions().size(), 2u) << describe(raw.source, o);
    auto pocket = test::triangles_of(m, raw, {"floor", "wall_x0", "wall_x1", "wall_y0", "wall_y1"});
    auto cavity = test::triangles_of(m, raw, {"void_x0", "void_x1", "void_y0", "void_y1",
                                              "void_z0", "void_z1"});
    EXPECT_EQ(p.regions()[0].triangles, pocket);
    EXPECT_FALSE(p.regions()[0].is_void);
    EXPECT_EQ(p.regions()[1].triangles, cavity);
    EXPECT_TRUE(p.regions()[1].is_void);
    // Occluders never cross between the void and the outer surface.
    auto s = test::triangles_of(m, raw, {"void_x0"});
    auto n = p.neighbor_occluders(s);
    EXPECT_TRUE(subset(n, cavity));
    auto o_s = p.potential_occluders(s, n, kAll);
    EXPECT_EQ(o_s, minus(minus(cavity, s), n)) << describe(raw.source, o);
    auto w = test::triangles_of(m, raw, {"wall_x1"});
    auto o_w = p.potential_occluders(w, p.neighbor_occluders(w), kAll);
    EXPECT_TRUE(subset(o_w, pocket));
    EXPECT_FALSE(o_w.empty());
  }
}

TEST(PartFeatures, EveryPlanarFaceIsOneFeature) {
  for (const auto& tp : test::all_test_parts()) {
    std::set<std::set<uint32_t>> first;
    for (const TestPartOptions& o : all_options()) {
      RawMesh raw = tp.make(o);
      Part p = analyze(raw);
      auto part = face_partition(p);
      EXPECT_EQ(part, group_partition(raw)) << describe(tp.name, o);
      // Rotations give identical partitions (input faces are numbered alike).
      if (o.rotation == 0 && !o.split && !o.quads) first = part;
      if (!o.split && !o.quads) EXPECT_EQ(part, first) << describe(tp.name, o);
      // Ids, names, order, consistency.
      uint32_t prev_min = 0;
      for (size_t i = 0; i < p.features().size(); ++i) {
        const Feature& f = p.features()[i];
        EXPECT_EQ(f.id, i);
        EXPECT_EQ(f.name, "F" + std::to_string(i));
        ASSERT_FALSE(f.triangles.empty());
        EXPECT_TRUE(std::is_sorted(f.triangles.begin(), f.triangles.end()));
        if (i > 0) EXPECT_GT(f.triangles.front(), prev_min);
        prev_min = f.triangles.front();
        for (uint32_t t : f.triangles) {
          EXPECT_EQ(p.is_hull(t), f.on_hull);
          EXPECT_EQ(p.region_of(t), f.region);
        }
      }
    }
  }
}

TEST(PartFeatures, RotatedSplitPartsGiveIdenticalFeatureTriangles) {
  for (const auto& tp : test::all_test_parts()) {
    Part a = analyze(tp.make({.rotation = 0, .split = true}));
    for (int rot : {1, 2}) {
      Part b = analyze(tp.make({.rotation = rot, .split = true}));
      ASSERT_EQ(a.features().size(), b.features().size()) << tp.name;
      for (size_t i = 0; i < a.features().size(); ++i)
        EXPECT_EQ(a.features()[i].triangles, b.features()[i].triangles) << tp.name;
    }
  }
}

TEST(PartFeatures, UserGroupsBecomeFeatures) {
  RawMesh raw = test::pocket_part({.rotation = 1, .split = true});
  PartOptions opt;
  opt.face_groups["walls"] = test::faces_of(raw, {"wall_x0", "wall_x1", "wall_y0", "wall_y1"});
  opt.face_groups["floor"] = raw.groups.at("floor");
  Part p = analyze(raw, opt);
  std::map<std::string, const Feature*> by_name;
  for (const Feature& f : p.features()) by_name[f.name] = &f;
  ASSERT_TRUE(by_name.count("walls"));
  ASSERT_TRUE(by_name.count("floor"));
  EXPECT_EQ(by_name["walls"]->triangles, test::triangles_of(p.mesh(), raw,
                                                           {"wall_x0", "wall_x1", "wall_y0", "wall_y1"}));
  EXPECT_EQ(by_name["walls"]->region, 0);
  EXPECT_FALSE(by_name["walls"]->on_hull);
  // Remaining faces are grouped automatically: top + 4 sides + bottom.
  EXPECT_EQ(p.features().size(), 2u + 6u);
  for (const Feature& f : p.features())
    if (f.name != "walls" && f.name != "floor") {
      EXPECT_EQ(f.name, "F" + std::to_string(f.id));
      EXPECT_TRUE(f.on_hull);
      EXPECT_EQ(f.region, -1);
    }

  // A group mixing hull and non-hull faces takes the region of its first non-hull one.
  PartOptions mixed;
  mixed.face_groups["mixed"] = test::faces_of(raw, {"top", "floor"});
  Part q = analyze(raw, mixed);
  for (const Feature& f : q.features())
    if (f.name == "mixed") {
      EXPECT_EQ(f.region, 0);
      EXPECT_FALSE(f.on_hull);
    }

  PartOptions bad;
  bad.face_groups["a"] = {0, 1};
  bad.face_groups["b"] = {1};
  EXPECT_FALSE(Part::analyze(solid(raw), bad).ok());
  bad.face_groups["b"] = {uint32_t(raw.faces.size())};
  EXPECT_FALSE(Part::analyze(solid(raw), bad).ok());
}

TEST(PartFeatures, NeverSplitsAnInputFace) {
  // With an angle of 0 nothing merges across edges, so every feature is exactly one
  // input face (the quads are split into two triangles each by build_solid).
  for (const auto& tp : test::all_test_parts()) {
    RawMesh raw = tp.make({.rotation = 2, .quads = true});
    PartOptions opt;
    opt.feature_angle_degrees = 0;
    Part p = analyze(raw, opt);
    EXPECT_EQ(p.features().size(), raw.faces.size()) << tp.name;
    for (const Feature& f : p.features()) {
      std::set<uint32_t> faces;
      for (uint32_t t : f.triangles) faces.insert(p.mesh().triangle_face[t]);
      EXPECT_EQ(faces.size(), 1u);
    }
  }
}

// ---- N_S -----------------------------------------------------------------------------

// N_S straight from the definition (O(F * T)), for cross-checking.
std::vector<uint32_t> brute_force_neighbors(const Part& p, const std::vector<uint32_t>& s) {
  const SolidMesh& m = p.mesh();
  auto pt = [&](uint32_t t, int i) -> const Point3& { return m.points[m.triangles[t][i]]; };
  std::vector<uint32_t> out;
  for (uint32_t f = 0; f < m.triangles.size(); ++f) {
    if (std::binary_search(s.begin(), s.end(), f)) continue;
    bool in = false;
    for (uint32_t t : s) {
      std::set<uint32_t> tv(m.triangles[t].begin(), m.triangles[t].end());
      int shared = 0;
      for (uint32_t v : m.triangles[f]) shared += tv.count(v);
      if (shared == 2)  // an edge: concave iff the far vertex of f is in front of t
        for (uint32_t v : m.triangles[f])
          if (!tv.count(v) && exact::orient3d(pt(t, 0), pt(t, 1), pt(t, 2), m.points[v]) ==
                                  Sign::kPositive)
            in = true;
      for (uint32_t v : m.triangles[f]) {
        if (!tv.count(v)) continue;
        bool covers = true;
        for (const Triangle& u : m.triangles)
          for (int i = 0; i < 3; ++i)
            if (u[i] == v && exact::det_diff(pt(f, 0), pt(f, 1), pt(f, 0), pt(f, 2),
                                             m.points[v], m.points[u[(i + 1) % 3]]) ==
                                 Sign::kNegative)
              covers = false;
        in |= covers;
      }
    }
    if (in) out.push_back(f);
  }
  return out;
}

// Checks N_S against the brute force, and against `expect`: exact in triangle mode when
// `closed` (every corner of S is concave in all directions, as in a pocket), an upper
// bound otherwise: with split faces only the triangles touching S are in N_S, and at the
// open ends of a slot or step a triangle touching S at one vertex is not (the end face
// goes down behind it).
void check_neighbors(const Part& p, const RawMesh& raw, const TestPartOptions& o,
                     std::initializer_list<std::string> s_names,
                     std::initializer_list<std::string> expect_names, bool closed = true) {
  auto s = test::triangles_of(p.mesh(), raw, s_names);
  auto expect = test::triangles_of(p.mesh(), raw, expect_names);
  auto n = p.neighbor_occluders(s);
  EXPECT_EQ(n, brute_force_neighbors(p, s)) << describe(raw.source, o);
  if (closed && triangle_mode(o))
    EXPECT_EQ(n, expect) << describe(raw.source, o);
  else
    EXPECT_TRUE(subset(n, expect)) << describe(raw.source, o);
  if (!expect.empty()) EXPECT_FALSE(n.empty()) << describe(raw.source, o);
}

TEST(PartNeighbors, PocketStepSlot) {
  for (const TestPartOptions& o : all_options()) {
    for (bool drafted : {false, true}) {
      RawMesh raw = drafted ? test::drafted_pocket_part(o) : test::pocket_part(o);
      Part p = analyze(raw);
      check_neighbors(p, raw, o, {"floor"}, {"wall_x0", "wall_x1", "wall_y0", "wall_y1"});
      check_neighbors(p, raw, o, {"wall_x0"}, {"floor", "wall_y0", "wall_y1"});
      // The whole region: nothing outside shares a concave edge or covers a vertex.
      check_neighbors(p, raw, o, {"floor", "wall_x0", "wall_x1", "wall_y0", "wall_y1"}, {});
      check_neighbors(p, raw, o, {"top"}, {});
    }
    {
      RawMesh raw = test::step_part(o);
      Part p = analyze(raw);
      check_neighbors(p, raw, o, {"step_floor"}, {"riser"}, false);
      check_neighbors(p, raw, o, {"riser"}, {"step_floor"}, false);
      check_neighbors(p, raw, o, {"top"}, {});  // convex edge with the riser
    }
    {
      RawMesh raw = test::slot_part(o);
      Part p = analyze(raw);
      check_neighbors(p, raw, o, {"floor"}, {"wall_x0", "wall_x1"}, false);
      check_neighbors(p, raw, o, {"wall_x0"}, {"floor"}, false);
    }
  }
}

TEST(PartNeighbors, VertexRuleAddsCoplanarAndCornerFaces) {
  // One floor triangle of the split pocket (a fan triangle along one wall): its edge
  // neighbors in the floor are coplanar (no concave edge), but at its two corner vertices
  // every edge is on the closed front side of the floor plane and of the two walls: those
  // faces cover the half-space behind them at the corner, so they are in N_S.
  RawMesh raw = test::pocket_part({.rotation = 1, .split = true});
  Part p = analyze(raw);
  const SolidMesh& m = p.mesh();
  auto floor = test::triangles_of(m, raw, {"floor"});
  ASSERT_EQ(floor.size(), 4u);
  std::vector<uint32_t> s = {floor[0]};
  auto n = p.neighbor_occluders(s);
  EXPECT_EQ(n, brute_force_neighbors(p, s));
  // The other three floor triangles all touch one of its corners.
  for (size_t i = 1; i < 4; ++i) EXPECT_TRUE(std::binary_search(n.begin(), n.end(), floor[i]));
  // Top faces are never in it: the pocket walls go down behind them.
  for (uint32_t t : test::triangles_of(m, raw, {"top"}))
    EXPECT_FALSE(std::binary_search(n.begin(), n.end(), t));
}

// ---- O_S -----------------------------------------------------------------------------

TEST(PartPotential, PocketWallSeesTheOppositeWall) {
  for (const TestPartOptions& o : all_options()) {
    for (bool drafted : {false, true}) {
      RawMesh raw = drafted ? test::drafted_pocket_part(o) : test::pocket_part(o);
      Part p = analyze(raw);
      const SolidMesh& m = p.mesh();
      auto s = test::triangles_of(m, raw, {"wall_x0"});
      auto n = p.neighbor_occluders(s);
      std::vector<uint32_t> asked;
      auto o_s = p.potential_occluders(s, n, [&](uint32_t t) {
        asked.push_back(t);
        return true;
      });
      // Everything of the region not in S + N_S faces the wall; without split faces that
      // is exactly the opposite wall.
      EXPECT_EQ(o_s, minus(test::triangles_of(m, raw, {"floor", "wall_y0", "wall_y1", "wall_x1"}), n))
          << describe(raw.source, o);
      if (triangle_mode(o))
        EXPECT_EQ(o_s, test::triangles_of(m, raw, {"wall_x1"})) << describe(raw.source, o);
      EXPECT_EQ(asked, o_s);
      EXPECT_TRUE(p.potential_occluders(s, n, [](uint32_t) { return false; }).empty());
      // Floor: everything of the region is in N_S already.
      auto floor = test::triangles_of(m, raw, {"floor"});
      auto fn = p.neighbor_occluders(floor);
      auto expect_floor = minus(test::triangles_of(m, raw, {"wall_x0", "wall_x1", "wall_y0", "wall_y1"}), fn);
      EXPECT_EQ(p.potential_occluders(floor, fn, kAll), expect_floor) << describe(raw.source, o);
      if (triangle_mode(o)) EXPECT_TRUE(expect_floor.empty());
    }
  }
}

TEST(PartPotential, TSlotLipSeesFloorFarWallAndFarNeck) {
  for (const TestPartOptions& o : all_options()) {
    RawMesh raw = test::tslot_open_part(o);
    Part p = analyze(raw);
    const SolidMesh& m = p.mesh();
    auto s = test::triangles_of(m, raw, {"lip_underside_0"});
    auto n = p.neighbor_occluders(s);
    EXPECT_FALSE(n.empty());
    EXPECT_TRUE(subset(n, test::triangles_of(m, raw, {"wall_x0"}))) << describe("tslot_open", o);
    // The other lip underside is coplanar (excluded); the near neck wall is behind the lip.
    // With split faces, the fan triangles at the top of the far neck wall lie entirely
    // above the lip plane, so they are not potential occluders either.
    auto o_s = p.potential_occluders(s, n, kAll);
    auto upper = minus(test::triangles_of(m, raw, {"floor", "wall_x1", "neck_x1", "wall_x0"}), n);
    EXPECT_EQ(o_s, brute_force_potential(p, s, n)) << describe("tslot_open", o);
    if (triangle_mode(o))
      EXPECT_EQ(o_s, upper) << describe("tslot_open", o);
    else
      EXPECT_TRUE(subset(o_s, upper)) << describe("tslot_open", o);
  }
}

TEST(PartPotential, FaceTouchingSAtOneVertexIsIncluded) {
  // Slot without splitting: wall_x0 is two triangles; S = the one with a single vertex on
  // the floor. A floor triangle touching S only at that vertex is not in N_S (the end
  // face goes down behind it) but potentially faces S, so it is in O_S.
  for (int rot = 0; rot < 3; ++rot) {
    RawMesh raw = test::slot_part({.rotation = rot});
    Part p = analyze(raw);
    const SolidMesh& m = p.mesh();
    auto wall = test::triangles_of(m, raw, {"wall_x0"});
    auto floor = test::triangles_of(m, raw, {"floor"});
    ASSERT_EQ(wall.size(), 2u);
    std::set<uint32_t> floor_verts;
    for (uint32_t t : floor) floor_verts.insert(m.triangles[t].begin(), m.triangles[t].end());
    uint32_t s_tri = 0;
    for (uint32_t t : wall) {
      int on_floor = 0;
      for (uint32_t v : m.triangles[t]) on_floor += floor_verts.count(v);
      if (on_floor == 1) s_tri = t;
    }
    std::vector<uint32_t> s = {s_tri};
    auto n = p.neighbor_occluders(s);
    auto o_s = p.potential_occluders(s, n, kAll);
    int touching = 0;
    for (uint32_t f : floor) {
      int shared = 0;
      for (uint32_t v : m.triangles[f])
        for (uint32_t w : m.triangles[s_tri]) shared += v == w;
      if (shared != 1) continue;
      ++touching;
      EXPECT_FALSE(std::binary_search(n.begin(), n.end(), f));
      EXPECT_TRUE(std::binary_search(o_s.begin(), o_s.end(), f));
    }
    EXPECT_GE(touching, 1);
    // The coplanar other half of the wall is never an occluder.
    for (uint32_t t : wall)
      if (t != s_tri) EXPECT_FALSE(std::binary_search(o_s.begin(), o_s.end(), t));
    for (uint32_t t : test::triangles_of(m, raw, {"wall_x1"}))
      EXPECT_TRUE(std::binary_search(o_s.begin(), o_s.end(), t));
  }
}

TEST(PartPotential, MatchesBruteForceOnRandomSurfaces) {
  std::mt19937 rng(7);
  for (const auto& tp : test::all_test_parts())
    for (const TestPartOptions& o : {TestPartOptions{.rotation = 2, .split = true},
                                     TestPartOptions{.rotation = 1}}) {
      Part p = analyze(tp.make(o));
      const uint32_t nt = uint32_t(p.mesh().triangles.size());
      for (int trial = 0; trial < 20; ++trial) {
        std::vector<uint32_t> s;
        int k = 1 + int(rng() % 6);
        for (int i = 0; i < k; ++i) s.push_back(rng() % nt);
        std::sort(s.begin(), s.end());
        s.erase(std::unique(s.begin(), s.end()), s.end());
        auto n = p.neighbor_occluders(s);
        for (uint32_t t : n) EXPECT_FALSE(std::binary_search(s.begin(), s.end(), t));
        EXPECT_EQ(p.potential_occluders(s, n, kAll), brute_force_potential(p, s, n))
            << describe(tp.name, o);
      }
    }
}

// Large planar faces take the per-plane path of the search (condition (ii) once per
// plane): every named face, and whole concave regions, against the definition.
TEST(PartPotential, MatchesBruteForceOnLargePlanarFacesAndRegions) {
  int planar_faces = 0;
  for (const auto& tp : test::all_test_parts()) {
    const TestPartOptions o{.rotation = 2, .split = true};
    const RawMesh raw = tp.make(o);
    Part p = analyze(raw);
    std::vector<std::vector<uint32_t>> surfaces;
    for (const auto& [name, faces] : raw.groups) {
      std::vector<uint32_t> s = test::triangles_of_faces(p.mesh(), faces);
      if (s.size() >= 16) ++planar_faces;
      surfaces.push_back(std::move(s));
    }
    for (const ConcaveRegion& r : p.regions()) surfaces.push_back(r.triangles);
    for (const auto& s : surfaces) {
      auto n = p.neighbor_occluders(s);
      EXPECT_EQ(p.potential_occluders(s, n, kAll), brute_force_potential(p, s, n))
          << describe(tp.name, o);
    }
  }
  EXPECT_GT(planar_faces, 10);  // the per-plane path did run
}

// ---- face group files ------------------------------------------------------------------

class PartFaceGroups : public ::testing::Test {
 protected:
  // In this process's own directory: ctest runs the tests of this fixture side by side in
  // separate processes, and a shared /tmp name let one test read the other's half-written file.
  std::string write(const std::string& text) {
    auto path = test::scratch_dir() / ("face_groups_" + std::to_string(counter_++) + ".json");
    std::ofstream(path) << text;
    return path.string();
  }
  std::string error(const std::string& text, uint32_t faces = 10) {
    auto r = read_face_groups(write(text), faces);
    EXPECT_FALSE(r.ok()) << text;
    return r.ok() ? std::string() : r.status().message();
  }
  int counter_ = 0;
};

TEST_F(PartFaceGroups, ReadsValidFile) {
  auto r = read_face_groups(write(R"({"floor": [3, 1, 2], "walls": [0, 9]})"), 10);
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r->size(), 2u);
  EXPECT_EQ(r->at("floor"), (std::vector<uint32_t>{3, 1, 2}));
  EXPECT_EQ(r->at("walls"), (std::vector<uint32_t>{0, 9}));
  auto empty = read_face_groups(write("{}"), 10);
  ASSERT_TRUE(empty.ok());
  EXPECT_TRUE(empty->empty());
}

TEST_F(PartFaceGroups, ReportsErrors) {
  EXPECT_EQ(read_face_groups("/nonexistent/groups.json", 10).status().code(),
            StatusCode::kNotFound);
  EXPECT_NE(error("{\"a\": [1, 2").find("not a JSON object"), std::string::npos);
  EXPECT_NE(error("[1, 2]").find("not a JSON object"), std::string::npos);
  EXPECT_NE(error(R"({"a": 3})").find("'a' is not a list"), std::string::npos);
  EXPECT_NE(error(R"({"a": []})").find("'a' is empty"), std::string::npos);
  EXPECT_NE(error(R"({"a": ["x"]})").find("entry 0 is not a number"), std::string::npos);
  EXPECT_NE(error(R"({"a": [1.5]})").find("not a non-negative integer"), std::string::npos);
  EXPECT_NE(error(R"({"a": [-1]})").find("not a non-negative integer"), std::string::npos);
  EXPECT_NE(error(R"({"a": [10]})").find("face 10 does not exist"), std::string::npos);
  EXPECT_NE(error(R"({"a": [1, 1]})").find("face 1 appears twice in face group 'a'"),
            std::string::npos);
  EXPECT_NE(error(R"({"a": [1], "b": [2, 1]})").find("face 1 is in face groups 'a' and 'b'"),
            std::string::npos);
}

}  // namespace
}  // namespace gvm
