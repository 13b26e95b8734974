// The window around an LVM, and coverage clipped to it, against brute-force membership.
#include "visibility/clip_window.h"

#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <vector>

#include "sphere/region_union.h"
#include "support/spherical_polygons.h"

namespace gvm {
namespace {

using namespace sphere;
using namespace sphere::test_polygons;

SphericalImage arc_image(const D3& a, const D3& b) {
  SphericalImage image;
  image.add_curve({v(a), v(b), exact::cross(v(a), v(b))});
  return image;
}

// The convex 2-cell of a counter-clockwise polygon.
SphericalImage cell_image(const Polygon& p) {
  Face f;
  f.convex = true;
  f.loops.emplace_back();
  for (size_t i = 0; i < p.size(); ++i) {
    const ExactVec &a = p[i], &b = p[(i + 1) % p.size()];
    f.loops[0].arcs.push_back({a, b, exact::cross(a, b)});
  }
  SphericalImage image;
  image.add_face(f);
  return image;
}

TEST(ClipWindow, SurroundsArcsPointsAndSmallCellsButNoHemisphere) {
  const ExactVec p = v(0.1, 0.2, 1);
  const std::optional<ClipWindow> around_point = ClipWindow::around(SphericalImage::point(p));
  ASSERT_TRUE(around_point);
  EXPECT_TRUE(around_point->contains_strictly(p));
  EXPECT_FALSE(around_point->contains_strictly(v(0.6, 0.2, 1)));  // 25 degrees away

  const D3 a = {1, 0, 1}, b = {0, 1, 1};
  const std::optional<ClipWindow> around_arc = ClipWindow::around(arc_image(a, b));
  ASSERT_TRUE(around_arc);
  EXPECT_EQ(around_arc->normals().size(), 4u);
  for (const D3& u : {a, b, D3{1, 1, 2}}) EXPECT_TRUE(around_arc->contains_strictly(v(u)));
  for (const D3& u : {D3{1, 1, 3}, D3{1, 1, 1.5}, D3{1, -0.2, 1}}) {
    EXPECT_FALSE(around_arc->contains_strictly(v(u)));
  }

  const Polygon cell = square(-1, -1, 1, 2);
  const std::optional<ClipWindow> around_cell = ClipWindow::around(cell_image(cell));
  ASSERT_TRUE(around_cell);
  for (const ExactVec& corner : cell) EXPECT_TRUE(around_cell->contains_strictly(corner));
  EXPECT_FALSE(around_cell->contains_strictly(v(0, 0, -1)));

  EXPECT_FALSE(ClipWindow::around(SphericalImage::hemisphere(v(0, 0, 1))));
  EXPECT_FALSE(ClipWindow::around(SphericalImage::full_sphere()));
  EXPECT_FALSE(ClipWindow::around(SphericalImage::empty()));
  SphericalImage two_points = SphericalImage::point(p);
  two_points.add_point(v(0, 0, 1));
  EXPECT_FALSE(ClipWindow::around(two_points));
  // A half circle: its ends are antipodal, no open hemisphere holds it.
  SphericalImage half;
  half.add_curve({v(1, 0, 0), v(-1, 0, 0), v(0, 0, 1)});
  EXPECT_FALSE(ClipWindow::around(half));
}

// Directions in and around a window: along its LVM, a little off it on either side.
std::vector<D3> samples_near(const D3& a, const D3& b, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> t(-0.1, 1.1), off(-0.05, 0.05);
  std::vector<D3> out;
  for (int i = 0; i < 4000; ++i) {
    const double s = t(rng);
    out.push_back(unit_d({a[0] + s * (b[0] - a[0]) + off(rng), a[1] + s * (b[1] - a[1]) + off(rng),
                          a[2] + s * (b[2] - a[2]) + off(rng)}));
  }
  return out;
}

// The region of the clipped coverage holds u iff u is strictly inside W and inside a polygon.
int check_clipped(const Region& region, const std::vector<Polygon>& polys, const ClipWindow& w,
                  const D3& r, const std::vector<D3>& dirs) {
  std::vector<DArc> circles = to_doubles(arcs_of(polys));
  for (const ExactVec& n : w.normals()) circles.push_back({{}, {}, unit_d(n.unit())});
  const std::vector<DArc> boundary = to_doubles(region.boundary);
  int checked = 0;
  for (const D3& u : dirs) {
    if (near_a_circle(circles, u) || near_a_circle(boundary, u)) continue;
    const std::optional<int> winding_number = winding(boundary, r, u, region.contains_reference ? 1 : 0);
    if (!winding_number) continue;
    const bool expected = w.contains_strictly(v(u)) && covering(polys, v(u)) > 0;
    EXPECT_EQ(*winding_number > 0, expected) << "at " << u[0] << " " << u[1] << " " << u[2];
    if (::testing::Test::HasFailure()) return checked;
    checked += expected;
  }
  return checked;
}

Region clipped_region(const std::vector<Polygon>& polys, const ClipWindow& w, const D3& r) {
  const std::optional<std::vector<ArrangementArc>> clipped =
      w.clip(arcs_of(polys), covering(polys, w.corner(0)));
  EXPECT_TRUE(clipped);
  if (!clipped) return {};
  return positive_region(*clipped, v(r), w.contains_strictly(v(r)) ? covering(polys, v(r)) : 0);
}

TEST(ClipWindow, ClippedCoverageIsTheCoverageInsideTheWindow) {
  std::mt19937_64 rng(31);
  std::vector<Polygon> tris;
  for (int i = 0; i < 60; ++i) tris.push_back(random_triangle(rng));
  const D3 a = unit_d({-2.5, -1, 8}), b = unit_d({2, 1.5, 8}), mid = unit_d({-0.25, 0.25, 8});
  const std::optional<ClipWindow> band = ClipWindow::around(arc_image(a, b));
  const std::optional<ClipWindow> dot = ClipWindow::around(SphericalImage::point(v(mid)));
  ASSERT_TRUE(band && dot);
  const std::vector<D3> dirs = samples_near(a, b, 5);
  for (const D3& r : {D3{-3, 5, -17}, mid}) {
    SCOPED_TRACE(r == mid ? "reference inside" : "reference outside");
    EXPECT_GT(check_clipped(clipped_region(tris, *band, r), tris, *band, r, dirs), 300);
    EXPECT_GT(check_clipped(clipped_region(tris, *dot, r), tris, *dot, r, dirs), 20);
  }
}

TEST(ClipWindow, GroupsClippedOrNotAgreeInsideTheWindow) {
  std::mt19937_64 rng(77);
  std::vector<Polygon> tris;
  for (int i = 0; i < 50; ++i) tris.push_back(random_triangle(rng));
  const D3 a = unit_d({-2, 1, 8}), b = unit_d({2.5, -0.5, 8}), r = {-3, 5, -17};
  const std::optional<ClipWindow> band = ClipWindow::around(arc_image(a, b));
  ASSERT_TRUE(band);
  std::vector<Region> groups;
  for (int g = 0; g < 5; ++g) {
    const std::vector<Polygon> members(tris.begin() + 10 * g, tris.begin() + 10 * g + 10);
    groups.push_back(g % 2 ? positive_region(arcs_of(members), v(r), covering(members, v(r)))
                           : clipped_region(members, *band, r));
  }
  const Region all = region_union(groups, v(r));
  // Inside W the union is that of all the triangles; outside it, only of the unclipped ones.
  std::vector<Polygon> unclipped;
  for (int g : {1, 3}) unclipped.insert(unclipped.end(), tris.begin() + 10 * g, tris.begin() + 10 * g + 10);
  std::vector<DArc> circles = to_doubles(arcs_of(tris));
  for (const ExactVec& n : band->normals()) circles.push_back({{}, {}, unit_d(n.unit())});
  const std::vector<DArc> boundary = to_doubles(all.boundary);
  int inside = 0;
  for (const D3& u : samples_near(a, b, 9)) {
    if (near_a_circle(circles, u) || near_a_circle(boundary, u)) continue;
    const std::optional<int> w = winding(boundary, v(r).unit(), u, all.contains_reference ? 1 : 0);
    if (!w) continue;
    const bool in_window = band->contains_strictly(v(u));
    const bool expected = covering(in_window ? tris : unclipped, v(u)) > 0;
    ASSERT_EQ(*w > 0, expected) << "at " << u[0] << " " << u[1] << " " << u[2];
    inside += in_window;
  }
  EXPECT_GT(inside, 300);
}

TEST(ClipWindow, ArcsMeetingTheBoundaryDegeneratelyAreLeftUnclipped) {
  const std::optional<ClipWindow> w = ClipWindow::around(SphericalImage::point(v(0, 0, 1)));
  ASSERT_TRUE(w);
  // A triangle with a vertex exactly on the circle of W's first edge, and an arc through a
  // corner of W.
  const ExactVec on_circle = exact::cross(w->normals()[0], v(1, 0, 0));
  const ExactVec on_circle_up = exact::sign_dot(on_circle, v(0, 0, 1)) == Sign::kPositive ? on_circle : -on_circle;
  const Polygon touching = {on_circle_up, v(1, 1, 3), v(-1, 1, 3)};
  EXPECT_FALSE(w->clip(arcs_of({touching}), 0));
  const ExactVec &corner = w->corner(1), d = v(0.001, 0.002, 0);
  const ExactVec from = corner - d, to = corner + d;  // corner = (from + to) / 2
  const std::vector<ArrangementArc> through_corner = {{from, to, exact::cross(from, to), 0, 1}};
  EXPECT_FALSE(w->clip(through_corner, 0));
}

}  // namespace
}  // namespace gvm
