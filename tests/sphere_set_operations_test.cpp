// Set operations on closed sets of directions against their definition, pointwise, at
// random and special exact directions; hand-made boundary cases of the non-regularized
// difference; is_subset across representations.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "sphere/clearance.h"
#include "sphere/local_visibility_map.h"
#include "sphere/set_operations.h"
#include "sphere_random_images.h"

namespace gvm::sphere {
namespace {

using exact::ExactVec;
using testing::iv;

// The same set, decided exactly whatever the representation.
bool same_set(const SphericalImage& a, const SphericalImage& b) { return is_subset(a, b) && is_subset(b, a); }

SphericalImage lvm(std::vector<ExactVec> normals) { return local_visibility_map(normals); }

// The polygon {x0 <= x/z <= x1, y0 <= y/z <= y1} around +z, as an LVM (convex).
SphericalImage square(int x0, int y0, int x1, int y1) {
  return lvm({iv(1, 0, -x0), iv(-1, 0, x1), iv(0, 1, -y0), iv(0, -1, y1)});
}

SphericalImage curve(const ExactVec& from, const ExactVec& to, const ExactVec& normal) {
  SphericalImage s;
  s.add_curve({from, to, normal});
  return s;
}

SphericalImage points(const std::vector<ExactVec>& ps) {
  SphericalImage s;
  for (const ExactVec& p : ps) s.add_point(p);
  return s;
}

// Canonical output: points on no curve and in no face, curves crossing no face.
void expect_canonical(const SphericalImage& r) {
  for (const ExactVec& p : r.points()) {
    for (const Face& f : r.faces()) EXPECT_FALSE(face_contains(f, p)) << r.description();
    for (const Arc& a : r.curves()) EXPECT_FALSE(arc_contains(a, p)) << r.description();
  }
  for (const Arc& a : r.curves()) {
    const std::vector<ExactVec> v = split_arc(a);
    for (size_t i = 0; i + 1 < v.size(); ++i) {
      for (const Face& f : r.faces()) EXPECT_FALSE(face_contains(f, v[i] + v[i + 1])) << r.description();
    }
  }
}

// Operands of every kind, including results of set operations (general faces, holes,
// faces touching at points, curves and points beside faces).
SphericalImage random_operand(std::mt19937_64& rng) {
  switch (testing::uniform(rng, 0, 7)) {
    case 0:
      return set_difference(testing::random_image(rng), testing::random_image(rng));
    case 1:
      return set_union(testing::random_image(rng), testing::random_image(rng));
    default:
      return testing::random_image(rng);
  }
}

// u in the interior of b's 2-cells, off their boundaries, or on them: then a tiny cap
// around u (far below the angular size of these small-integer constructions) lies in b
// iff u is interior -- an independent decision by the clearance module.
bool in_interior(const SphericalImage& b, const ExactVec& u) {
  if (!testing::on_face_boundary(b, u)) return testing::in_some_face(b, u);
  return contains_cap(b, u, 0x1p-80);
}

TEST(SphereSetOperations, RandomOperandsAgainstTheDefinition) {
  constexpr uint64_t kBaseSeed = 20261126;
  int subsets = 0, difference_checked = 0;
  for (uint64_t i = 0; i < 250; ++i) {
    const uint64_t seed = kBaseSeed + i;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    const SphericalImage a = random_operand(rng), b = random_operand(rng);
    SCOPED_TRACE("a: " + a.description() + "; b: " + b.description());
    const SphericalImage u = set_union(a, b), n = set_intersection(a, b), d = set_difference(a, b);
    expect_canonical(u);
    expect_canonical(n);
    expect_canonical(d);
    const bool a_in_b = is_subset(a, b);
    subsets += a_in_b;
    bool counterexample = false;
    for (const ExactVec& x : testing::probe_directions(rng, {&a, &b, &u, &n, &d}, 150)) {
      const bool in_a = a.contains(x), in_b = b.contains(x);
      ASSERT_EQ(u.contains(x), in_a || in_b) << u.description();
      ASSERT_EQ(n.contains(x), in_a && in_b) << n.description();
      // a - Int(b), with the interior decided off and on b's face boundaries.
      const bool in_d = d.contains(x);
      if (in_d) ASSERT_TRUE(in_a) << d.description();
      if (in_a && !in_b) ASSERT_TRUE(in_d) << d.description();
      ASSERT_EQ(in_d, in_a && !in_interior(b, x)) << d.description();
      difference_checked += testing::on_face_boundary(b, x);
      counterexample |= in_a && !in_b;
    }
    if (counterexample) ASSERT_FALSE(a_in_b);
    // Subsets that hold by construction, and a <= b iff a + b <= b iff a <= a * b.
    ASSERT_TRUE(is_subset(n, a) && is_subset(n, b) && is_subset(a, u) && is_subset(b, u));
    ASSERT_TRUE(is_subset(d, a));
    ASSERT_TRUE(is_subset(a, a) && same_set(u, set_union(b, a)) && same_set(n, set_intersection(b, a)));
    ASSERT_EQ(a_in_b, is_subset(u, b));
    ASSERT_EQ(a_in_b, is_subset(a, n));
  }
  EXPECT_GT(subsets, 20);
  EXPECT_GT(difference_checked, 1000);  // directions on b's face boundaries
}

TEST(SphereSetOperations, DifferenceKeepsArcsAndPointsOfAOnTheBoundaryOfB) {
  const SphericalImage upper = SphericalImage::hemisphere(iv(0, 0, 1));
  // An arc of a along b's boundary survives, whole.
  const SphericalImage equator_arc = curve(iv(1, 0, 0), iv(0, 1, 0), iv(0, 0, 1));
  EXPECT_EQ(set_difference(equator_arc, upper), equator_arc);
  // An arc from inside b across its boundary keeps the closed part outside Int(b).
  const SphericalImage crossing = curve(iv(1, 0, 1), iv(1, 0, -1), iv(0, 1, 0));
  EXPECT_EQ(set_difference(crossing, upper), curve(iv(1, 0, 0), iv(1, 0, -1), iv(0, 1, 0)));
  // A point of a inside b goes, on b's boundary or outside it stays.
  EXPECT_TRUE(set_difference(points({iv(1, 2, 3)}), upper).is_empty());
  EXPECT_EQ(set_difference(points({iv(1, 2, 3), iv(1, 2, 0), iv(1, 2, -3)}), upper),
            points({iv(1, 2, 0), iv(1, 2, -3)}));
  // A 180-degree arc in b: its open part is in Int(b), its antipodal ends on b's boundary.
  const SphericalImage half = curve(iv(1, 0, 0), iv(-1, 0, 0), iv(0, 0, 1));
  const SphericalImage y_up = SphericalImage::hemisphere(iv(0, 1, 0));
  EXPECT_EQ(set_difference(half, y_up), points({iv(1, 0, 0), iv(-1, 0, 0)}));
  EXPECT_EQ(set_intersection(half, y_up), half);
}

TEST(SphereSetOperations, AFaceMinusItselfIsItsBoundary) {
  const SphericalImage sq = square(-2, -1, 3, 2);
  const SphericalImage d = set_difference(sq, sq);
  EXPECT_EQ(d.dimension(), 1);
  EXPECT_EQ(d.curves().size(), 4u);
  EXPECT_TRUE(d.contains(iv(-2, -1, 1)) && d.contains(iv(0, 2, 1)) && d.contains(iv(3, 0, 1)));
  EXPECT_FALSE(d.contains(iv(0, 0, 1)));
  // Boundary loops of the face, as curves: the same set as the closed loop arcs.
  SphericalImage loop_arcs;
  for (const Arc& a : sq.faces()[0].loops[0].arcs) loop_arcs.add_curve(a);
  EXPECT_TRUE(same_set(d, loop_arcs));
  EXPECT_EQ(d, loop_arcs);
}

TEST(SphereSetOperations, FacesSharingAnEdgeOrACorner) {
  const SphericalImage left = square(-2, -1, 0, 1), right = square(0, -1, 2, 1), corner = square(2, 1, 3, 2);
  // Closed: a face keeps the edge it shares with the face removed.
  EXPECT_EQ(set_difference(left, right), left);
  EXPECT_TRUE(set_difference(left, right).faces()[0].convex);
  // Non-regularized: touching faces meet in an arc or a point.
  EXPECT_EQ(set_intersection(left, right), curve(iv(0, -1, 1), iv(0, 1, 1), iv(-1, 0, 0)));
  EXPECT_EQ(set_intersection(right, corner), points({iv(2, 1, 1)}));
  // The union is one face across the shared edge (a 4 x 2 rectangle), merged arcs.
  const SphericalImage u = set_union(left, right);
  EXPECT_EQ(u, square(-2, -1, 2, 1));
  EXPECT_EQ(u.faces().size(), 1u);
  // An arc along an edge of the face and beyond it: the part outside stays a curve.
  const SphericalImage along = curve(iv(0, -3, 1), iv(0, 1, 1), iv(-1, 0, 0));
  const SphericalImage ua = set_union(right, along);
  ASSERT_EQ(ua.curves().size(), 1u);
  EXPECT_TRUE(same_set(ua, testing::combine({right, curve(iv(0, -3, 1), iv(0, -1, 1), iv(-1, 0, 0))})));
}

TEST(SphereSetOperations, HemispheresGreatCirclesAndTheFullSphere) {
  const SphericalImage up = SphericalImage::hemisphere(iv(0, 0, 1)), down = SphericalImage::hemisphere(iv(0, 0, -1));
  EXPECT_TRUE(set_union(up, down).is_full_sphere());
  EXPECT_EQ(set_intersection(up, down), SphericalImage::great_circle(iv(0, 0, 1)));
  EXPECT_EQ(set_difference(up, down), up);
  EXPECT_EQ(set_difference(SphericalImage::full_sphere(), up), down);
  EXPECT_EQ(set_union(up, SphericalImage::empty()), up);
  EXPECT_EQ(set_intersection(SphericalImage::full_sphere(), up), up);
  EXPECT_TRUE(set_difference(up, SphericalImage::full_sphere()).is_empty());
  EXPECT_TRUE(set_union(SphericalImage::empty(), SphericalImage::empty()).is_empty());
  EXPECT_TRUE(set_intersection(SphericalImage::full_sphere(), SphericalImage::full_sphere()).is_full_sphere());
  EXPECT_TRUE(is_subset(SphericalImage::empty(), SphericalImage::empty()));
  EXPECT_TRUE(is_subset(up, SphericalImage::full_sphere()));
  EXPECT_FALSE(is_subset(SphericalImage::full_sphere(), up));
  EXPECT_TRUE(is_subset(SphericalImage::full_sphere(), set_union(up, down)));
  // A lune of two hemispheres, and its complement's closure by difference.
  const SphericalImage east = SphericalImage::hemisphere(iv(1, 0, 0));
  const SphericalImage lune = set_intersection(up, east);
  EXPECT_EQ(lune, lvm({iv(0, 0, 1), iv(1, 0, 0)}));
  EXPECT_TRUE(same_set(set_difference(SphericalImage::full_sphere(), lune), set_union(down, SphericalImage::hemisphere(iv(-1, 0, 0)))));
}

TEST(SphereSetOperations, AntipodalPointsAndGreatCircles) {
  const SphericalImage pair = points({iv(1, 1, 0), iv(-1, -1, 0)});
  const SphericalImage equator = SphericalImage::great_circle(iv(0, 0, 1));
  EXPECT_EQ(set_intersection(pair, equator), pair);
  EXPECT_EQ(set_union(pair, equator), equator);
  EXPECT_TRUE(set_difference(pair, equator) == pair);  // the circle has no interior
  EXPECT_TRUE(set_difference(equator, pair) == equator);
  EXPECT_TRUE(is_subset(pair, equator));
  EXPECT_FALSE(is_subset(equator, pair));
  // Two great circles meet in two antipodal points.
  EXPECT_EQ(set_intersection(equator, SphericalImage::great_circle(iv(1, -1, 0))), pair);
}

TEST(SphereSetOperations, SubsetIsExactForAnyRepresentation) {
  // One square as one convex face, as two general faces, and as overlapping faces.
  const SphericalImage whole = square(-2, -2, 2, 2);
  const SphericalImage halves = testing::combine({square(-2, -2, 0, 2), square(0, -2, 2, 2)});
  const SphericalImage overlapping = testing::combine({square(-2, -2, 1, 2), square(-1, -2, 2, 2)});
  EXPECT_TRUE(same_set(whole, halves));
  EXPECT_TRUE(same_set(whole, overlapping));
  EXPECT_TRUE(same_set(halves, overlapping));
  EXPECT_EQ(set_union(halves, SphericalImage::empty()), whole);
  EXPECT_FALSE(is_subset(whole, square(-2, -2, 2, 1)));
  // A single direction outside, on a corner: the corner of a larger square.
  EXPECT_FALSE(is_subset(testing::combine({whole, points({iv(3, 3, 1)})}), square(-2, -2, 2, 2)));
  EXPECT_TRUE(is_subset(testing::combine({whole, points({iv(2, 2, 1)})}), square(-2, -2, 2, 2)));
  // An arc inside a face but along a curve of the other set.
  EXPECT_TRUE(is_subset(curve(iv(0, -1, 1), iv(0, 1, 1), iv(-1, 0, 0)), halves));
}

}  // namespace
}  // namespace gvm::sphere
