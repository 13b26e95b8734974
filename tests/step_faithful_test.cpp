// The integer geometry of the faithful STEP tessellation (engine/step/faithful/): exact
// directions and frames, the lattice placement, the ruled strips and the planar
// triangulation, each against what it promises, in integers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "step/faithful/exact_directions.h"
#include "step/faithful/lattice_placement.h"
#include "step/faithful/planar_triangulation.h"
#include "step/faithful/ruled_strips.h"

namespace gvm::faithful {
namespace {

Dir3 unit(double x, double y, double z) {
  const double n = std::sqrt(x * x + y * y + z * z);
  return {x / n, y / n, z / n};
}

TEST(ExactDirections, CoordinateAxesAndRationalDirectionsAreExact) {
  const std::vector<Dir3> dirs = {{0, 0, -1}, {1, 0, 0}, unit(2, -1, 2), unit(2, 2, -1), unit(-1, 2, 2), unit(0, 3, 4)};
  const ExactDirections d = exact_directions(dirs, std::vector<uint32_t>(dirs.size(), 1));
  ASSERT_EQ(d.classes.size(), dirs.size());
  EXPECT_EQ(d.classes[d.class_of[0]].exact, (IVec{0, 0, 1}));
  EXPECT_EQ(d.classes[d.class_of[1]].exact, (IVec{1, 0, 0}));
  EXPECT_EQ(d.classes[d.class_of[2]].exact, (IVec{2, -1, 2}));
  EXPECT_EQ(d.classes[d.class_of[3]].exact, (IVec{2, 2, -1}));
  EXPECT_EQ(d.classes[d.class_of[4]].exact, (IVec{1, -2, -2}));  // canonical sign
  EXPECT_EQ(d.classes[d.class_of[5]].exact, (IVec{0, 3, 4}));
  for (const DirectionClass& c : d.classes) EXPECT_LT(c.angle, 1e-15);
  // The rotated axes are one frame of their own.
  const IVec a{2, -1, 2}, b{2, 2, -1}, c{1, -2, -2};
  bool found = false;
  for (const Frame& f : d.frames) {
    std::set<std::array<int64_t, 3>> axes;
    for (const IVec& v : f.axis) axes.insert({v.x, v.y, v.z});
    found |= axes == std::set<std::array<int64_t, 3>>{{a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}};
  }
  EXPECT_TRUE(found);
}

TEST(ExactDirections, ParallelDirectionsAreOneClass) {
  const Dir3 d = unit(0.42261826174069905, -0.90630778703665016, 0);
  const Dir3 e = unit(-0.42261826174069789, 0.90630778703665082, 0);  // piattello's two roundings, opposite
  const ExactDirections x = exact_directions({d, e}, {1, 1});
  EXPECT_EQ(x.classes.size(), 1u);
  EXPECT_EQ(x.class_of[0], x.class_of[1]);
}

TEST(ExactDirections, ADirectionInACoordinatePlaneStaysInItAndItsNormalIsExactlyOrthogonal) {
  const double t = 25 * std::numbers::pi / 180;
  const Dir3 d = unit(std::cos(t), -std::sin(t), 0), n = unit(std::sin(t), std::cos(t), 0);
  const ExactDirections x = exact_directions({d, n, {0, 0, 1}}, {3, 1, 1});
  const IVec& vd = x.classes[x.class_of[0]].exact;
  const IVec& vn = x.classes[x.class_of[1]].exact;
  EXPECT_EQ(vd.z, 0);
  EXPECT_EQ(dot(vd, vn), 0);
  EXPECT_LT(x.classes[x.class_of[0]].angle, 1e-10);
  EXPECT_LT(x.classes[x.class_of[1]].angle, 1e-10);
  EXPECT_LE(max_abs(vd), int64_t(1) << 20);
}

TEST(ExactDirections, GenericDirectionsAreWithinTheStatedAngleAndFramesAreOrthogonal) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g;
  std::vector<Dir3> dirs;
  for (int i = 0; i < 12; ++i) dirs.push_back(unit(g(rng), g(rng), g(rng)));
  const ExactDirections x = exact_directions(dirs, std::vector<uint32_t>(dirs.size(), 1));
  for (const DirectionClass& c : x.classes) {
    EXPECT_LE(c.angle, 1e-7);
    EXPECT_LE(max_abs(c.exact), int64_t(1) << 20);
  }
  for (const DirectionClass& c : x.classes) {
    bool in_frame = false;
    for (const Frame& f : x.frames)
      for (const IVec& a : f.axis) in_frame |= a == c.exact;
    EXPECT_TRUE(in_frame);
  }
  for (const Frame& f : x.frames) {
    EXPECT_EQ(dot(f.axis[0], f.axis[1]), 0);
    EXPECT_EQ(dot(f.axis[0], f.axis[2]), 0);
    EXPECT_EQ(dot(f.axis[1], f.axis[2]), 0);
  }
}

TEST(ExactDirections, TheOrthogonalLatticeIsAllOfIt) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int64_t> c(-5000, 5000);
  for (int i = 0; i < 200; ++i) {
    const IVec a = canonical({c(rng), c(rng), c(rng)});
    if (a.is_zero()) continue;
    const auto [b1, b2] = orthogonal_lattice(a);
    EXPECT_EQ(dot(a, b1), 0);
    EXPECT_EQ(dot(a, b2), 0);
    // A basis of the whole lattice spans a parallelogram of area |a|.
    const IVec x = cross(b1, b2);
    EXPECT_EQ(dot(x, x), dot(a, a)) << a.x << " " << a.y << " " << a.z;
  }
}

// A box of the frame of (2, -1, 2), (2, 2, -1), (1, -2, -2) with a ruling along the third
// axis: every plane and the ruling hold exactly.
TEST(LatticePlacement, PlanesAndRulingsOfOneFrameHoldExactly) {
  const Dir3 a = unit(2, -1, 2), b = unit(2, 2, -1), c = unit(1, -2, -2);
  const ExactDirections dirs = exact_directions({a, b, c}, {1, 1, 1});
  PlacementProblem p;
  p.grid_exponent = -40;
  p.directions = &dirs;
  // Corners of a 1 x 2 x 3 box in that frame, at an offset, as doubles.
  auto at = [&](double x, double y, double z) {
    return std::array<double, 3>{0.3 + x * a[0] + y * b[0] + z * c[0], 0.7 + x * a[1] + y * b[1] + z * c[1],
                                 -0.2 + x * a[2] + y * b[2] + z * c[2]};
  };
  for (int i = 0; i < 8; ++i) p.target.push_back(at(i & 1, 2.0 * ((i >> 1) & 1), 3.0 * (i >> 2)));
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      PlacementProblem::Plane plane;
      plane.cls = dirs.class_of[axis];
      for (uint32_t i = 0; i < 8; ++i)
        if (((i >> axis) & 1) == uint32_t(side)) plane.points.push_back(i);
      plane.point = p.target[plane.points.front()];
      p.planes.push_back(plane);
    }
  p.rulings.push_back({dirs.class_of[2], {0, 4}, 0});  // the edge along c
  const Placement out = place_on_lattices(p);
  EXPECT_TRUE(out.misses.empty());
  for (const auto& plane : p.planes) {
    const IVec& n = dirs.classes[plane.cls].exact;
    for (uint32_t q : plane.points) EXPECT_EQ(dot(n, out.grid[q]), dot(n, out.grid[plane.points[0]]));
  }
  EXPECT_TRUE(cross(out.grid[4] - out.grid[0], dirs.classes[dirs.class_of[2]].exact).is_zero());
  EXPECT_LT(out.max_displacement_mm, 1e-9);
}

// A point on planes of two frames keeps the heavier frame's and reports the other.
TEST(LatticePlacement, AFaceOfAnotherFrameIsReportedWhenItCannotHold) {
  const double t = 25 * std::numbers::pi / 180;
  const Dir3 oblique = unit(std::cos(t), -std::sin(t), 0);
  const ExactDirections dirs = exact_directions({{1, 0, 0}, oblique, {0, 0, 1}}, {1, 1, 1});
  PlacementProblem p;
  p.grid_exponent = -40;
  p.directions = &dirs;
  p.target = {{1.0, 0.1234567, 0.5}};
  p.planes.push_back({dirs.class_of[0], {1.0, 0, 0}, {0}, 7});
  p.planes.push_back({dirs.class_of[1], p.target[0], {0}, 8});
  const Placement out = place_on_lattices(p);
  ASSERT_EQ(out.misses.size(), 1u);
  EXPECT_TRUE(out.misses[0].face == 7 || out.misses[0].face == 8);
  EXPECT_LT(out.misses[0].distance_mm, 1e-6);
}

// The wall of half a hole: rulings 0..4, the bottom rim at v = 0 left to right, the top
// rim at v = 1 back, two seam lines.
TEST(RuledStrips, EveryTriangleHasTwoCornersOnOneRuling) {
  std::vector<StripPoint> loop;
  for (uint32_t r = 0; r < 5; ++r) loop.push_back({r, r, 0.0});
  loop.push_back({10, 4, 0.5});  // a point on the right seam
  for (uint32_t r = 5; r-- > 0;) loop.push_back({5 + r, r, 1.0});
  std::vector<std::array<uint32_t, 3>> tris;
  std::string why;
  ASSERT_TRUE(ruled_strips({loop}, 5, tris, why)) << why;
  EXPECT_EQ(tris.size(), 9u);  // 8 + 1 for the seam point
  std::map<uint32_t, uint32_t> ruling;
  for (const StripPoint& p : loop) ruling[p.id] = p.ruling;
  for (const auto& t : tris) {
    const uint32_t a = ruling[t[0]], b = ruling[t[1]], c = ruling[t[2]];
    EXPECT_TRUE(a == b || b == c || a == c);
    EXPECT_FALSE(a == b && b == c);
  }
}

TEST(RuledStrips, ASegmentSkippingARulingIsRefused) {
  const std::vector<StripPoint> loop = {{0, 0, 0}, {1, 2, 0}, {2, 2, 1}, {3, 1, 1}, {4, 0, 1}};
  std::vector<std::array<uint32_t, 3>> tris;
  std::string why;
  EXPECT_FALSE(ruled_strips({loop}, 3, tris, why));
  EXPECT_NE(why.find("skips"), std::string::npos);
}

i128 area2(const Point2& a, const Point2& b, const Point2& c) {
  return i128(b[0] - a[0]) * (c[1] - a[1]) - i128(b[1] - a[1]) * (c[0] - a[0]);
}

// A square with two holes and collinear points on its sides, both ways round: the
// triangles turn as the loops do and cover the face's area exactly once.
TEST(PlanarTriangulation, HolesAreBridgedAndTheAreaIsCoveredOnce) {
  for (bool reversed : {false, true}) {
    PlanarLoop outer{{0, 1, 2, 3, 4, 5, 6, 7},
                     {Point2{0, 0}, {50, 0}, {100, 0}, {100, 50}, {100, 100}, {50, 100}, {0, 100}, {0, 50}}};
    PlanarLoop h1{{10, 11, 12, 13}, {Point2{10, 10}, {10, 30}, {30, 30}, {30, 10}}};
    PlanarLoop h2{{20, 21, 22}, {Point2{60, 60}, {70, 90}, {90, 60}}};
    if (reversed) {
      for (PlanarLoop* l : {&outer, &h1, &h2}) {
        std::reverse(l->ids.begin(), l->ids.end());
        std::reverse(l->xy.begin(), l->xy.end());
      }
    }
    std::vector<std::array<uint32_t, 3>> tris;
    std::string why;
    ASSERT_TRUE(triangulate_planar({outer, h1, h2}, tris, why)) << why;
    std::map<uint32_t, Point2> xy;
    for (const PlanarLoop* l : {&outer, &h1, &h2})
      for (size_t k = 0; k < l->ids.size(); ++k) xy[l->ids[k]] = l->xy[k];
    const int sign = reversed ? -1 : 1;
    i128 total = 0;
    for (const auto& t : tris) {
      const i128 a = area2(xy[t[0]], xy[t[1]], xy[t[2]]);
      EXPECT_GT(a * sign, 0);
      total += a;
    }
    EXPECT_EQ(total * sign, i128(2) * (100 * 100 - 20 * 20) - 900);
    EXPECT_EQ(tris.size(), 8u + 4 + 3 + 2 * 2 - 2);  // points + 2 per hole - 2
  }
}

TEST(PlanarTriangulation, AHoleRunningTheSameWayIsRefused) {
  PlanarLoop outer{{0, 1, 2, 3}, {Point2{0, 0}, {10, 0}, {10, 10}, {0, 10}}};
  PlanarLoop hole{{4, 5, 6}, {Point2{2, 2}, {5, 2}, {5, 5}}};
  std::vector<std::array<uint32_t, 3>> tris;
  std::string why;
  EXPECT_FALSE(triangulate_planar({outer, hole}, tris, why));
  EXPECT_NE(why.find("hole"), std::string::npos);
}

}  // namespace
}  // namespace gvm::faithful
