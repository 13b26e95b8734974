// The window around an LVM, and coverage clipped to it, against brute-force membership.
#include "visibility/clip_window.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>
#include <vector>

#include "sphere/clearance.h"
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

// A convex 2-cell from its arcs (each with the cell on its left).
SphericalImage convex_cell(const std::vector<Arc>& arcs) {
  Face f;
  f.convex = true;
  f.loops.push_back({arcs});
  SphericalImage image;
  image.add_face(f);
  return image;
}

// Every direction of the LVM, those on its boundary too, lies strictly inside a window;
// directions far from it lie in none.
void expect_covered(const SphericalImage& lvm, const std::vector<ClipWindow>& windows, uint64_t seed) {
  auto in_a_window = [&](const ExactVec& u) {
    return std::any_of(windows.begin(), windows.end(), [&](const ClipWindow& w) { return w.contains_strictly(u); });
  };
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0, 1);
  int inside = 0;
  for (int i = 0; i < 4000; ++i) {
    const ExactVec u = v(unit_d({g(rng), g(rng), g(rng)}));
    if (lvm.contains(u)) {
      ASSERT_TRUE(in_a_window(u)) << lvm.description();
      ++inside;
    } else if (approx_signed_clearance(lvm, u.unit()) < -0.3) {
      EXPECT_FALSE(in_a_window(u)) << lvm.description();
    }
  }
  EXPECT_GT(inside, 400);
  // Directions exactly on the boundary circles.
  for (const Face& f : lvm.faces()) {
    for (const Arc& arc : f.loops[0].arcs) {
      for (int k = 0; k < 40; ++k) {
        const ExactVec on_circle = exact::cross(arc.normal, v(unit_d({g(rng), g(rng), g(rng)})));
        for (const ExactVec& x : {on_circle, -on_circle}) {
          if (lvm.contains(x)) EXPECT_TRUE(in_a_window(x)) << lvm.description();
        }
      }
    }
  }
}

TEST(ClipWindow, FanPiecesCoverHemispheresLunesAndLargeCells) {
  const SphericalImage hemisphere = SphericalImage::hemisphere(v(0.3, -0.2, 1));
  const std::vector<ClipWindow> four = ClipWindow::covering(hemisphere);
  EXPECT_EQ(four.size(), 4u);
  expect_covered(hemisphere, four, 1);

  // The lune {z >= 0, x >= 0}: two half circles between -y and +y.
  const SphericalImage lune = convex_cell({{v(0, -1, 0), v(0, 1, 0), v(0, 0, 1)}, {v(0, 1, 0), v(0, -1, 0), v(1, 0, 0)}});
  const std::vector<ClipWindow> lune_windows = ClipWindow::covering(lune);
  EXPECT_GE(lune_windows.size(), 2u);
  expect_covered(lune, lune_windows, 2);

  // A cell with four corners close together and one opposite: more than a right angle
  // from the centre of its corners, too wide for one window.
  std::vector<ExactVec> corners;
  for (const double degrees : {-3, 0, 3, 6, 180}) {
    corners.push_back(v(std::cos(degrees * kPi / 180), std::sin(degrees * kPi / 180), 0.1));
  }
  std::vector<Arc> sides;
  for (size_t k = 0; k < corners.size(); ++k) {
    const ExactVec &a = corners[k], &b = corners[(k + 1) % corners.size()];
    sides.push_back({a, b, exact::cross(a, b)});
  }
  const SphericalImage wide = convex_cell(sides);
  EXPECT_FALSE(ClipWindow::around(wide));
  const std::vector<ClipWindow> pieces = ClipWindow::covering(wide);
  EXPECT_GE(pieces.size(), 3u);
  expect_covered(wide, pieces, 3);

  // A small cell keeps its single window; the full sphere and two cells get none.
  EXPECT_EQ(ClipWindow::covering(cell_image(square(-1, -1, 1, 2))).size(), 1u);
  EXPECT_TRUE(ClipWindow::covering(SphericalImage::full_sphere()).empty());
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
