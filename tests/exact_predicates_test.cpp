// Exactness of the predicates on inputs built to be degenerate. The reference is GMP's
// rational type, an implementation independent of the engine's dyadic arithmetic.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "exact/exact_vec.h"
#include "exact/predicates.h"

namespace gvm::exact {
namespace {

mpq_class q(double d) { return mpq_class(d); }

Sign sign_of(const mpq_class& v) { return static_cast<Sign>(sgn(v)); }

Sign reference_det_diff(const Point3& a0, const Point3& a1, const Point3& b0, const Point3& b1,
                        const Point3& c0, const Point3& c1) {
  mpq_class a[3], b[3], c[3];
  for (int i = 0; i < 3; ++i) {
    a[i] = q(a1[i]) - q(a0[i]);
    b[i] = q(b1[i]) - q(b0[i]);
    c[i] = q(c1[i]) - q(c0[i]);
  }
  mpq_class det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                  a[2] * (b[0] * c[1] - b[1] * c[0]);
  return sign_of(det);
}

Sign reference_orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return reference_det_diff(a, b, a, c, a, d);
}

// The 3-4-5 rotation about z, scaled by 5 so that integer points stay integer: the
// rotated copy of an axis-aligned configuration has no axis-aligned special cases.
Point3 rot345z(const Point3& p) { return {3 * p.x + 4 * p.y, -4 * p.x + 3 * p.y, 5 * p.z}; }
Point3 rot345x(const Point3& p) { return {5 * p.x, 3 * p.y + 4 * p.z, -4 * p.y + 3 * p.z}; }
Point3 rotate(const Point3& p) { return rot345x(rot345z(p)); }

TEST(ExactPredicates, CoplanarPointsWithMixedMagnitudesGiveZero) {
  // All on the plane x + y + z = 0, coordinates from 1e-12 to 1e12 in one configuration:
  // the rounded differences make a naive determinant non-zero.
  Point3 a{1e12, -1e12, 0}, b{1e-12, 0, -1e-12}, c{0, 0x1p-40, -0x1p-40},
      d{0x1p40, 1, -(0x1p40 + 1)};
  EXPECT_EQ(orient3d(a, b, c, d), Sign::kZero);
  EXPECT_EQ(reference_orient3d(a, b, c, d), Sign::kZero);
  // One ulp off the plane is decided, with the sign of the exact value.
  Point3 above{d.x, d.y, std::nextafter(d.z, 0.0)};
  Point3 below{d.x, d.y, std::nextafter(d.z, -1e300)};
  EXPECT_EQ(orient3d(a, b, c, above), reference_orient3d(a, b, c, above));
  EXPECT_EQ(orient3d(a, b, c, below), reference_orient3d(a, b, c, below));
  EXPECT_NE(orient3d(a, b, c, above), Sign::kZero);
  EXPECT_EQ(orient3d(a, b, c, above), -orient3d(a, b, c, below));
}

TEST(ExactPredicates, ExactlyParallelWallsUnderRationalRotation) {
  // Two opposite walls of a slot, x = 0 and x = 7, each split into two triangles; the
  // normals of the walls are exactly antiparallel and every wall point lies on its plane.
  const Point3 w0[] = {{0, 0, 0}, {0, 10, 0}, {0, 10, 5}, {0, 0, 5}};
  const Point3 w1[] = {{7, 0, 0}, {7, 0, 5}, {7, 10, 5}, {7, 10, 0}};
  for (bool rotated : {false, true}) {
    auto r = [&](const Point3& p) { return rotated ? rotate(p) : p; };
    // Coplanar triangles of one wall: every vertex on the other triangle's plane.
    EXPECT_EQ(orient3d(r(w0[0]), r(w0[1]), r(w0[2]), r(w0[3])), Sign::kZero);
    EXPECT_EQ(orient3d(r(w1[0]), r(w1[1]), r(w1[2]), r(w1[3])), Sign::kZero);
    // Parallel planes: the normal of wall 0 is perpendicular to every edge of wall 1.
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(det_diff(r(w0[0]), r(w0[1]), r(w0[0]), r(w0[2]), r(w1[i]), r(w1[(i + 1) % 4])),
                Sign::kZero);
    }
    ExactVec n0 = triangle_normal(r(w0[0]), r(w0[1]), r(w0[2]));
    ExactVec n1 = triangle_normal(r(w1[0]), r(w1[1]), r(w1[2]));
    EXPECT_TRUE(parallel(n0, n1));
    EXPECT_FALSE(same_direction(n0, n1));
    EXPECT_TRUE(same_direction(n0, -n1));
    // Wall 1 is on the positive side of wall 0 (normal +x), wall 0 on the positive side
    // of wall 1 (normal -x): they face each other.
    EXPECT_EQ(orient3d(r(w0[0]), r(w0[1]), r(w0[2]), r(w1[0])), Sign::kPositive);
    EXPECT_EQ(orient3d(r(w1[0]), r(w1[1]), r(w1[2]), r(w0[0])), Sign::kPositive);
  }
}

TEST(ExactPredicates, PointsExactlyOnPlanesAndLines) {
  for (bool rotated : {false, true}) {
    auto r = [&](const Point3& p) { return rotated ? rotate(p) : p; };
    Point3 a = r({1, 2, 3}), b = r({4, 6, 3}), c = r({-2, 5, 3});
    EXPECT_EQ(orient3d(a, b, c, r({100, -300, 3})), Sign::kZero);
    EXPECT_TRUE(collinear(a, b, r({7, 10, 3})));   // a + 2 (b - a)
    EXPECT_FALSE(collinear(a, b, r({7, 10, 4})));
    // (b - a) = (3, 4, 0) is exactly perpendicular to (-4, 3, 0), rotated or not.
    EXPECT_EQ(dot_diff(a, b, a, r({-3, 5, 3})), Sign::kZero);
    EXPECT_EQ(dot_diff(a, b, a, c), Sign::kPositive);
  }
}

TEST(ExactPredicates, Orient2dInEveryProjection) {
  Point3 a{0, 0, 0}, b{1, 1, 1}, c{2, 2, 2}, d{1, 2, 3};
  for (int drop = 0; drop < 3; ++drop) {
    EXPECT_EQ(orient2d(a, b, c, drop), Sign::kZero);
    EXPECT_NE(orient2d(a, b, d, drop), Sign::kZero);
  }
  // Cyclic axis order: dropping z gives the usual (x, y) orientation.
  EXPECT_EQ(orient2d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2), Sign::kPositive);
  EXPECT_EQ(orient2d({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0), Sign::kPositive);
  EXPECT_EQ(orient2d({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 1), Sign::kPositive);
}

// Random configurations made degenerate on purpose (coplanar by construction, coordinates
// spread over 2^-60 .. 2^60) agree with the rational reference, seed printed on failure.
TEST(ExactPredicates, RandomDegenerateConfigurationsMatchRationalReference) {
  const unsigned seed = 20261122;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> small(-8, 8), expo(-60, 60);
  auto scaled = [&] { return std::ldexp(small(rng), expo(rng)); };
  int zeros = 0;
  for (int iter = 0; iter < 20000; ++iter) {
    Point3 a{scaled(), scaled(), scaled()};
    Point3 u{static_cast<double>(small(rng)), static_cast<double>(small(rng)),
             static_cast<double>(small(rng))};
    Point3 v{static_cast<double>(small(rng)), static_cast<double>(small(rng)),
             static_cast<double>(small(rng))};
    // b, c, d = a + integer combinations of u, v: coplanar whenever no rounding happens,
    // and nearly coplanar otherwise.
    auto comb = [&](int s, int t) {
      return Point3{a.x + s * u.x + t * v.x, a.y + s * u.y + t * v.y, a.z + s * u.z + t * v.z};
    };
    Point3 b = comb(1, 0), c = comb(0, 1), d = comb(small(rng), small(rng));
    Sign got = orient3d(a, b, c, d);
    ASSERT_EQ(got, reference_orient3d(a, b, c, d)) << "iteration " << iter;
    ASSERT_EQ(PlaneSide(a, b, c)(d), got) << "iteration " << iter;
    zeros += got == Sign::kZero;
    Point3 e{scaled(), scaled(), scaled()};
    ASSERT_EQ(det_diff(a, b, c, d, e, a), reference_det_diff(a, b, c, d, e, a));
  }
  EXPECT_GT(zeros, 1000);  // the construction really is degenerate
}

// The first stage decides in plain doubles with an error bound from the permanent; these
// inputs sit where such a bound is tight or fails: determinants a few ulps of the
// permanent from zero, products that underflow beside ones that do not, magnitudes near
// overflow, and the ends of the range the exact stage takes without GMP. Every sign
// against rationals.
TEST(ExactPredicates, NearlyDegenerateAndExtremeMagnitudesMatchRationalReference) {
  std::mt19937_64 rng(20261130);
  std::uniform_int_distribution<int> small(-9, 9), ulps(-3, 3);
  auto vec = [&](int lo, int hi) {
    std::uniform_int_distribution<int> expo(lo, hi);
    return Point3{std::ldexp(small(rng), expo(rng)), std::ldexp(small(rng), expo(rng)),
                  std::ldexp(small(rng), expo(rng))};
  };
  auto nudge = [&](double x) {
    for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) x = std::nextafter(x, k > 0 ? 1e308 : -1e308);
    return x;
  };
  const Point3 o{0, 0, 0};
  int decided_near_zero = 0;
  for (int iter = 0; iter < 40000; ++iter) {
    SCOPED_TRACE("iteration " + std::to_string(iter));
    Point3 a, b, c;
    switch (iter % 5) {
      case 0: {  // c = s a + t b in doubles, then a few ulps off: |det| ~ ulps of the permanent
        a = vec(-20, 20), b = vec(-20, 20);
        const double s = small(rng) * 0.37, t = small(rng) * 1.91;
        c = {nudge(s * a.x + t * b.x), nudge(s * a.y + t * b.y), nudge(s * a.z + t * b.z)};
        break;
      }
      case 1:  // outer factors large, inner products underflowing or subnormal
        a = vec(150, 250), b = vec(-700, -480), c = vec(-700, -480);
        break;
      case 2:  // subnormal coordinates
        a = vec(-1074, -1000), b = vec(-1074, -1000), c = vec(-60, 60);
        break;
      case 3: {  // the ends of the range the expansion stage takes, a few ulps off degenerate
        a = vec(-200, -190), b = vec(190, 199);
        const double s = std::ldexp(small(rng), 200), t = std::ldexp(small(rng), -200);
        c = {nudge(s * a.x + t * b.x), nudge(s * a.y + t * b.y), nudge(s * a.z + t * b.z)};
        break;
      }
      default:  // near overflow: the permanent is not finite or beyond 2^1000
        a = vec(300, 340), b = vec(300, 340), c = vec(300, 345);
        break;
    }
    const Sign got = det_diff(o, a, o, b, o, c);
    ASSERT_EQ(got, reference_det_diff(o, a, o, b, o, c));
    ASSERT_EQ(PlaneSide(o, a, b)(c), got);  // orient3d(o, a, b, c), by its other first stage
    decided_near_zero += iter % 5 == 0 && got != Sign::kZero;
    for (int drop = 0; drop < 3; ++drop) {
      const Point3 e{drop == 0 ? 1.0 : 0.0, drop == 1 ? 1.0 : 0.0, drop == 2 ? 1.0 : 0.0};
      ASSERT_EQ(orient2d(o, a, b, drop), reference_det_diff(o, a, o, b, o, e)) << "drop " << drop;
    }
  }
  EXPECT_GT(decided_near_zero, 3000);
}

TEST(ExactPredicates, AxisAlignedPlanesMatchRationalReference) {
  // orient3d and orient2d decide planes normal to an axis, and triangles sharing a
  // coordinate, without their exact stage: every sign against rationals, including
  // points on the plane, degenerate triangles and coordinates that differ in the last bit.
  std::mt19937_64 rng(20261129);
  std::uniform_int_distribution<int> small(-3, 3), axis_of(0, 2), pick(0, 3);
  const double levels[] = {0.1, 0.1 + 0x1p-55, 0.3, -2.5};
  auto coordinate = [&] { return pick(rng) == 0 ? levels[pick(rng)] : small(rng) * 0.1; };
  int zeros = 0, aligned = 0;
  for (int iter = 0; iter < 20000; ++iter) {
    const int axis = axis_of(rng);
    const double level = levels[pick(rng)];
    Point3 t[3], d{coordinate(), coordinate(), coordinate()};
    for (Point3& p : t) {
      p = {coordinate(), coordinate(), coordinate()};
      if (iter % 4 != 3) (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = level;  // on the plane
    }
    if (iter % 3 == 0) (axis == 0 ? d.x : axis == 1 ? d.y : d.z) = level;
    const Sign got = orient3d(t[0], t[1], t[2], d);
    ASSERT_EQ(got, reference_orient3d(t[0], t[1], t[2], d)) << "iteration " << iter;
    zeros += got == Sign::kZero;
    aligned += iter % 4 != 3;
    for (int drop = 0; drop < 3; ++drop) {
      const Point3 o{0, 0, 0}, e{drop == 0 ? 1.0 : 0.0, drop == 1 ? 1.0 : 0.0, drop == 2 ? 1.0 : 0.0};
      // Component `drop` of (t1 - t0) x (t2 - t0) is det(t1 - t0, t2 - t0, e_drop).
      ASSERT_EQ(orient2d(t[0], t[1], t[2], drop), reference_det_diff(t[0], t[1], t[0], t[2], o, e))
          << "iteration " << iter << ", drop " << drop;
    }
  }
  EXPECT_GT(zeros, 3000);
  EXPECT_GT(aligned, 10000);
}

TEST(ExactPredicates, DifferenceDetMatchesRationalReference) {
  // DifferenceDet decides a pair of differences both normal to an axis (edges and faces
  // of CAD parts) by the third difference's coordinate there: every sign against
  // rationals, with the pair normal to an axis in three of four iterations (parallel
  // pairs and coordinates that differ in the last bit among them), the third difference
  // along the pair's plane in a third of them.
  std::mt19937_64 rng(20261202);
  std::uniform_int_distribution<int> small(-3, 3), axis_of(0, 2), pick(0, 3);
  const double levels[] = {0.1, 0.1 + 0x1p-55, 0.3, -2.5};
  auto coordinate = [&] { return pick(rng) == 0 ? levels[pick(rng)] : small(rng) * 0.1; };
  auto set = [](Point3& p, int axis, double v) { (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = v; };
  int zeros = 0, aligned = 0;
  for (int iter = 0; iter < 20000; ++iter) {
    SCOPED_TRACE("iteration " + std::to_string(iter));
    const int axis = axis_of(rng);
    Point3 v[6];
    for (Point3& p : v) p = {coordinate(), coordinate(), coordinate()};
    if (iter % 4 != 3) {
      set(v[1], axis, v[0][axis]);
      set(v[3], axis, v[2][axis]);
      ++aligned;
    }
    if (iter % 3 == 0) set(v[5], axis, v[4][axis]);
    if (iter % 7 == 0) v[3] = {v[2].x + v[1].x - v[0].x, v[2].y + v[1].y - v[0].y, v[2].z + v[1].z - v[0].z};
    const DifferenceDet det(v[0], v[1], v[2], v[3]);
    const Sign got = det(v[4], v[5]);
    ASSERT_EQ(got, reference_det_diff(v[0], v[1], v[2], v[3], v[4], v[5]));
    ASSERT_EQ(got, det_diff(v[0], v[1], v[2], v[3], v[4], v[5]));
    ASSERT_EQ(PlaneSide(v[0], v[1], v[3]).along(v[4], v[5]), reference_det_diff(v[0], v[1], v[0], v[3], v[4], v[5]));
    zeros += got == Sign::kZero;
  }
  EXPECT_GT(zeros, 3000);
  EXPECT_GT(aligned, 10000);
}

TEST(ExactVec, CrossProductDirectionsAreExact) {
  // Edge direction of two rotated walls meeting at a concave edge: n0 x n1 is exactly the
  // rotated z axis.
  Point3 o = rotate({0, 0, 0});
  ExactVec n_floor = triangle_normal(o, rotate({1, 0, 0}), rotate({0, 1, 0}));
  ExactVec n_wall = triangle_normal(o, rotate({0, 1, 0}), rotate({0, 0, 1}));
  ExactVec edge = cross(n_floor, n_wall);
  ExactVec y_axis = ExactVec::from_point(rotate({0, 1, 0})) - ExactVec::from_point(o);
  EXPECT_TRUE(parallel(edge, y_axis));
  EXPECT_EQ(sign_det(n_floor, n_wall, edge), Sign::kPositive);
  EXPECT_EQ(sign_dot(edge, n_floor), Sign::kZero);
  EXPECT_TRUE(is_zero(cross(edge, edge)));
  auto u = edge.unit();
  EXPECT_NEAR(u[0] * u[0] + u[1] * u[1] + u[2] * u[2], 1.0, 1e-15);
}

// triangle_normal and point_difference are single nodes with their own exact stage: their
// signs against each other and as factors of cross products, on coplanar and nearly
// coplanar points, equal the rational reference and the same expressions built as trees
// of points (from_point, -, cross).
TEST(ExactVec, OneNodeNormalsAndDifferencesMatchTheirTrees) {
  std::mt19937_64 rng(20261206);
  std::uniform_int_distribution<int> small(-9, 9), wide(-30, 30), narrow(-2, 3), ulps(-2, 2);
  bool exactly = false;  // even iterations: coordinates whose combinations below are exact
  auto point = [&] {
    auto& expo = exactly ? narrow : wide;
    return Point3{std::ldexp(small(rng), expo(rng)), std::ldexp(small(rng), expo(rng)), std::ldexp(small(rng), expo(rng))};
  };
  auto nudge = [&](double x) {
    for (int k = exactly ? 0 : ulps(rng); k != 0; k += k > 0 ? -1 : 1) x = std::nextafter(x, k > 0 ? 1e308 : -1e308);
    return x;
  };
  auto tree_normal = [](const Point3& a, const Point3& b, const Point3& c) {
    const ExactVec pa = ExactVec::from_point(a);
    return cross(ExactVec::from_point(b) - pa, ExactVec::from_point(c) - pa);
  };
  int zeros = 0;
  for (int iter = 0; iter < 20000; ++iter) {
    SCOPED_TRACE("iteration " + std::to_string(iter));
    exactly = iter % 2 == 0;
    const Point3 a = point(), b = point(), c = point();
    // d on the plane of a, b, c (odd iterations: in doubles, then a few ulps off), and a
    // point on the line a b.
    const double s = small(rng) * 0.25, t = small(rng) * 0.5;
    const Point3 d{nudge(a.x + s * (b.x - a.x) + t * (c.x - a.x)), nudge(a.y + s * (b.y - a.y) + t * (c.y - a.y)),
                   nudge(a.z + s * (b.z - a.z) + t * (c.z - a.z))};
    const Point3 on_line{a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.z + s * (b.z - a.z)};
    const ExactVec n = triangle_normal(a, b, c), ad = point_difference(d, a);
    const Sign want = reference_orient3d(a, b, c, d);
    ASSERT_EQ(sign_dot(n, ad), want);
    ASSERT_EQ(sign_dot(tree_normal(a, b, c), ExactVec::from_point(d) - ExactVec::from_point(a)), want);
    ASSERT_EQ(sign_det(point_difference(b, a), point_difference(c, a), ad), want);
    ASSERT_EQ(is_zero(triangle_normal(a, b, on_line)), is_zero(tree_normal(a, b, on_line)));
    ASSERT_TRUE(parallel(n, tree_normal(a, b, c)));
    ASSERT_EQ(sign_dot(cross(n, ad), n), Sign::kZero);  // a factor of a cross product, by construction
    for (int i = 0; i < 3; ++i) {
      const mpq_class coordinate = (q(b[(i + 1) % 3]) - q(a[(i + 1) % 3])) * (q(c[(i + 2) % 3]) - q(a[(i + 2) % 3])) -
                                   (q(b[(i + 2) % 3]) - q(a[(i + 2) % 3])) * (q(c[(i + 1) % 3]) - q(a[(i + 1) % 3]));
      ASSERT_EQ(sign_of_coordinate(n, i), sign_of(coordinate)) << "coordinate " << i;
    }
    zeros += want == Sign::kZero;
  }
  EXPECT_GT(zeros, 5000);
}

// Coordinates of directions built as meetings of circles through them, with exact zero
// coordinates the doubles round away (p = (0, 1, 3) and the like): each sign equals the
// dot with the axis.
TEST(ExactVec, SignOfACoordinateIsTheDotWithTheAxis) {
  std::mt19937_64 rng(20261129);
  std::uniform_int_distribution<int> small(-9, 9);
  auto vec = [&] { return ExactVec::from_point({0.1 * small(rng), 0.3 * small(rng), 0.7 * small(rng)}); };
  const ExactVec axes[3] = {ExactVec::from_point({1, 0, 0}), ExactVec::from_point({0, 1, 0}),
                            ExactVec::from_point({0, 0, 1})};
  int zeros = 0, rounded_zeros = 0;
  for (int iter = 0; iter < 3000; ++iter) {
    ExactVec p = vec();
    const ExactVec m = cross(cross(p, vec()), cross(p, vec()));  // parallel to p, or zero
    for (int i = 0; i < 3; ++i) {
      const Sign s = sign_of_coordinate(m, i);
      ASSERT_EQ(s, sign_dot(m, axes[i])) << "iteration " << iter << " coordinate " << i;
      zeros += s == Sign::kZero;
      rounded_zeros += s == Sign::kZero && m.approx()[i] != 0;
    }
  }
  EXPECT_GT(rounded_zeros, 100);  // the filter alone cannot tell these
  EXPECT_GT(zeros, rounded_zeros);
}

// The dot's sign from unit estimates where they decide it equals the exact one, for
// directions orthogonal by value but not by construction (the estimates cannot decide
// those) and for general ones (they decide most).
TEST(ExactVec, SignOfADotFromEstimatesIsTheExactOne) {
  std::mt19937_64 rng(20261129);
  std::uniform_int_distribution<int> small(-9, 9);
  auto vec = [&] { return ExactVec::from_point({0.1 * small(rng), 0.3 * small(rng), 0.7 * small(rng)}); };
  int zeros = 0;
  for (int iter = 0; iter < 3000; ++iter) {
    const ExactVec p = vec(), q = vec();
    const ExactVec m = cross(cross(p, vec()), cross(p, vec()));  // parallel to p, or zero
    for (const ExactVec& n : {cross(p, q), q}) {
      if (is_zero(m) || is_zero(n)) continue;
      const Sign s = sign_dot(m, n, unit_estimate(m), unit_estimate(n));
      ASSERT_EQ(s, sign_dot(m, n)) << "iteration " << iter;
      zeros += s == Sign::kZero;
    }
  }
  EXPECT_GT(zeros, 1000);
}

// A sum of signed volumes long enough to be summed in parallel, where the doubles cannot
// decide: every triangle's volume cancels against its reversed copy in the other half, and
// one tiny triangle decides the sign (or, without it, the sum is exactly zero).
TEST(ExactPredicates, SignedVolumeOfManyCancellingTrianglesIsExact) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> big(-1e6, 1e6);
  std::vector<Point3> points;
  std::vector<Triangle> triangles;
  const uint32_t pairs = 20000;
  for (uint32_t i = 0; i < 3 * pairs; ++i) points.push_back({big(rng), big(rng), big(rng)});
  for (uint32_t i = 0; i < pairs; ++i) triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  for (uint32_t i = 0; i < pairs; ++i) triangles.push_back({3 * i, 3 * i + 2, 3 * i + 1});
  std::vector<uint32_t> all(triangles.size());
  for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  EXPECT_EQ(signed_volume_sign(points, triangles, all), Sign::kZero);

  const uint32_t tiny = static_cast<uint32_t>(points.size());
  points.push_back({1e-9, 0, 0});
  points.push_back({0, 1e-9, 0});
  points.push_back({0, 0, 1e-9});
  triangles.insert(triangles.begin() + pairs, {tiny, tiny + 1, tiny + 2});
  all.push_back(static_cast<uint32_t>(all.size()));
  EXPECT_EQ(signed_volume_sign(points, triangles, all), Sign::kPositive);
  std::swap(triangles[pairs][1], triangles[pairs][2]);
  EXPECT_EQ(signed_volume_sign(points, triangles, all), Sign::kNegative);
}

}  // namespace
}  // namespace gvm::exact
