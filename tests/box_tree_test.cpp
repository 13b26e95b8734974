// BoxTree pair and query searches against an O(n^2) brute force on closed boxes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "sphere/box_tree.h"

namespace gvm::sphere {
namespace {

using Pairs = std::vector<std::pair<uint32_t, uint32_t>>;

// Closed boxes, written out independently of box_tree.h: they meet unless separated along
// some axis by a positive gap, so boxes touching at a face, an edge or a corner meet.
bool meet(const Box& a, const Box& b) {
  for (int i = 0; i < 3; ++i) {
    if (a.hi[i] < b.lo[i]) return false;
    if (b.hi[i] < a.lo[i]) return false;
  }
  return true;
}

Pairs brute_pairs(const std::vector<Box>& boxes) {
  Pairs out;
  for (uint32_t i = 0; i < boxes.size(); ++i) {
    for (uint32_t j = i + 1; j < boxes.size(); ++j) {
      if (meet(boxes[i], boxes[j])) out.emplace_back(i, j);
    }
  }
  return out;  // already sorted
}

std::vector<uint32_t> brute_query(const std::vector<Box>& boxes, const Box& q) {
  std::vector<uint32_t> out;
  for (uint32_t i = 0; i < boxes.size(); ++i) {
    if (meet(boxes[i], q)) out.push_back(i);
  }
  return out;
}

Box make_box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return Box{{x0, y0, z0}, {x1, y1, z1}};
}

Box point_box(double x, double y, double z) { return make_box(x, y, z, x, y, z); }

// The tree's answers for every pair and for the given queries equal the brute force.
void check(const std::vector<Box>& boxes, const std::vector<Box>& queries, const char* what) {
  const BoxTree tree(boxes);
  const Pairs expected = brute_pairs(boxes);
  const Pairs actual = tree.overlapping_pairs();
  ASSERT_EQ(actual.size(), expected.size()) << what << ", n = " << boxes.size();
  ASSERT_TRUE(actual == expected) << what << ", n = " << boxes.size();
  for (size_t k = 0; k < queries.size(); ++k) {
    ASSERT_EQ(tree.overlapping(queries[k]), brute_query(boxes, queries[k]))
        << what << ", n = " << boxes.size() << ", query " << k;
  }
}

// Random boxes of wildly different sizes: points, tiny boxes, ordinary ones and huge ones,
// some with coordinates on a coarse grid so that exact touching is common.
std::vector<Box> random_boxes(std::mt19937_64& rng, size_t n) {
  std::uniform_real_distribution<double> pos(-10, 10), unit(0, 1);
  std::uniform_int_distribution<int> kind(0, 5), grid(-40, 40), cells(0, 8);
  std::vector<Box> boxes;
  for (size_t i = 0; i < n; ++i) {
    Box b;
    const int k = kind(rng);
    for (int a = 0; a < 3; ++a) {
      switch (k) {
        case 0:  // a point
          b.lo[a] = b.hi[a] = pos(rng);
          break;
        case 1: {  // tiny
          b.lo[a] = pos(rng);
          b.hi[a] = b.lo[a] + 1e-9 * unit(rng);
          break;
        }
        case 2: {  // ordinary
          b.lo[a] = pos(rng);
          b.hi[a] = b.lo[a] + unit(rng);
          break;
        }
        case 3: {  // huge
          b.lo[a] = pos(rng) - 1e6 * unit(rng);
          b.hi[a] = pos(rng) + 1e6 * unit(rng);
          if (b.hi[a] < b.lo[a]) std::swap(b.lo[a], b.hi[a]);
          break;
        }
        default: {  // on a grid of quarters: exact touching and identical faces
          b.lo[a] = grid(rng) / 4.0;
          b.hi[a] = b.lo[a] + cells(rng) / 4.0;
          break;
        }
      }
    }
    boxes.push_back(b);
  }
  return boxes;
}

// Point queries: random points, box corners (on the boundary: closed boxes contain them)
// and box centres; plus a few box queries.
std::vector<Box> queries_for(std::mt19937_64& rng, const std::vector<Box>& boxes) {
  std::uniform_real_distribution<double> pos(-12, 12);
  std::vector<Box> q;
  for (int i = 0; i < 30; ++i) q.push_back(point_box(pos(rng), pos(rng), pos(rng)));
  for (size_t i = 0; i < boxes.size() && i < 40; ++i) {
    const Box& b = boxes[(i * 7919) % boxes.size()];
    q.push_back(point_box(b.lo[0], b.lo[1], b.lo[2]));
    q.push_back(point_box(b.hi[0], b.hi[1], b.hi[2]));
    q.push_back(point_box(b.lo[0], b.hi[1], b.lo[2]));
    q.push_back(point_box((b.lo[0] + b.hi[0]) / 2, (b.lo[1] + b.hi[1]) / 2,
                          (b.lo[2] + b.hi[2]) / 2));
    q.push_back(b);  // the box itself
  }
  q.push_back(make_box(-1, -1, -1, 1, 1, 1));
  q.push_back(make_box(-1e9, -1e9, -1e9, 1e9, 1e9, 1e9));
  q.push_back(point_box(1e8, 1e8, 1e8));
  return q;
}

TEST(BoxTree, OverlapIsClosed) {
  const Box a = make_box(0, 0, 0, 1, 1, 1);
  EXPECT_TRUE(overlap(a, a));
  EXPECT_TRUE(overlap(a, make_box(1, 0, 0, 2, 1, 1)));     // shared face
  EXPECT_TRUE(overlap(a, make_box(1, 1, 0, 2, 2, 1)));     // shared edge
  EXPECT_TRUE(overlap(a, make_box(1, 1, 1, 2, 2, 2)));     // shared corner
  EXPECT_TRUE(overlap(make_box(-1, -1, -1, 0, 0, 0), a));  // corner, other order
  EXPECT_TRUE(overlap(a, point_box(1, 1, 1)));             // a point on the corner
  EXPECT_TRUE(overlap(a, point_box(0.5, 0.5, 0.5)));
  const double gap = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(overlap(a, make_box(gap, 0, 0, 2, 1, 1)));
  EXPECT_FALSE(overlap(make_box(gap, 0, 0, 2, 1, 1), a));
  EXPECT_FALSE(overlap(a, make_box(0, 0, gap, 1, 1, 2)));
  EXPECT_FALSE(overlap(a, point_box(0.5, -1e-300, 0.5)));
  EXPECT_FALSE(overlap(a, make_box(2, 2, 2, 3, 3, 3)));
}

TEST(BoxTree, EmptyAndTinyInputs) {
  std::vector<Box> none;
  const BoxTree empty(none);
  EXPECT_TRUE(empty.overlapping_pairs().empty());
  EXPECT_TRUE(empty.overlapping(make_box(-1e300, -1e300, -1e300, 1e300, 1e300, 1e300)).empty());

  std::vector<Box> one{make_box(0, 0, 0, 1, 1, 1)};
  const BoxTree single(one);
  EXPECT_TRUE(single.overlapping_pairs().empty());
  EXPECT_EQ(single.overlapping(point_box(1, 1, 1)), std::vector<uint32_t>{0});
  EXPECT_TRUE(single.overlapping(point_box(1, 1, 1.5)).empty());

  std::vector<Box> two_apart{make_box(0, 0, 0, 1, 1, 1), make_box(3, 0, 0, 4, 1, 1)};
  EXPECT_TRUE(BoxTree(two_apart).overlapping_pairs().empty());
  std::vector<Box> two_touching{make_box(3, 0, 0, 4, 1, 1), make_box(0, 0, 0, 3, 1, 1)};
  EXPECT_EQ(BoxTree(two_touching).overlapping_pairs(), (Pairs{{0, 1}}));
}

TEST(BoxTree, RandomBoxesMatchBruteForce) {
  for (uint64_t seed : {1u, 2u, 3u, 17u, 12345u}) {
    std::mt19937_64 rng(seed);
    for (size_t n : {0, 1, 2, 3, 7, 8, 9, 16, 17, 33, 100, 257, 600, 2000}) {
      if (n == 2000 && seed > 3) continue;  // the largest size on a few seeds is enough
      const std::vector<Box> boxes = random_boxes(rng, n);
      check(boxes, queries_for(rng, boxes), "random");
      if (HasFatalFailure()) return;
    }
  }
}

TEST(BoxTree, ManyIdenticalBoxes) {
  for (size_t n : {9, 64, 1000}) {
    std::vector<Box> boxes(n, make_box(-1, 2, 3, 4, 5, 6));
    std::mt19937_64 rng(n);
    check(boxes, queries_for(rng, boxes), "identical");
    EXPECT_EQ(BoxTree(boxes).overlapping_pairs().size(), n * (n - 1) / 2);
    // Identical points too.
    std::vector<Box> points(n, point_box(0.25, -7, 1e-300));
    EXPECT_EQ(BoxTree(points).overlapping_pairs().size(), n * (n - 1) / 2);
    check(points, {point_box(0.25, -7, 1e-300), point_box(0.25, -7, 0)}, "identical points");
  }
}

TEST(BoxTree, BoxesClusteredAtOnePoint) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> tiny(-1e-12, 1e-12);
  std::uniform_int_distribution<int> coin(0, 3);
  std::vector<Box> boxes;
  for (int i = 0; i < 1500; ++i) {
    if (coin(rng) == 0) {
      boxes.push_back(point_box(1, 1, 1));  // exactly the cluster point
    } else {
      // A tiny box near the point, which contains it or not.
      Box b;
      for (int a = 0; a < 3; ++a) {
        double u = 1 + tiny(rng), v = 1 + tiny(rng);
        b.lo[a] = std::min(u, v);
        b.hi[a] = std::max(u, v);
      }
      boxes.push_back(b);
    }
  }
  // Some far boxes as well, and one huge box containing everything.
  for (int i = 0; i < 50; ++i) boxes.push_back(point_box(100 + i, -100, 0));
  boxes.push_back(make_box(-1e6, -1e6, -1e6, 1e6, 1e6, 1e6));
  std::vector<Box> queries = queries_for(rng, boxes);
  queries.push_back(point_box(1, 1, 1));
  check(boxes, queries, "clustered");
}

TEST(BoxTree, BoxesTouchingAtFacesEdgesAndCorners) {
  // A row of unit boxes along x: consecutive ones share a face, the others are apart.
  std::vector<Box> row;
  for (int i = 0; i < 200; ++i) row.push_back(make_box(i, 0, 0, i + 1, 1, 1));
  Pairs chain;
  for (uint32_t i = 0; i + 1 < 200; ++i) chain.emplace_back(i, i + 1);
  EXPECT_EQ(BoxTree(row).overlapping_pairs(), chain);  // hand count: 199 face contacts
  check(row, {point_box(5, 1, 1), point_box(200, 0.5, 0.5), point_box(200.5, 0.5, 0.5)},
        "row");
  EXPECT_EQ(BoxTree(row).overlapping(point_box(5, 1, 1)), (std::vector<uint32_t>{4, 5}));

  // A 9 x 9 x 9 grid of unit cubes: each touches its (up to) 26 neighbours.
  const int g = 9;
  std::vector<Box> grid;
  for (int x = 0; x < g; ++x) {
    for (int y = 0; y < g; ++y) {
      for (int z = 0; z < g; ++z) grid.push_back(make_box(x, y, z, x + 1, y + 1, z + 1));
    }
  }
  // Two cubes touch iff their indices differ by at most 1 on every axis. Per axis there
  // are g + 2 (g - 1) ordered index pairs with |a - b| <= 1; the ordered cube pairs are
  // the product over the axes, minus the g^3 pairs of a cube with itself, halved.
  const size_t per_axis = size_t(g) + 2 * size_t(g - 1);  // pairs (a, b) with |a - b| <= 1
  const size_t expected_pairs = (per_axis * per_axis * per_axis - size_t(g) * g * g) / 2;
  EXPECT_EQ(BoxTree(grid).overlapping_pairs().size(), expected_pairs);
  std::mt19937_64 rng(5);
  std::vector<Box> queries = queries_for(rng, grid);
  queries.push_back(point_box(4, 4, 4));  // a grid vertex: 8 cubes
  check(grid, queries, "grid");
  EXPECT_EQ(BoxTree(grid).overlapping(point_box(4, 4, 4)).size(), 8u);
  EXPECT_EQ(BoxTree(grid).overlapping(point_box(4, 4, 4.5)).size(), 4u);
  EXPECT_EQ(BoxTree(grid).overlapping(point_box(4, 4.5, 4.5)).size(), 2u);
  EXPECT_EQ(BoxTree(grid).overlapping(point_box(4.5, 4.5, 4.5)).size(), 1u);

  // Flat boxes all lying on one plane z = 0 (zero thickness) side by side, and slabs
  // stacked on each other.
  std::vector<Box> flat, stack;
  for (int i = 0; i < 300; ++i) {
    flat.push_back(make_box(i % 20, i / 20, 0, i % 20 + 1, i / 20 + 1, 0));
    stack.push_back(make_box(0, 0, i, 1, 1, i + 1));
  }
  check(flat, queries_for(rng, flat), "flat");
  check(stack, queries_for(rng, stack), "stack");
  EXPECT_EQ(BoxTree(stack).overlapping_pairs().size(), 299u);
}

}  // namespace
}  // namespace gvm::sphere
