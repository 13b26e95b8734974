// The exact convex hull and the hill-climbing extreme-vertex query behind hull facets.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cstdio>
#include <random>
#include <set>

#include "exact/predicates.h"
#include "part/convex_hull.h"

namespace gvm::part {
namespace {

// Points of a box with a dense grid on every face: many points are coplanar, and some
// face-interior points may become hull vertices (inserted while still extreme).
std::vector<Point3> grid_box(int n) {
  std::vector<Point3> pts;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k)
        if (i == 0 || j == 0 || k == 0 || i == n || j == n || k == n)
          pts.push_back({double(i), double(j), double(k)});
  return pts;
}

TEST(PartConvexHull, EveryPointInsideAndClosed) {
  auto pts = grid_box(8);
  std::vector<uint32_t> use(pts.size());
  for (uint32_t i = 0; i < use.size(); ++i) use[i] = i;
  ConvexHull h = convex_hull(pts, use);
  ASSERT_FALSE(h.facets.empty());
  for (const Triangle& f : h.facets)
    for (const Point3& p : pts)
      ASSERT_NE(exact::orient3d(pts[f[0]], pts[f[1]], pts[f[2]], p), Sign::kPositive);
  // Closed: every directed edge has its reverse.
  std::set<std::pair<uint32_t, uint32_t>> edges;
  for (const Triangle& f : h.facets)
    for (int i = 0; i < 3; ++i) edges.insert({f[i], f[(i + 1) % 3]});
  for (auto [a, b] : edges) EXPECT_TRUE(edges.count({b, a}));
}

// Hill climbing must find the maximum from every hull vertex, including vertices that
// lie inside a flat face opposite to the direction (all their neighbors tie).
TEST(PartConvexHull, ExtremeVertexFromEveryStart) {
  auto pts = grid_box(6);
  std::vector<uint32_t> use(pts.size());
  for (uint32_t i = 0; i < use.size(); ++i) use[i] = i;
  ConvexHull h = convex_hull(pts, use);
  const std::vector<std::array<Point3, 3>> dirs = {
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},   // +z
      {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}},   // -z
      {{{0, 0, 0}, {0, 1, 0}, {0, 0, 1}}},   // +x
      {{{0, 0, 0}, {0, 0, 1}, {0, 1, 0}}},   // -x
      {{{0, 0, 0}, {0, 0, 1}, {1, 0, 0}}},   // +y
      {{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}},   // -y
      {{{0, 0, 0}, {1, 1, 0}, {0, 1, 1}}},   // oblique
  };
  int interior_starts = 0;
  for (uint32_t v = 0; v < pts.size(); ++v) {
    if (h.offset[v + 1] == h.offset[v]) continue;
    bool interior = true;  // all coordinates strictly inside on two axes: a face interior
    int inner = 0;
    for (int k = 0; k < 3; ++k) inner += pts[v][k] > 0 && pts[v][k] < 6;
    interior = inner == 2;
    interior_starts += interior;
    for (const auto& d : dirs) {
      uint32_t best = hull_extreme_vertex(h, pts, d[0], d[1], d[2], v);
      for (const Point3& p : pts)
        ASSERT_NE(exact::det_diff(d[0], d[1], d[0], d[2], pts[best], p), Sign::kPositive)
            << "start " << v;
    }
  }
  std::printf("hull vertices inside a face: %d\n", interior_starts);
}

// Enough points for the conflict lists to be assigned in parallel (a box's grid and random
// points inside it): the hull holds every point, and it is the same facets on one thread
// and on two.
TEST(PartConvexHull, LargeSetIsTheSameOnOneAndTwoThreads) {
  auto pts = grid_box(12);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coordinate(1, 1 << 20);
  while (pts.size() < 9000)
    pts.push_back({12.0 * coordinate(rng) / (1 << 20), 12.0 * coordinate(rng) / (1 << 20), 12.0 * coordinate(rng) / (1 << 20)});
  std::vector<uint32_t> use(pts.size());
  for (uint32_t i = 0; i < use.size(); ++i) use[i] = i;
  ConvexHull one, two;
  tbb::task_arena(1).execute([&] { one = convex_hull(pts, use); });
  tbb::task_arena(2).execute([&] { two = convex_hull(pts, use); });
  ASSERT_FALSE(one.facets.empty());
  EXPECT_EQ(one.facets, two.facets);
  EXPECT_EQ(one.adjacency, two.adjacency);
  for (const Triangle& f : two.facets)
    for (const Point3& p : pts) ASSERT_NE(exact::orient3d(pts[f[0]], pts[f[1]], pts[f[2]], p), Sign::kPositive);
}

}  // namespace
}  // namespace gvm::part
