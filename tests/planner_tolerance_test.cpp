// The planning tolerance epsilon on parts and sets whose answers are derived by hand: two
// blind holes whose axes differ by a tiny exact angle delta (1e-12, 1e-9, 1e-5 rad) need
// separate setups exactly, and one within a tolerance of at least delta / 2 -- the count
// changes exactly there, both ways, with its proof; tolerance 0 is the exact plan; the
// cover's midpoints between sets that no corner serves together.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <string>

#include "step/faithful/planar_triangulation.h"
#include "gvm/analysis.h"
#include "gvm/planner/plan.h"
#include "support/mesh_files.h"
#include "support/scratch_dir.h"
#include "candidates.h"
#include "tolerance.h"

namespace gvm {
namespace {

// A mesh built face by face, each face oriented to the outward normal it is given.
class MeshBuilder {
 public:
  uint32_t point(double x, double y, double z) {
    const std::array<double, 3> key = {x, y, z};
    auto [it, added] = index_.emplace(key, static_cast<uint32_t>(raw.points.size()));
    if (added) raw.points.push_back({x, y, z});
    return it->second;
  }
  void face(std::vector<uint32_t> v, const std::array<double, 3>& outward, const std::string& group) {
    const Point3 &a = raw.points[v[0]], &b = raw.points[v[1]], &c = raw.points[v[2]];
    const double n[3] = {(b.y - a.y) * (c.z - a.z) - (b.z - a.z) * (c.y - a.y),
                         (b.z - a.z) * (c.x - a.x) - (b.x - a.x) * (c.z - a.z),
                         (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)};
    if (n[0] * outward[0] + n[1] * outward[1] + n[2] * outward[2] < 0) std::reverse(v.begin(), v.end());
    raw.groups[group].push_back(static_cast<uint32_t>(raw.faces.size()));
    raw.faces.push_back(std::move(v));
  }
  RawMesh raw;

 private:
  std::map<std::array<double, 3>, uint32_t> index_;
};

// A 40 x 20 x 20 block with two blind 5 x 5 holes, 10 deep, from its +y face: hole A along
// +y, hole B along (0, 1, t) (its walls contain that direction exactly: t is a power of
// two), so their GVMs are the points +y and (0, 1, t), delta = atan(t) apart. Exactly three
// setups (+y, (0, 1, t), and -y for the bottom); two within a tolerance of delta / 2 (the
// direction halfway between the holes; -y).
RawMesh two_holes(double t) {
  MeshBuilder m;
  auto quad = [&](std::array<std::array<double, 3>, 4> p, std::array<double, 3> n, const std::string& g) {
    std::vector<uint32_t> v;
    for (const auto& q : p) v.push_back(m.point(q[0], q[1], q[2]));
    m.face(v, n, g);
  };
  const double s = 10 * t;  // hole B's bottom is shifted by -10 t in z
  for (const auto& [x0, x1, dz, name] : {std::tuple{5.0, 10.0, 0.0, "holeA"}, std::tuple{25.0, 30.0, s, "holeB"}}) {
    quad({{{x0, 20, 5}, {x0, 20, 10}, {x0, 10, 10 - dz}, {x0, 10, 5 - dz}}}, {1, 0, 0}, name);
    quad({{{x1, 20, 5}, {x1, 20, 10}, {x1, 10, 10 - dz}, {x1, 10, 5 - dz}}}, {-1, 0, 0}, name);
    quad({{{x0, 20, 5}, {x1, 20, 5}, {x1, 10, 5 - dz}, {x0, 10, 5 - dz}}}, {0, 0, 1}, name);
    quad({{{x0, 20, 10}, {x1, 20, 10}, {x1, 10, 10 - dz}, {x0, 10, 10 - dz}}}, {0, 0, -1}, name);
    quad({{{x0, 10, 5 - dz}, {x1, 10, 5 - dz}, {x1, 10, 10 - dz}, {x0, 10, 10 - dz}}}, {0, 1, 0}, name);
  }
  quad({{{0, 0, 0}, {40, 0, 0}, {40, 0, 20}, {0, 0, 20}}}, {0, -1, 0}, "bottom");
  quad({{{0, 0, 0}, {0, 20, 0}, {0, 20, 20}, {0, 0, 20}}}, {-1, 0, 0}, "x0");
  quad({{{40, 0, 0}, {40, 20, 0}, {40, 20, 20}, {40, 0, 20}}}, {1, 0, 0}, "x1");
  quad({{{0, 0, 0}, {40, 0, 0}, {40, 20, 0}, {0, 20, 0}}}, {0, 0, -1}, "z0");
  quad({{{0, 0, 20}, {40, 0, 20}, {40, 20, 20}, {0, 20, 20}}}, {0, 0, 1}, "z1");
  // The top with its two openings, triangulated exactly in its (z, x) coordinates.
  auto loop = [&](std::vector<std::array<int, 2>> zx) {
    faithful::PlanarLoop l;
    for (const auto& [z, x] : zx) {
      l.ids.push_back(m.point(x, 20, z));
      l.xy.push_back({z, x});
    }
    return l;
  };
  const std::vector<faithful::PlanarLoop> loops = {loop({{0, 0}, {20, 0}, {20, 40}, {0, 40}}),
                                                   loop({{5, 5}, {5, 10}, {10, 10}, {10, 5}}),
                                                   loop({{5, 25}, {5, 30}, {10, 30}, {10, 25}})};
  std::vector<std::array<uint32_t, 3>> triangles;
  std::string why;
  EXPECT_TRUE(faithful::triangulate_planar(loops, triangles, why)) << why;
  for (const auto& tri : triangles) m.face({tri[0], tri[1], tri[2]}, {0, 1, 0}, "top");
  return m.raw;
}

Analysis analyzed(const RawMesh& raw, const std::string& name) {
  AnalyzeRequest request;
  request.part_path = test::write_obj(raw, test::scratch_dir() / (name + ".obj"));
  auto a = analyze(request);
  EXPECT_TRUE(a.ok()) << a.status().message();
  return std::move(*a);
}

planner::SetupPlan plan_within(const Analysis& a, double tolerance) {
  v1::PlanOptions options;
  options.set_tolerance_radians(tolerance);
  auto p = planner::plan(a, options);
  EXPECT_TRUE(p.ok()) << p.status().message();
  return std::move(*p);
}

const Surface& feature(const Analysis& a, const std::string& name) {
  for (const Surface& f : a.features()) {
    if (f.name == name) return f;
  }
  ADD_FAILURE() << "no feature " << name;
  return a.features().front();
}

// Every setup's exact direction lies within the tolerance of the GVM of every surface
// planned in it (sin^2 of the tolerance rounded up: this checks, the planner decides).
void expect_within(const Analysis& a, const planner::SetupPlan& p, double tolerance) {
  const double s = std::sin(tolerance), s2 = s * s * (1 + 1e-12);
  for (int k = 0; k < p.message.setups_size(); ++k) {
    for (uint32_t id : p.message.setups(k).features()) {
      EXPECT_TRUE(a.features()[id].maps.gvm->within(p.directions[k], s2)) << a.features()[id].name << " setup " << k;
    }
  }
}

TEST(PlannerTolerance, TwoHolesATinyAngleApartShareASetupFromHalfThatAngle) {
  for (const int k : {40, 30, 17}) {
    const double t = std::ldexp(1.0, -k), delta = std::atan(t);
    SCOPED_TRACE("delta " + std::to_string(delta));
    const Analysis a = analyzed(two_holes(t), "two_holes_" + std::to_string(k));
    const Surface &hole_a = feature(a, "holeA"), &hole_b = feature(a, "holeB");
    ASSERT_TRUE(hole_a.maps.gvm && hole_b.maps.gvm);
    EXPECT_EQ(*hole_a.maps.gvm, DirectionSet::point(Direction(0, 1, 0)));
    EXPECT_EQ(*hole_b.maps.gvm, DirectionSet::point(Direction(0, 1, t)));
    // Down through delta / 2 and up again: 3, 2, 2, 3, and 3 exactly.
    for (const auto& [factor, setups] : {std::pair{0.49, 3}, {0.51, 2}, {1.01, 2}, {0.49, 3}, {0.0, 3}}) {
      SCOPED_TRACE("tolerance " + std::to_string(factor) + " delta");
      const planner::SetupPlan p = plan_within(a, factor * delta);
      EXPECT_EQ(p.message.setups_size(), setups);
      EXPECT_TRUE(p.message.optimal());
      EXPECT_EQ(p.message.lower_bound(), static_cast<uint32_t>(setups));
      EXPECT_EQ(p.message.unreachable_size(), 0);
      expect_within(a, p, factor * delta);
      if (factor == 0) {
        EXPECT_FALSE(p.message.has_tolerance());
        EXPECT_FALSE(p.message.options().has_tolerance_radians());
        continue;
      }
      EXPECT_EQ(p.message.tolerance().exact_setups(), 3u);
      EXPECT_EQ(p.message.tolerance().exact_lower_bound(), 3u);
      // Within delta / 2 the holes are reached within the tolerance, each by about delta / 2.
      if (setups == 2) {
        uint32_t within = 0;
        for (const auto& s : p.message.setups())
          for (const auto& r : s.reach())
            if (r.within_tolerance() && (r.feature() == hole_a.id || r.feature() == hole_b.id)) {
              ++within;
              EXPECT_LE(r.distance_radians(), factor * delta * (1 + 1e-9));
            }
        EXPECT_EQ(within, factor < 1 ? 2u : 1u);  // beyond delta the corner +y serves hole B alone
      }
    }
  }
}

TEST(PlannerTolerance, ToleranceZeroWritesNothingNew) {
  const Analysis a = analyzed(two_holes(std::ldexp(1.0, -17)), "two_holes_zero");
  const planner::SetupPlan p = plan_within(a, 0);
  EXPECT_FALSE(p.message.has_tolerance());
  for (const auto& s : p.message.setups())
    for (const auto& r : s.reach()) EXPECT_FALSE(r.has_within_tolerance() || r.has_distance_radians());
  // The default is the stated one.
  auto d = planner::plan(a, v1::PlanOptions());
  ASSERT_TRUE(d.ok());
  EXPECT_EQ(d->message.options().tolerance_radians(), 1e-6);
  EXPECT_EQ(d->message.tolerance().radians(), 1e-6);
}

TEST(PlannerTolerance, BadTolerancesNameTheField) {
  for (const double bad : {-1e-9, 0.02, std::nan("")}) {
    v1::PlanOptions o;
    o.set_tolerance_radians(bad);
    const Status s = planner::validate(o);
    EXPECT_FALSE(s.ok());
    EXPECT_NE(s.message().find("tolerance_radians"), std::string::npos) << s.message();
  }
}

// A point and a hemisphere delta apart: no corner serves both below delta (the hemisphere
// has none), so the cover needs the midpoint between them, found where the packing could
// not be proven (tolerance.h).
TEST(PlannerTolerance, MidpointsJoinSetsThatNoCornerServesTogether) {
  const double t = std::ldexp(1.0, -20), delta = std::atan(t);
  std::vector<planner::Target> targets;
  for (const DirectionSet& s : {DirectionSet::point(Direction(0, 1, 0)), DirectionSet::hemisphere(Direction(0, -t, 1))}) {
    targets.push_back({static_cast<uint32_t>(targets.size()), {}, 0, s, s, s});
  }
  const planner::CandidateSet seeds = planner::exact_candidates(targets);
  for (const auto& [factor, setups, midpoints] : {std::tuple{0.4, 2, 0}, {0.6, 1, 1}, {1.2, 1, 0}}) {
    SCOPED_TRACE(factor);
    const planner::Tolerance tolerance = planner::Tolerance::of(factor * delta);
    auto within = [&](uint32_t k, const Direction& d) { return targets[k].reach.within(d, tolerance.near_sin2); };
    auto cover = planner::tolerance_cover(targets, seeds, within, tolerance, {});
    ASSERT_TRUE(cover.ok());
    EXPECT_EQ(static_cast<int>(cover->solution.chosen.size()), setups);
    EXPECT_EQ(cover->solution.lower_bound, static_cast<uint32_t>(setups));
    EXPECT_EQ(static_cast<int>(cover->midpoints), midpoints);
    for (uint32_t c : cover->solution.chosen) {
      for (uint32_t k : cover->candidates.candidates[c].targets) EXPECT_TRUE(within(k, cover->candidates.candidates[c].direction));
    }
  }
}

}  // namespace
}  // namespace gvm
