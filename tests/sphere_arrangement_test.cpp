// The exact arrangement and its non-regularized cell selection.
#include <gtest/gtest.h>

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
