// The exact arrangement and its non-regularized cell selection.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sphere/arrangement.h"

namespace gvm::sphere {
namespace {

using exact::ExactVec;

ExactVec v(double x, double y, double z) { return ExactVec::from_point({x, y, z}); }

// Counter-clockwise polygon (seen from outside) with the given vertices as arcs of one
// layer, weight 1: coverage 1 inside.
void add_polygon(std::vector<ArrangementArc>& arcs, const std::vector<ExactVec>& p, int layer) {
  for (size_t i = 0; i < p.size(); ++i) {
    const ExactVec& a = p[i];
    const ExactVec& b = p[(i + 1) % p.size()];
    arcs.push_back({a, b, exact::cross(a, b), layer, 1});
  }
}

std::vector<ExactVec> square(double x0, double y0, double x1, double y1, double z = 8) {
  return {v(x0, y0, z), v(x1, y0, z), v(x1, y1, z), v(x0, y1, z)};
}

SphericalImage convex_polygon(const std::vector<ExactVec>& p) {
  Loop loop;
  for (size_t i = 0; i < p.size(); ++i) {
    loop.arcs.push_back({p[i], p[(i + 1) % p.size()], exact::cross(p[i], p[(i + 1) % p.size()])});
  }
  SphericalImage img;
  img.add_face({{loop}, true});
  return img;
}

const ExactVec kReference = v(-3, 5, -17);  // far from everything below, on no arc

// Coverage selections: faces with coverage >= k in layer 0.
SphericalImage at_least(const Arrangement& arr, int k) {
  return arr.extract([&](uint32_t f) { return arr.coverage(f, 0) >= k; },
                     [](uint32_t) { return false; }, [](uint32_t) { return false; });
}

TEST(SphereArrangement, UnionAndIntersectionOfOverlappingSquares) {
  std::vector<ArrangementArc> arcs;
  auto a = square(-2, -2, 2, 2), b = square(0, 0, 4, 4);
  add_polygon(arcs, a, 0);
  add_polygon(arcs, b, 0);
  const int ref[] = {0};
  Arrangement arr(arcs, {}, 1, kReference, ref);
  SphericalImage uni = at_least(arr, 1), both = at_least(arr, 2);
  double area_a = convex_polygon(a).area(), area_b = convex_polygon(b).area();
  double area_ab = convex_polygon(square(0, 0, 2, 2)).area();
  EXPECT_NEAR(uni.area(), area_a + area_b - area_ab, 1e-12);
  EXPECT_NEAR(both.area(), area_ab, 1e-12);
  ASSERT_EQ(uni.faces().size(), 1u);
  ASSERT_EQ(uni.faces()[0].loops.size(), 1u);
  EXPECT_EQ(uni.faces()[0].loops[0].arcs.size(), 8u);  // the union is an octagon
  EXPECT_EQ(both.faces()[0].loops[0].arcs.size(), 4u);
  // Nothing is covered three times, and the reference face is outside.
  EXPECT_TRUE(at_least(arr, 3).is_empty());
  // Exact membership in the non-convex union, boundary points included.
  SphericalImage ca = convex_polygon(a), cb = convex_polygon(b);
  int inside = 0;
  for (int x = -6; x <= 6; ++x) {
    for (int y = -6; y <= 6; ++y) {
      for (double z : {8.0, 5.0, -8.0}) {
        ExactVec u = v(x, y, z);
        bool expected = ca.contains(u) || cb.contains(u);
        ASSERT_EQ(uni.contains(u), expected) << x << " " << y << " " << z;
        inside += expected;
      }
    }
  }
  EXPECT_GT(inside, 30);
}

TEST(SphereArrangement, CollinearEdgesAndAHoleAndSeparateComponents) {
  std::vector<ArrangementArc> arcs;
  // A big square with a smaller square inside it (a hole when selecting coverage == 1),
  // a square sharing part of an edge with the big one, and a far square on its own.
  add_polygon(arcs, square(-3, -3, 3, 3), 0);
  add_polygon(arcs, square(-1, -1, 1, 1), 0);
  add_polygon(arcs, square(3, -1, 5, 1), 0);
  add_polygon(arcs, square(-1, -1, 1, 1, -8), 0);  // around -z, seen CW: coverage -1
  const int ref[] = {0};
  Arrangement arr(arcs, {}, 1, kReference, ref);
  SphericalImage exactly_one = arr.extract(
      [&](uint32_t f) { return arr.coverage(f, 0) == 1; }, [](uint32_t) { return false; },
      [](uint32_t) { return false; });
  // Big square minus the inner one, joined with the neighbour across the shared edge.
  ASSERT_EQ(exactly_one.faces().size(), 1u);
  EXPECT_EQ(exactly_one.faces()[0].loops.size(), 2u);
  double expected = convex_polygon(square(-3, -3, 3, 3)).area() -
                    convex_polygon(square(-1, -1, 1, 1)).area() +
                    convex_polygon(square(3, -1, 5, 1)).area();
  EXPECT_NEAR(exactly_one.area(), expected, 1e-12);
  SphericalImage negative = arr.extract(
      [&](uint32_t f) { return arr.coverage(f, 0) < 0; }, [](uint32_t) { return false; },
      [](uint32_t) { return false; });
  EXPECT_EQ(negative.faces().size(), 1u);
}

// Components far apart are joined by bridges between near ones: 48 small squares on a
// ring around +z, each bridged to a neighbour, and only one bridge down to a square
// around -z -- listed first, so the component of vertex 0, to which every other one used
// to be bridged, across the sphere (TR12J F234: 8.5 M candidate pairs where 1.3 M do).
// The coverage stays right whichever bridges are chosen.
TEST(SphereArrangement, BridgesJoinNearComponents) {
  std::vector<ArrangementArc> arcs;
  add_polygon(arcs, {v(1, -1, -8), v(-1, -1, -8), v(-1, 1, -8), v(1, 1, -8)}, 0);  // CCW seen from -z
  double squares_area = convex_polygon({v(1, -1, -8), v(-1, -1, -8), v(-1, 1, -8), v(1, 1, -8)}).area();
  constexpr int kRing = 48;
  for (int k = 0; k < kRing; ++k) {
    const double angle = 2 * M_PI * k / kRing;
    const double x = std::round(6 * std::cos(angle) * 64) / 64, y = std::round(6 * std::sin(angle) * 64) / 64;
    const auto sq = square(x - 0.125, y - 0.125, x + 0.125, y + 0.125);
    add_polygon(arcs, sq, 0);
    squares_area += convex_polygon(sq).area();
  }
  const int ref[] = {0};
  const Arrangement arr(arcs, {}, 1, v(-3, 5, 17), ref);  // inside the ring, on no arc
  double bridges = 0, longest = 0;
  for (uint32_t e = 0; e < arr.edges().size(); ++e) {
    if (!arr.is_bridge(e)) continue;
    const auto a = arr.vertices()[arr.edges()[e].v0].p.unit(), b = arr.vertices()[arr.edges()[e].v1].p.unit();
    const double angle = std::acos(std::clamp(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], -1.0, 1.0));
    bridges += angle;
    longest = std::max(longest, angle);
  }
  // The ring's squares are about 5 degrees apart, the ring 37 degrees from +z and 143
  // from the square around -z: one bridge down, the rest along the ring and to the
  // reference. All to one component would be 48 bridges of 140 degrees or more.
  EXPECT_LT(bridges, 2 * M_PI);
  EXPECT_GT(longest, 2.0);  // the one bridge down to -z
  EXPECT_NEAR(at_least(arr, 1).area(), squares_area, 1e-12);
  EXPECT_EQ(at_least(arr, 1).faces().size(), size_t(kRing + 1));
}

// Many nodes of one direction (unions leave hundreds of constructions of one vertex) are
// one vertex, found with one exact comparison each against the direction's first node,
// not with all m^2 / 2 pairs of their overlapping boxes.
TEST(SphereArrangement, ManyNodesOfOneDirectionAreOneVertex) {
  std::vector<ArrangementArc> arcs;
  add_polygon(arcs, square(-1, -1, 1, 1), 0);
  std::vector<ArrangementPoint> points;
  constexpr int kNodes = 400;
  for (int k = 1; k <= kNodes; ++k) points.push_back({v(3.0 * k, 5.0 * k, 7.0 * k), 0});
  points.push_back({exact::cross(v(0, 7, -5), v(7, 0, -3)), 0});  // (-21, -35, -49): the opposite
  const Arrangement arr(arcs, points, v(-3, 5, 17));
  // The square's 4 corners, the direction, its opposite, the reference.
  EXPECT_EQ(arr.vertices().size(), 7u);
  EXPECT_LT(arr.compared_pairs(), uint64_t{4 * kNodes});
}

// Nodes of one direction whose estimates straddle a border of the grid that finds equal
// directions: p = (0, 1, 3) lies on the border x = 0, and each construction of it as the
// meeting of two circles through it rounds its own way, so their boxes' centres fall on
// both sides. All are one vertex.
TEST(SphereArrangement, OneDirectionAcrossAGridCellBorderIsOneVertex) {
  const ExactVec p = v(0, 1, 3);
  std::vector<ArrangementArc> arcs;
  add_polygon(arcs, square(-1, -1, 1, 1, -8), 0);
  std::vector<ArrangementPoint> points;
  std::vector<double> x;
  for (int k = 1; k <= 300; ++k) {
    const ExactVec n1 = exact::cross(p, v(std::sin(k), std::cos(3.0 * k), 0.5 + k));
    const ExactVec n2 = exact::cross(p, v(std::cos(7.0 * k), 1 + k, std::sin(5.0 * k)));
    ExactVec m = exact::cross(n1, n2);
    if (exact::sign_dot(m, p) == Sign::kNegative) m = exact::cross(n2, n1);
    ASSERT_TRUE(exact::same_direction(m, p));
    points.push_back({m, 0});
    x.push_back(exact::unit_estimate(m).unit[0]);
  }
  // The estimates do lie on both sides of the border.
  ASSERT_TRUE(std::any_of(x.begin(), x.end(), [&](double t) { return t < 0; }));
  ASSERT_TRUE(std::any_of(x.begin(), x.end(), [&](double t) { return t > 0; }));
  const Arrangement arr(arcs, points, kReference);
  EXPECT_EQ(arr.vertices().size(), 6u);  // the square's 4 corners, p, the reference
}

// Non-regularized difference: an arc L (layer 1) through two open occluders (layer 0) that
// touch at one corner keeps exactly that corner point.
TEST(SphereArrangement, ArcThroughTouchingOccludersKeepsTheCornerPoint) {
  std::vector<ArrangementArc> arcs;
  add_polygon(arcs, square(-2, -2, 0, 0), 0);
  add_polygon(arcs, square(0, 0, 2, 2), 0);
  ExactVec from = v(-3, -3, 8), to = v(3, 3, 8);
  arcs.push_back({from, to, exact::cross(from, to), 1, 0});
  const int ref[] = {0, 0};
  Arrangement arr(arcs, {}, 2, kReference, ref);
  auto occluded_face = [&](uint32_t f) { return arr.coverage(f, 0) >= 1; };
  auto occluded_edge = [&](uint32_t e) {
    return occluded_face(arr.half_edges()[2 * e].face) &&
           occluded_face(arr.half_edges()[2 * e + 1].face);
  };
  auto occluded_vertex = [&](uint32_t vi) {
    for (uint32_t h : arr.vertices()[vi].out) {
      if (!occluded_face(arr.half_edges()[h].face)) return false;
    }
    return true;
  };
  auto on_l_vertex = [&](uint32_t vi) {
    for (uint32_t h : arr.vertices()[vi].out) {
      if (arr.edge_on_layer(arr.half_edges()[h].edge, 1)) return true;
    }
    return false;
  };
  SphericalImage gvm = arr.extract(
      [](uint32_t) { return false; },
      [&](uint32_t e) { return arr.edge_on_layer(e, 1) && !occluded_edge(e); },
      [&](uint32_t vi) { return on_l_vertex(vi) && !occluded_vertex(vi); });
  // Two pieces of the arc outside the squares, and the corner point between them: the
  // corner is not in the interior of the union of the two open squares.
  EXPECT_EQ(gvm.dimension(), 1);
  EXPECT_EQ(gvm.curves().size(), 2u);
  ASSERT_EQ(gvm.points().size(), 1u);
  EXPECT_TRUE(exact::same_direction(gvm.points()[0], v(0, 0, 1)));
}

// Two occluders sharing an edge: the interior of their union contains the shared edge, so
// an arc of L lying exactly on it is removed.
TEST(SphereArrangement, ArcOnTheSharedEdgeOfTwoOccludersIsOccluded) {
  std::vector<ArrangementArc> arcs;
  add_polygon(arcs, square(-2, -2, 0, 2), 0);
  add_polygon(arcs, square(0, -2, 2, 2), 0);
  ExactVec from = v(0, -1, 8), to = v(0, 1, 8);
  arcs.push_back({from, to, exact::cross(from, to), 1, 0});
  const int ref[] = {0, 0};
  Arrangement arr(arcs, {}, 2, kReference, ref);
  auto occluded_face = [&](uint32_t f) { return arr.coverage(f, 0) >= 1; };
  SphericalImage gvm = arr.extract(
      [](uint32_t) { return false; },
      [&](uint32_t e) {
        return arr.edge_on_layer(e, 1) &&
               !(occluded_face(arr.half_edges()[2 * e].face) &&
                 occluded_face(arr.half_edges()[2 * e + 1].face));
      },
      [](uint32_t) { return false; });
  EXPECT_TRUE(gvm.is_empty());
}

TEST(SphereArrangement, IsolatedPointsAreLocated) {
  std::vector<ArrangementArc> arcs;
  add_polygon(arcs, square(-2, -2, 2, 2), 0);
  std::vector<ArrangementPoint> points = {{v(0, 0, 1), 1}, {v(0, 0, -1), 1}, {v(2, 0, 8), 1}};
  const int ref[] = {0, 0};
  Arrangement arr(arcs, points, 2, kReference, ref);
  auto occluded_vertex = [&](uint32_t vi) {
    for (uint32_t h : arr.vertices()[vi].out) {
      if (arr.coverage(arr.half_edges()[h].face, 0) < 1) return false;
    }
    return !arr.vertices()[vi].out.empty();
  };
  SphericalImage gvm = arr.extract(
      [](uint32_t) { return false; }, [](uint32_t) { return false; },
      [&](uint32_t vi) { return arr.vertex_has_point(vi, 1) && !occluded_vertex(vi); });
  // +z is inside the open square: occluded. -z is far: kept. (2, 0, 8) is on the
  // square's boundary, not in its interior: kept.
  ASSERT_EQ(gvm.points().size(), 2u);
  int found = 0;
  for (const auto& p : gvm.points()) {
    found += exact::same_direction(p, v(0, 0, -1)) + exact::same_direction(p, v(2, 0, 8));
  }
  EXPECT_EQ(found, 2);
}

}  // namespace
}  // namespace gvm::sphere
