// DirectionWindow prunes only faces whose directions q - p certainly miss the image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/spherical_image.h"
#include "visibility/direction_window.h"

namespace gvm {
namespace {

using exact::ExactVec;
using sphere::Arc;
using sphere::SphericalImage;

constexpr double kBound = 100;  // every coordinate of q and p below is in [-100, 100]

ExactVec v(double x, double y, double z) { return ExactVec::from_point({x, y, z}); }
ExactVec v(const Point3& p) { return ExactVec::from_point(p); }

// A convex polygon image; the vertices are put counter-clockwise seen from outside.
SphericalImage polygon(std::vector<Point3> p) {
  if (exact::sign_det(v(p[0]), v(p[1]), v(p[2])) == Sign::kNegative) {
    std::reverse(p.begin(), p.end());
  }
  sphere::Loop loop;
  for (size_t i = 0; i < p.size(); ++i) {
    ExactVec a = v(p[i]), b = v(p[(i + 1) % p.size()]);
    loop.arcs.push_back({a, b, exact::cross(a, b), false});
  }
  SphericalImage img;
  img.add_face({{loop}, true});
  return img;
}

SphericalImage arc_image(const Point3& a, const Point3& b, const Point3& n) {
  SphericalImage img;
  img.add_curve(Arc{v(a), v(b), v(n), false});
  return img;
}

// A face of the envelope: its directions are all q - p, q in Q, p in P.
struct Face {
  std::vector<Point3> q, p;
};

Point3 sub(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

bool window_may_meet(const DirectionWindow& w, const Face& f) {
  const size_t n = w.row_size();
  std::vector<double> q_max(n), p_min(n), tmp(n);
  auto row = [&](const std::vector<Point3>& points, bool largest, std::vector<double>& out) {
    w.values(points[0], out.data());
    for (size_t i = 1; i < points.size(); ++i) {
      w.values(points[i], tmp.data());
      w.fold(out.data(), tmp.data(), largest);
    }
  };
  row(f.q, true, q_max);
  row(f.p, false, p_min);
  return w.may_meet(q_max.data(), p_min.data());
}

std::string describe(const Face& f) {
  auto point = [](std::string& s, const Point3& x) {
    s += " (";  // appended piecewise: GCC 12 warns falsely on "(" + std::string
    s += std::to_string(x.x);
    s += ",";
    s += std::to_string(x.y);
    s += ",";
    s += std::to_string(x.z);
    s += ")";
  };
  std::string s = "Q:";
  for (const Point3& q : f.q) point(s, q);
  s += " P:";
  for (const Point3& p : f.p) point(s, p);
  return s;
}

// Brute force: a direction of the face's cone (a non-negative integer combination of the
// q - p, exact in doubles) in the image, if one of the samples hits it. The pure
// directions q - p and sparse combinations come first: they hit vertices and edges.
bool cone_hits(const SphericalImage& img, const Face& f, std::mt19937_64& rng, Point3* hit) {
  std::vector<Point3> d;
  for (const Point3& q : f.q) {
    for (const Point3& p : f.p) d.push_back(sub(q, p));
  }
  auto try_dir = [&](const Point3& x) {
    if (x.x == 0 && x.y == 0 && x.z == 0) return false;
    if (!img.contains(v(x))) return false;
    *hit = x;
    return true;
  };
  for (const Point3& x : d) {
    if (try_dir(x)) return true;
  }
  for (size_t i = 0; i < d.size(); ++i) {
    for (size_t j = i + 1; j < d.size(); ++j) {
      for (double wi : {1.0, 2.0, 3.0}) {
        for (double wj : {1.0, 2.0, 3.0}) {
          Point3 x{wi * d[i].x + wj * d[j].x, wi * d[i].y + wj * d[j].y, wi * d[i].z + wj * d[j].z};
          if (try_dir(x)) return true;
        }
      }
    }
  }
  std::uniform_int_distribution<int> weight(0, 1000), sparse(0, 3);
  for (int s = 0; s < 300; ++s) {
    Point3 x{};
    for (const Point3& y : d) {
      const double w = sparse(rng) == 0 ? 0.0 : double(weight(rng));
      x = {x.x + w * y.x, x.y + w * y.y, x.z + w * y.z};
    }
    if (try_dir(x)) return true;
  }
  return false;
}

// An image with integer directions known (by hand) to lie in it.
struct Case {
  std::string name;
  SphericalImage image;
  std::vector<Point3> inside;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  out.push_back({"square", polygon({{-2, -2, 8}, {2, -2, 8}, {2, 2, 8}, {-2, 2, 8}}),
                 {{-2, -2, 8}, {2, 2, 8}, {0, -2, 8}, {2, 1, 8}, {0, 0, 1}, {1, -1, 5}}});
  out.push_back({"triangle", polygon({{10, 1, 2}, {3, 9, 1}, {2, 2, 10}}),
                 {{10, 1, 2}, {3, 9, 1}, {2, 2, 10}, {13, 10, 3}, {5, 11, 11}, {15, 12, 13}}});
  out.push_back({"sliver", polygon({{40, 0, 1}, {-40, 0, 1}, {0, 1, 1}}),
                 {{40, 0, 1}, {-40, 0, 1}, {0, 0, 1}, {0, 1, 1}, {1, 0, 2}, {0, 1, 3}}});
  out.push_back({"hemisphere", SphericalImage::hemisphere(v(1, -2, 3)),
                 {{1, -2, 3}, {2, 1, 0}, {3, 0, -1}, {0, 3, 2}, {-1, 1, 1}}});
  out.push_back({"point", SphericalImage::point(v(2, -1, 5)), {{2, -1, 5}, {4, -2, 10}}});
  out.push_back({"great circle", SphericalImage::great_circle(v(1, 1, 1)),
                 {{1, -1, 0}, {1, 1, -2}, {0, 1, -1}, {-3, 1, 2}}});
  out.push_back({"quarter arc", arc_image({1, 0, 0}, {0, 1, 0}, {0, 0, 1}),
                 {{1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {3, 1, 0}, {1, 5, 0}}});
  // Half a circle around +y: from +x through -z to -x.
  out.push_back({"half arc", arc_image({1, 0, 0}, {-1, 0, 0}, {0, 1, 0}),
                 {{1, 0, 0}, {-1, 0, 0}, {0, 0, -1}, {1, 0, -1}, {-1, 0, -2}}});
  // Three quarters around +z: from +x through +y and -x to -y.
  out.push_back({"long arc", arc_image({1, 0, 0}, {0, -1, 0}, {0, 0, 1}),
                 {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {-1, -1, 0}, {1, 1, 0}}});
  {
    SphericalImage mix = polygon({{-2, -2, 8}, {2, -2, 8}, {2, 2, 8}, {-2, 2, 8}});
    mix.add_point(v(-3, 4, -5));
    mix.add_curve(Arc{v(0, 0, -1), v(0, 1, 0), v(1, 0, 0), false});  // -z to +y around +x
    mix.add_curve(Arc{{}, {}, v(0, 1, 3), true});                     // y + 3z = 0
    out.push_back({"mixed cells", mix,
                   {{-3, 4, -5}, {0, 1, -1}, {0, 3, -1}, {0, 0, -1}, {0, 1, 0}, {1, 0, 0},
                    {5, 3, -1}, {0, -3, 1}, {1, 1, 8}, {0, 0, 1}}});
  }
  return out;
}

TEST(DirectionWindow, HandDirectionsAreInTheImages) {
  // The test's own premise: the hand-chosen directions lie in their images.
  for (const Case& c : cases()) {
    for (const Point3& d : c.inside) EXPECT_TRUE(c.image.contains(v(d))) << c.name;
  }
  // And a few that do not.
  EXPECT_FALSE(cases()[6].image.contains(v(1, -1, 0)));   // quarter arc, beyond its end
  EXPECT_FALSE(cases()[7].image.contains(v(0, 0, 1)));    // half arc, the other half
  EXPECT_FALSE(cases()[8].image.contains(v(1, -1, 0)));   // long arc, the missing quarter
  EXPECT_FALSE(cases()[9].image.contains(v(0, -1, -1)));  // mixed: x = 0, off the arc
  EXPECT_FALSE(cases()[9].image.contains(v(80, 80, -95)));
}

// Soundness: whenever the window rejects a face, no sampled direction of the face's cone
// lies in the image. Half of the faces are built around a direction of the image (exactly
// on it, or a few units off), so that the rejected faces include near misses.
TEST(DirectionWindow, RejectedFacesMissTheImage) {
  std::mt19937_64 rng(77);
  std::uniform_int_distribution<int> coord(-100, 100), small(-30, 30), off(-2, 2), count(1, 3),
      mode(0, 3);
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const DirectionWindow w(c.image, kBound);
    ASSERT_GT(w.half_spaces(), 0u);
    int rejected = 0, accepted = 0, exact_hits = 0;
    for (int t = 0; t < 3000; ++t) {
      Face f;
      const int m = mode(rng);
      const int nq = count(rng), np = count(rng);
      for (int i = 0; i < np; ++i) {
        f.p.push_back({double(small(rng)), double(small(rng)), double(small(rng))});
      }
      bool exact = false;
      if (m <= 1) {
        // q0 = p0 + k s for a direction s of the image, exactly (m == 0) or perturbed.
        const Point3& s = c.inside[rng() % c.inside.size()];
        const double big = std::max({std::fabs(s.x), std::fabs(s.y), std::fabs(s.z)});
        const int k = 1 + int(rng() % uint64_t(std::max(1.0, std::floor(60 / big))));
        Point3 q{f.p[0].x + k * s.x, f.p[0].y + k * s.y, f.p[0].z + k * s.z};
        if (m == 1) q = {q.x + off(rng), q.y + off(rng), q.z + off(rng)};
        exact = m == 0;
        f.q.push_back(q);
        for (int i = 1; i < nq; ++i) {
          f.q.push_back({q.x + off(rng) * 3, q.y + off(rng) * 3, q.z + off(rng) * 3});
        }
      } else {
        for (int i = 0; i < nq; ++i) {
          f.q.push_back({double(coord(rng)), double(coord(rng)), double(coord(rng))});
        }
      }
      for (const Point3& x : f.q) {
        ASSERT_LE(std::max({std::fabs(x.x), std::fabs(x.y), std::fabs(x.z)}), kBound);
      }
      const bool may = window_may_meet(w, f);
      if (exact) {
        ++exact_hits;
        EXPECT_TRUE(may) << "q0 - p0 lies in the image; " << describe(f);
      }
      if (may) {
        ++accepted;
        continue;
      }
      ++rejected;
      Point3 hit;
      if (cone_hits(c.image, f, rng, &hit)) {
        ADD_FAILURE() << "rejected a face whose direction (" << hit.x << ", " << hit.y << ", "
                      << hit.z << ") lies in the image; " << describe(f);
        return;
      }
    }
    EXPECT_GT(rejected, 200);
    EXPECT_GT(accepted, 200);
    EXPECT_GT(exact_hits, 500);
  }
}

// Random points in [lo, hi] per axis.
std::vector<Point3> box_points(std::mt19937_64& rng, int n, Point3 lo, Point3 hi) {
  std::vector<Point3> out;
  for (int i = 0; i < n; ++i) {
    out.push_back({std::uniform_int_distribution<int>(int(lo.x), int(hi.x))(rng) * 1.0,
                   std::uniform_int_distribution<int>(int(lo.y), int(hi.y))(rng) * 1.0,
                   std::uniform_int_distribution<int>(int(lo.z), int(hi.z))(rng) * 1.0});
  }
  return out;
}

// Completeness on easy cases (hand geometry): faces well inside are kept, faces far on
// the wrong side of one half-space of every cell are pruned.
TEST(DirectionWindow, EasyFacesAreDecided) {
  std::mt19937_64 rng(3);
  const auto all = cases();
  const SphericalImage& square = all[0].image;    // |x|, |y| <= z / 4
  const SphericalImage& hemi = all[3].image;      // x - 2y + 3z >= 0
  const SphericalImage& point = all[4].image;     // (2, -1, 5)
  const SphericalImage& circle = all[5].image;    // x + y + z = 0
  const SphericalImage& quarter = all[6].image;   // z = 0, x >= 0, y >= 0
  const SphericalImage& mixed = all[9].image;
  const Point3 p_lo{-5, -5, -5}, p_hi{5, 5, 5};
  for (int t = 0; t < 200; ++t) {
    const int nq = 1 + t % 3, np = 1 + (t / 3) % 3;
    const std::vector<Point3> p = box_points(rng, np, p_lo, p_hi);
    // Square: d = q - p has |dx|, |dy| <= 15 and dz >= 75: well inside. Beyond the edge
    // y = -2 (half-space 4y + z >= 0): dy <= -65 and |dz| <= 25.
    EXPECT_TRUE(window_may_meet(DirectionWindow(square, kBound),
                                {box_points(rng, nq, {-10, -10, 80}, {10, 10, 100}), p}));
    EXPECT_FALSE(window_may_meet(DirectionWindow(square, kBound),
                                 {box_points(rng, nq, {-20, -100, -20}, {20, -70, 20}), p}));
    // Hemisphere: n = (1, -2, 3), |n| < 3.75. d = (-a, b, -c) with a, b, c in [60, 100]
    // gives n . d <= -360 and |d| < 174: the cosine to n is below -0.55, more than 30
    // degrees beyond the boundary.
    EXPECT_FALSE(window_may_meet(DirectionWindow(hemi, kBound),
                                 {box_points(rng, nq, {-95, 65, -95}, {-65, 95, -65}), p}));
    EXPECT_TRUE(window_may_meet(DirectionWindow(hemi, kBound),
                                {box_points(rng, nq, {65, -95, 65}, {95, -65, 95}), p}));
    // Point u = (2, -1, 5): d in [-46, -26] x [8, 28] x [-100, -80] has u . d < -460: a
    // cone on the opposite side of the point's hemisphere is pruned.
    EXPECT_FALSE(window_may_meet(DirectionWindow(point, kBound),
                                 {box_points(rng, nq, {-41, 13, -95}, {-31, 23, -85}), p}));
    // Great circle x + y + z = 0: cones with x + y + z >= 185 (or <= -185) for all their d
    // are pruned; a cone with directions on both sides is kept (it meets the circle).
    EXPECT_FALSE(window_may_meet(DirectionWindow(circle, kBound),
                                 {box_points(rng, nq, {60, 60, 80}, {100, 100, 100}), p}));
    EXPECT_FALSE(window_may_meet(DirectionWindow(circle, kBound),
                                 {box_points(rng, nq, {-100, -100, -100}, {-60, -60, -80}), p}));
    {
      std::vector<Point3> q = box_points(rng, 1, {60, 60, 80}, {100, 100, 100});
      q.push_back({-90, -90, -90});
      EXPECT_TRUE(window_may_meet(DirectionWindow(circle, kBound), {q, p}));
    }
    // Quarter arc from +x to +y around +z: directions near -x - y (on its circle, beyond
    // both ends) and far above or below its circle are pruned.
    EXPECT_FALSE(window_may_meet(
        DirectionWindow(quarter, kBound),
        {box_points(rng, nq, {-95, -95, -3}, {-80, -80, 3}), {{0, 0, 0}}}));
    EXPECT_FALSE(window_may_meet(DirectionWindow(quarter, kBound),
                                 {box_points(rng, nq, {20, 20, 60}, {40, 40, 100}), p}));
    // Mixed cells: d in [70, 90]^2 x [-105, -85], a cone of about 10 degrees, misses each
    // cell by far: the square's edge x = 2 (half-space -4x + z >= 0), the arc (x > 0 off
    // its circle x = 0), the circle y + 3z = 0 (y + 3z < -160), and the point (-3, 4, -5),
    // about 57 degrees away, so that one of any two orthogonal circles through it leaves
    // the whole cone strictly on one side.
    EXPECT_FALSE(window_may_meet(DirectionWindow(mixed, kBound),
                                 {box_points(rng, nq, {75, 75, -100}, {85, 85, -90}), p}));
  }
  // The exact directions of the point and of the arc, and the arc's end itself.
  EXPECT_TRUE(window_may_meet(DirectionWindow(point, kBound), {{{22, -11, 55}}, {{2, -1, 5}}}));
  EXPECT_TRUE(window_may_meet(DirectionWindow(point, kBound), {{{20, -10, 50}}, {{0, 0, 0}}}));
  EXPECT_TRUE(window_may_meet(DirectionWindow(quarter, kBound), {{{0, 100, 0}}, {{0, 0, 0}}}));
  EXPECT_TRUE(window_may_meet(DirectionWindow(quarter, kBound), {{{37, 61, 0}}, {{0, 0, 0}}}));
  // A square face touching the image at a vertex direction only, from outside.
  EXPECT_TRUE(window_may_meet(DirectionWindow(square, kBound),
                              {{{20, 20, 80}, {40, 20, 80}, {40, 40, 80}}, {{0, 0, 0}}}));
}

TEST(DirectionWindow, FullSphereKeepsEverything) {
  const DirectionWindow w(SphericalImage::full_sphere(), kBound);
  EXPECT_EQ(w.half_spaces(), 0u);
  EXPECT_TRUE(w.may_meet(nullptr, nullptr));
  std::mt19937_64 rng(1);
  for (int t = 0; t < 100; ++t) {
    Face f{box_points(rng, 1 + t % 3, {-100, -100, -100}, {100, 100, 100}),
           box_points(rng, 1 + t % 2, {-100, -100, -100}, {100, 100, 100})};
    EXPECT_TRUE(window_may_meet(w, f));
  }
}

// A face bounded by minor arcs through the given points, the face on their left.
sphere::Face face_through(const std::vector<std::vector<Point3>>& loops) {
  sphere::Face f;
  for (const auto& points : loops) {
    sphere::Loop& loop = f.loops.emplace_back();
    for (size_t i = 0; i < points.size(); ++i) {
      const ExactVec a = v(points[i]), b = v(points[(i + 1) % points.size()]);
      loop.arcs.push_back({a, b, exact::cross(a, b), false});
    }
  }
  return f;
}

// What is left of an LVM outside some occluded directions: faces that are not convex,
// with holes, and arcs and points. The cover must keep every direction of the set, and
// still rule out directions far from it.
TEST(DirectionWindow, CoverByCapsKeepsEveryDirectionOfANonConvexSet) {
  SphericalImage set;
  set.add_face(face_through({{{-1, -1, 1}, {1, -1, 1}, {1, 0, 1}, {0, 0, 1}, {0, 1, 1}, {-1, 1, 1}}}));  // an L
  set.add_face(face_through({{{4, -1, -1}, {4, 1, -1}, {4, 1, 1}, {4, -1, 1}},                      // a frame
                             {{4, -0.5, -0.5}, {4, -0.5, 0.5}, {4, 0.5, 0.5}, {4, 0.5, -0.5}}}));
  set.add_curve(Arc{v(0, -1, -3), v(1, -1, -3), v(0, -3, 1), false});
  set.add_point(v(-2, -5, 1));
  const std::optional<DirectionWindow> w = DirectionWindow::covering(set, {}, kBound);
  ASSERT_TRUE(w.has_value());
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coord(-6, 6);
  int inside = 0, ruled_out = 0;
  for (int t = 0; t < 20000; ++t) {
    const Point3 d{coord(rng), coord(rng), coord(rng)};
    const bool in = set.contains(v(d));
    const bool kept = window_may_meet(*w, {{d}, {{0, 0, 0}}});
    if (in) {
      ++inside;
      EXPECT_TRUE(kept) << d.x << " " << d.y << " " << d.z;
    }
    ruled_out += !kept;
  }
  for (const Point3& d : {Point3{1, -1, -3}, Point3{0.5, -1, -3}, Point3{-2, -5, 1}, Point3{1, 0, 1}, Point3{4, 1, 1}}) {
    EXPECT_TRUE(set.contains(v(d)));
    EXPECT_TRUE(window_may_meet(*w, {{d}, {{0, 0, 0}}}));
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(ruled_out, 10000);  // most of the sphere is far from the set
  // The frame's hole and the L's missing quarter are not ruled out (a cap holds them),
  // but the far side is.
  EXPECT_FALSE(window_may_meet(*w, {{{0, 0, -1}}, {{0, 0, 0}}}));
}

TEST(DirectionWindow, CoverKeepsToTheConvexCellThatHoldsTheSet) {
  SphericalImage set;
  set.add_face(face_through({{{-1, -1, 1}, {1, -1, 1}, {1, 0, 1}, {0, 0, 1}, {0, 1, 1}, {-1, 1, 1}}}));
  sphere::Face square = face_through({{{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}});
  square.convex = true;
  const std::optional<DirectionWindow> capped = DirectionWindow::covering(set, {}, kBound);
  const std::optional<DirectionWindow> within = DirectionWindow::covering(set, square, kBound);
  ASSERT_TRUE(capped && within);
  // Beside the square, inside the L's cap: only the second window rules it out.
  const Point3 beside{1.05, 0, 1};
  EXPECT_TRUE(window_may_meet(*capped, {{beside}, {{0, 0, 0}}}));
  EXPECT_FALSE(window_may_meet(*within, {{beside}, {{0, 0, 0}}}));
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> coord(-1.2, 1.2);
  for (int t = 0; t < 5000; ++t) {
    const Point3 d{coord(rng), coord(rng), 1};
    if (set.contains(v(d))) EXPECT_TRUE(window_may_meet(*within, {{d}, {{0, 0, 0}}}));
  }
}

TEST(DirectionWindow, NoCoverForFacesNoSmallCapHolds) {
  // Bounded by a full circle.
  EXPECT_FALSE(DirectionWindow::covering(SphericalImage::hemisphere(v(0, 0, 1)), {}, kBound));
  // Everything but a small square: its boundary lies in a small cap, the face does not.
  SphericalImage outside;
  outside.add_face(face_through({{{-1, 1, 4}, {1, 1, 4}, {1, -1, 4}, {-1, -1, 4}}}));
  EXPECT_FALSE(DirectionWindow::covering(outside, {}, kBound));
  // A band around the equator: no cap smaller than a hemisphere holds it.
  SphericalImage band;
  band.add_face(face_through({{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}},
                              {{0, -1, 1}, {-1, 0, 1}, {0, 1, 1}, {1, 0, 1}}}));
  EXPECT_FALSE(DirectionWindow::covering(band, {}, kBound));
  EXPECT_FALSE(DirectionWindow::covering(SphericalImage::full_sphere(), {}, kBound));
}

// The window's answer is that of its sides taken one by one (a face is left out when one
// side of every cell has it wholly outside), however it reaches it: here on a 420-sided
// polygon much like a pocket floor's LVM, with faces around its border, where a shortcut
// that took the polygon for a round cap would keep faces a side rules out.
TEST(DirectionWindow, ManySidedCellDecidesAsItsSides) {
  constexpr int kSides = 420;
  const double radius = 54 * M_PI / 180;
  // The cap around (0, 0, 1), tilted about x by 0.3 radians so that no axis is special.
  auto direction = [](double polar, double azimuth) {
    const Point3 d{std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar)};
    const double c = std::cos(0.3), s = std::sin(0.3);
    return Point3{d.x, c * d.y - s * d.z, s * d.y + c * d.z};
  };
  std::vector<Point3> corners;
  for (int i = 0; i < kSides; ++i) corners.push_back(direction(radius, 2 * M_PI * i / kSides));
  const SphericalImage image = polygon(corners);
  const DirectionWindow w(image, kBound);
  ASSERT_EQ(w.half_spaces(), size_t(kSides));
  auto sides_say_meet = [&](const Face& f) {
    for (const Arc& arc : image.faces()[0].loops[0].arcs) {
      const auto m = arc.normal.unit();
      auto value = [&](const Point3& x) { return m[0] * x.x + m[1] * x.y + m[2] * x.z; };
      double q_max = -HUGE_VAL, p_min = HUGE_VAL;
      for (const Point3& q : f.q) q_max = std::max(q_max, value(q));
      for (const Point3& p : f.p) p_min = std::min(p_min, value(p));
      if (q_max - p_min < -1e-9 * kBound) return false;
    }
    return true;
  };
  std::mt19937_64 rng(420);
  std::uniform_real_distribution<double> azimuth(0, 2 * M_PI), off(-0.02, 0.02), jitter(-1, 1);
  int kept = 0, left_out = 0;
  for (int t = 0; t < 20000; ++t) {
    // q0 - p0 about 60 units along a direction within 0.02 radians of the border (the
    // corners' circle; the sides cut inside it by up to 1 - cos(pi / 420) of the radius).
    Face f;
    f.p.push_back({jitter(rng) * 20, jitter(rng) * 20, jitter(rng) * 20});
    const Point3 d = direction(radius + off(rng), azimuth(rng));
    f.q.push_back({f.p[0].x + 60 * d.x, f.p[0].y + 60 * d.y, f.p[0].z + 60 * d.z});
    for (int i = 1 + int(rng() % 3); i > 1; --i) {
      const Point3& q = f.q[0];
      f.q.push_back({q.x + jitter(rng) * 0.3, q.y + jitter(rng) * 0.3, q.z + jitter(rng) * 0.3});
    }
    const bool meet = sides_say_meet(f);
    ASSERT_EQ(window_may_meet(w, f), meet) << describe(f);
    (meet ? kept : left_out)++;
  }
  EXPECT_GT(kept, 2000);
  EXPECT_GT(left_out, 2000);
}

}  // namespace
}  // namespace gvm
