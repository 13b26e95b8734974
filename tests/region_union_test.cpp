// Positive regions and their unions against brute-force membership in the input polygons.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "sphere/region_union.h"
#include "sphere/set_operations.h"
#include "support/spherical_polygons.h"

namespace gvm::sphere {
namespace {

using namespace test_polygons;

// Every sample not near any input circle is inside the region (per the winding number of
// its boundary) iff it is inside at least one input polygon. Returns the samples checked.
int check_membership(const Region& region, const std::vector<Polygon>& polys, const D3& r,
                     const std::vector<D3>& dirs, const char* what) {
  const std::vector<DArc> inputs = to_doubles(arcs_of(polys));
  const std::vector<DArc> boundary = to_doubles(region.boundary);
  const int base = covering(polys, v(r)) > 0 ? 1 : 0;
  int checked = 0;
  for (const D3& u : dirs) {
    if (near_a_circle(inputs, u) || near_a_circle(boundary, u)) continue;
    const std::optional<int> w = winding(boundary, r, u, base);
    if (!w) continue;
    const bool expected = covering(polys, v(u)) > 0;
    EXPECT_TRUE(*w == 0 || *w == 1) << what << ": winding " << *w << " at " << u[0] << " "
                                    << u[1] << " " << u[2];
    EXPECT_EQ(*w > 0, expected) << what << ": at " << u[0] << " " << u[1] << " " << u[2];
    if (::testing::Test::HasFailure()) return checked;
    ++checked;
  }
  return checked;
}

// The boundary is made of weight-1 arcs shorter than 180 degrees (counter-clockwise
// around their normal, as ArrangementArc requires) with the union just on their left and
// not just on their right: no arc lies inside the union (e.g. on a shared edge) or
// outside it.
void check_boundary(const Region& region, const std::vector<Polygon>& polys, const char* what) {
  const std::vector<DArc> inputs = to_doubles(arcs_of(polys));
  for (const ArrangementArc& a : region.boundary) {
    EXPECT_EQ(a.weight, 1) << what;
    EXPECT_EQ(exact::sign_det(a.normal, a.from, a.to), Sign::kPositive) << what;
    EXPECT_EQ(exact::sign_dot(a.normal, a.from), Sign::kZero) << what;
    EXPECT_EQ(exact::sign_dot(a.normal, a.to), Sign::kZero) << what;
    const D3 f = a.from.unit(), t = a.to.unit(), n = a.normal.unit();
    const D3 mid = unit_d({f[0] + t[0], f[1] + t[1], f[2] + t[2]});
    constexpr double kPush = 1e-7;
    // Skip a midpoint that lies close to another circle: the push could cross it.
    bool crowded = false;
    for (const DArc& c : inputs) {
      const D3 nc = cross_d(c.normal, n);
      if (dot_d(nc, nc) > 1e-18 && std::fabs(dot_d(c.normal, mid)) < 20 * kPush) crowded = true;
    }
    if (crowded) continue;
    const D3 left = unit_d(axpy(kPush, n, mid)), right = unit_d(axpy(-kPush, n, mid));
    EXPECT_GT(covering(polys, v(left)), 0)
        << what << ": outside on the left of a boundary arc at " << mid[0] << " " << mid[1]
        << " " << mid[2];
    EXPECT_EQ(covering(polys, v(right)), 0)
        << what << ": inside on the right of a boundary arc at " << mid[0] << " " << mid[1]
        << " " << mid[2];
  }
}

// Lengths in radians, in doubles: the boundary of a union is made of pieces of the input
// edges, so its length follows from the input perimeters by hand.
double arc_length(const D3& a, const D3& b) {
  const D3 c = cross_d(a, b);
  return std::atan2(std::sqrt(dot_d(c, c)), dot_d(a, b));
}
double boundary_length(const Region& reg) {
  double s = 0;
  for (const ArrangementArc& a : reg.boundary) s += arc_length(a.from.unit(), a.to.unit());
  return s;
}
double perimeter(const Polygon& p) {
  double s = 0;
  for (size_t i = 0; i < p.size(); ++i) s += arc_length(p[i].unit(), p[(i + 1) % p.size()].unit());
  return s;
}
double edge_length(double x0, double y0, double x1, double y1) {
  return arc_length(unit_d({x0, y0, 8}), unit_d({x1, y1, 8}));
}

const D3 kOutside = {-3, 5, -17};  // outside every polygon below, on no circle

Region positive(const std::vector<Polygon>& polys, const D3& r) {
  const std::vector<ArrangementArc> arcs = arcs_of(polys);
  return positive_region(arcs, v(r), covering(polys, v(r)));
}

// positive_region of all polygons together, and the union of their single regions.
void check_union(const std::vector<Polygon>& polys, const D3& r, const char* what,
                 int min_checked = 200) {
  const bool r_inside = covering(polys, v(r)) > 0;
  Region together = positive(polys, r);
  std::vector<Region> parts;
  for (const Polygon& p : polys) parts.push_back(positive({p}, r));
  Region merged = region_union(parts, v(r));
  for (const Region* reg : {&together, &merged}) {
    SCOPED_TRACE(reg == &together ? "positive_region" : "region_union");
    EXPECT_EQ(reg->contains_reference, r_inside) << what;
    EXPECT_GT(reg->arrangement_vertices, 0u) << what;
    EXPECT_FALSE(reg->boundary.empty()) << what;
    check_boundary(*reg, polys, what);
    EXPECT_GE(check_membership(*reg, polys, r, samples(7), what), min_checked) << what;
  }
}

// A direction inside the polygons, off their circles, as a second reference.
const D3 kInsideRef = {0.013, 0.021, 1};

TEST(RegionUnion, TwoOverlappingSquares) {
  const std::vector<Polygon> polys = {square(-2, -2, 2, 2), square(0, 0, 4, 4)};
  check_union(polys, kOutside, "overlapping");
  check_union(polys, kInsideRef, "overlapping, reference inside");
  // The union is an octagon: both perimeters minus the boundary of the intersection
  // [0, 2] x [0, 2], whose four edges are the pieces of input edges inside the other square.
  const double expected =
      perimeter(polys[0]) + perimeter(polys[1]) - perimeter(square(0, 0, 2, 2));
  for (const D3& r : {kOutside, kInsideRef}) {
    EXPECT_NEAR(boundary_length(positive(polys, r)), expected, 1e-12);
  }
}

TEST(RegionUnion, TwoDisjointSquares) {
  const std::vector<Polygon> polys = {square(-4, -1, -2, 1), square(2, -1, 4, 1)};
  check_union(polys, kOutside, "disjoint");
  check_union(polys, {-3.01, 0.02, 8}, "disjoint, reference in one");
  // Nothing to cut: the boundary is made of the 8 input edges.
  EXPECT_NEAR(boundary_length(positive(polys, kOutside)),
              perimeter(polys[0]) + perimeter(polys[1]), 1e-12);
}

TEST(RegionUnion, NestedSquares) {
  const std::vector<Polygon> polys = {square(-3, -3, 3, 3), square(-1, -1, 1, 1)};
  check_union(polys, kOutside, "nested");
  check_union(polys, kInsideRef, "nested, reference in both");
  // The inner square leaves no trace: the boundary is the outer square's.
  EXPECT_NEAR(boundary_length(positive(polys, kOutside)), perimeter(polys[0]), 1e-12);
  EXPECT_NEAR(boundary_length(positive(polys, kInsideRef)), perimeter(polys[0]), 1e-12);
}

TEST(RegionUnion, SquaresSharingAnEdgeExactly) {
  // [-2, 0] x [-1, 1] and [0, 2] x [-1, 1]: the edge x = 0 is shared, walked both ways.
  const std::vector<Polygon> polys = {square(-2, -1, 0, 1), square(0, -1, 2, 1)};
  check_union(polys, kOutside, "shared edge");
  check_union(polys, kInsideRef, "shared edge, reference inside");
  // Hand geometry: no boundary arc lies on the circle of the shared edge (the plane
  // x = 0), and the boundary is both perimeters minus twice the shared edge.
  for (const D3& r : {kOutside, kInsideRef}) {
    const Region reg = positive(polys, r);
    for (const ArrangementArc& a : reg.boundary) {
      EXPECT_FALSE(exact::parallel(a.normal, v(1, 0, 0))) << "an arc on the shared edge";
    }
    EXPECT_NEAR(boundary_length(reg),
                perimeter(polys[0]) + perimeter(polys[1]) - 2 * edge_length(0, -1, 0, 1),
                1e-12);
    std::vector<Region> parts = {positive({polys[0]}, r), positive({polys[1]}, r)};
    const Region merged = region_union(parts, v(r));
    for (const ArrangementArc& a : merged.boundary) {
      EXPECT_FALSE(exact::parallel(a.normal, v(1, 0, 0))) << "an arc on the shared edge";
    }
  }
  // A shared edge only partly (a smaller square against a longer edge).
  const std::vector<Polygon> partly = {square(-2, -2, 0, 2), square(0, -1, 1, 1)};
  check_union(partly, kOutside, "partly shared edge");
  EXPECT_NEAR(boundary_length(positive(partly, kOutside)),
              perimeter(partly[0]) + perimeter(partly[1]) - 2 * edge_length(0, -1, 0, 1),
              1e-12);
}

TEST(RegionUnion, SquaresTouchingAtACornerOnly) {
  const std::vector<Polygon> polys = {square(-2, -2, 0, 0), square(0, 0, 2, 2)};
  check_union(polys, kOutside, "corner");
  check_union(polys, {-1.01, -0.98, 8}, "corner, reference in one");
  // Hand geometry: the two squares keep all their edges (nothing overlaps or is shared).
  EXPECT_NEAR(boundary_length(positive(polys, kOutside)),
              perimeter(polys[0]) + perimeter(polys[1]), 1e-12);
}

TEST(RegionUnion, PolygonWithWeightTwoArcs) {
  const Polygon p = square(-2, -1, 3, 2);
  std::vector<ArrangementArc> arcs;
  add_polygon(arcs, p, 2);  // coverage 2 inside
  for (const D3& r : {kOutside, kInsideRef}) {
    const int ref_cov = inside_polygon(p, v(r)) ? 2 : 0;
    const Region reg = positive_region(arcs, v(r), ref_cov);
    EXPECT_EQ(reg.contains_reference, ref_cov > 0);
    EXPECT_GT(reg.arrangement_vertices, 0u);
    EXPECT_NEAR(boundary_length(reg), perimeter(p), 1e-12);
    check_boundary(reg, {p}, "weight 2");
    EXPECT_GE(check_membership(reg, {p}, r, samples(11), "weight 2"), 200);
  }
}

TEST(RegionUnion, EmptyInput) {
  const Region none = region_union({}, v(kOutside));
  EXPECT_TRUE(none.boundary.empty());
  EXPECT_FALSE(none.contains_reference);
  const Region nothing = positive_region({}, v(kOutside), 0);
  EXPECT_TRUE(nothing.boundary.empty());
  EXPECT_FALSE(nothing.contains_reference);
  const Region everything = positive_region({}, v(kOutside), 1);
  EXPECT_TRUE(everything.boundary.empty());
  EXPECT_TRUE(everything.contains_reference);
  // Empty regions and the whole sphere merged with a square.
  const std::vector<Polygon> sq = {square(-1, -1, 1, 1)};
  const Region merged = region_union({nothing, positive(sq, kOutside), nothing}, v(kOutside));
  EXPECT_FALSE(merged.contains_reference);
  check_boundary(merged, sq, "square with empty parts");
  EXPECT_GE(check_membership(merged, sq, kOutside, samples(3), "square with empty parts"), 200);
  const Region all = region_union({positive(sq, kOutside), everything}, v(kOutside));
  EXPECT_TRUE(all.contains_reference);
  EXPECT_TRUE(all.boundary.empty());
}

TEST(RegionUnion, RandomTrianglesDoNotDependOnGrouping) {
  std::mt19937_64 rng(2024);
  std::vector<Polygon> tris;
  for (int i = 0; i < 50; ++i) tris.push_back(random_triangle(rng));
  for (const Polygon& t : tris) ASSERT_EQ(exact::sign_det(t[0], t[1], t[2]), Sign::kPositive);
  const std::vector<D3> dirs = samples(5, 2500);

  for (const D3& r : {kOutside, kInsideRef}) {
    // The reference must lie on no input circle.
    for (const ArrangementArc& a : arcs_of(tris)) {
      ASSERT_NE(exact::sign_dot(a.normal, v(r)), Sign::kZero);
    }
    // Group splits: all in one, one each, blocks of 7, a random split with an empty group,
    // and two groups in reverse order.
    std::vector<std::vector<std::vector<int>>> splits;
    std::vector<std::vector<int>> one(1), each, sevens, random_split(6), halves(2);
    for (int i = 0; i < 50; ++i) {
      one[0].push_back(i);
      each.push_back({i});
      if (i % 7 == 0) sevens.emplace_back();
      sevens.back().push_back(i);
      random_split[1 + rng() % 5].push_back(i);  // group 0 stays empty
      halves[i < 25 ? 1 : 0].push_back(49 - i);
    }
    splits = {one, each, sevens, random_split, halves};

    std::vector<Region> results;
    for (const auto& split : splits) {
      std::vector<Region> parts;
      for (const std::vector<int>& group : split) {
        std::vector<Polygon> polys;
        for (int i : group) polys.push_back(tris[i]);
        parts.push_back(positive(polys, r));
      }
      results.push_back(region_union(parts, v(r)));
    }
    const bool r_inside = covering(tris, v(r)) > 0;
    for (size_t s = 0; s < results.size(); ++s) {
      SCOPED_TRACE("split " + std::to_string(s));
      EXPECT_EQ(results[s].contains_reference, r_inside);
      EXPECT_GT(results[s].arrangement_vertices, 0u);
      check_boundary(results[s], tris, "triangles");
      EXPECT_GE(check_membership(results[s], tris, r, dirs, "triangles"), 1000);
      if (HasFailure()) return;
    }
    // The splits agree with each other sample by sample.
    std::vector<DArc> inputs = to_doubles(arcs_of(tris));
    std::vector<std::vector<DArc>> bounds;
    for (const Region& reg : results) bounds.push_back(to_doubles(reg.boundary));
    const int base = r_inside ? 1 : 0;
    int compared = 0;
    for (const D3& u : dirs) {
      if (near_a_circle(inputs, u)) continue;
      std::optional<int> first;
      for (size_t s = 0; s < bounds.size(); ++s) {
        std::optional<int> w = winding(bounds[s], r, u, base);
        if (!w) continue;
        if (!first) {
          first = w;
        } else {
          EXPECT_EQ(*w > 0, *first > 0) << "split " << s << " at " << u[0] << " " << u[1];
          ++compared;
        }
      }
    }
    EXPECT_GT(compared, 4000);
  }
}

TEST(RegionUnion, OutsideTheInteriorKeepsTheBoundaryWithinTheSet) {
  // R = [-2, 2]^2 u [0, 4]^2 (on the plane z = 8); the set [-1, 3] x [-1, 1] leaves R's
  // interior in the closed rectangle [2, 3] x [-1, 0].
  const std::vector<Polygon> polys = {square(-2, -2, 2, 2), square(0, 0, 4, 4)};
  const Region r = positive(polys, kOutside);
  const SphericalImage set = image_of(square(-1, -1, 3, 1));
  const SphericalImage left = outside_interior(set, r, v(kOutside));
  ASSERT_EQ(left.faces().size(), 1u);
  EXPECT_TRUE(left.curves().empty());
  EXPECT_TRUE(left.points().empty());
  const SphericalImage expected = image_of(square(2, -1, 3, 0));
  EXPECT_TRUE(is_subset(left, expected) && is_subset(expected, left));
  // On R's boundary inside the set: kept; on an edge of one square inside the other: not.
  EXPECT_TRUE(left.contains(v(2.5, 0, 8)));
  EXPECT_TRUE(left.contains(v(2, -0.5, 8)));
  EXPECT_TRUE(left.contains(v(2, 0, 8)));
  EXPECT_FALSE(left.contains(v(2, 0.5, 8)));
  EXPECT_FALSE(left.contains(v(1, 0.5, 8)));
  int checked = 0;
  for (const D3& u : samples(13)) {
    const ExactVec x = v(u);
    const bool expected = set.contains(x) && covering(polys, x) == 0;
    if (near_a_circle(to_doubles(arcs_of({square(-1, -1, 3, 1), polys[0], polys[1]})), u)) continue;
    ASSERT_EQ(left.contains(x), expected) << u[0] << " " << u[1] << " " << u[2];
    checked += expected;
  }
  EXPECT_GT(checked, 0);

  // A curve across R keeps its pieces outside the interior, its end on R's boundary too;
  // a point keeps only what lies outside the interior.
  SphericalImage line;
  line.add_curve({v(-3, 0.5, 8), v(3, 0.5, 8), exact::cross(v(-3, 0.5, 8), v(3, 0.5, 8))});
  const SphericalImage piece = outside_interior(line, r, v(kOutside));
  ASSERT_EQ(piece.curves().size(), 1u);
  EXPECT_TRUE(piece.faces().empty());
  EXPECT_TRUE(piece.contains(v(-2, 0.5, 8)));
  EXPECT_TRUE(piece.contains(v(-2.5, 0.5, 8)));
  EXPECT_FALSE(piece.contains(v(-1.9, 0.5, 8)));
  EXPECT_FALSE(piece.contains(v(2.5, 0.5, 8)));
  // Along R's boundary a curve stays, along an edge inside R's interior it goes.
  SphericalImage along;
  along.add_curve({v(-1, -2, 8), v(1, -2, 8), exact::cross(v(-1, -2, 8), v(1, -2, 8))});
  along.add_curve({v(2, 0.5, 8), v(2, 1.5, 8), exact::cross(v(2, 0.5, 8), v(2, 1.5, 8))});
  const SphericalImage on_boundary = outside_interior(along, r, v(kOutside));
  ASSERT_EQ(on_boundary.curves().size(), 1u);
  EXPECT_TRUE(on_boundary.contains(v(0, -2, 8)));
  EXPECT_FALSE(on_boundary.contains(v(2, 1, 8)));
  SphericalImage points;
  for (const ExactVec& p : {v(1, 1, 8), v(2, -1, 8), v(5, 5, 8)}) points.add_point(p);
  const SphericalImage kept = outside_interior(points, r, v(kOutside));
  ASSERT_EQ(kept.points().size(), 2u);
  EXPECT_FALSE(kept.contains(v(1, 1, 8)));
  EXPECT_TRUE(kept.contains(v(2, -1, 8)));
  EXPECT_TRUE(kept.contains(v(5, 5, 8)));
  // Nothing left once the set lies in the interior.
  EXPECT_TRUE(outside_interior(image_of(square(-1, -1, 1, 1)), r, v(kOutside)).is_empty());
}

}  // namespace
}  // namespace gvm::sphere
