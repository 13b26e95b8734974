// Caps in closed sets and clearances: the exact angle predicates against GMP rationals,
// contains_cap against an independent long-double distance (sampling and refinement along
// every arc) away from ties and at exact ties, the approximate clearance against the
// same distances, and the quarter splits of arcs. The planner's tolerance (nearness.h):
// a set within theta of a direction and of another set, against the same distances and
// at exact ties.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/clearance.h"
#include "sphere/local_visibility_map.h"
#include "sphere/nearness.h"
#include "sphere/set_operations.h"
#include "sphere_random_images.h"

namespace gvm::sphere {
namespace {

using exact::ExactVec;
using testing::iv;
using D3 = std::array<double, 3>;
using L3 = std::array<long double, 3>;

constexpr long double kPiL = 3.141592653589793238462643383279502884L;

// --- the exact predicates against rationals ---

using Q3 = std::array<mpq_class, 3>;
Q3 q3(const D3& a) { return {mpq_class(a[0]), mpq_class(a[1]), mpq_class(a[2])}; }
Q3 cross_q(const Q3& a, const Q3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
mpq_class dot_q(const Q3& a, const Q3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Sign sign_of(const mpq_class& x) { return static_cast<Sign>(sgn(x)); }

ExactVec ev(const D3& a) { return ExactVec::from_point({a[0], a[1], a[2]}); }

// A double with a random binary exponent in [-e, e], either sign.
double random_double(std::mt19937_64& rng, int e) {
  std::uniform_real_distribution<double> m(-1, 1);
  return std::ldexp(m(rng), std::uniform_int_distribution<int>(-e, e)(rng));
}

TEST(SphereClearance, AnglePredicatesAgainstRationals) {
  constexpr uint64_t kSeed = 31337;
  SCOPED_TRACE("seed " + std::to_string(kSeed));
  std::mt19937_64 rng(kSeed);
  for (int i = 0; i < 4000; ++i) {
    // Vectors of doubles over a wide exponent range, sometimes cross products of such.
    const int e = i % 4 == 0 ? 300 : 20;
    D3 a0 = {random_double(rng, e), random_double(rng, e), random_double(rng, e)};
    D3 b0 = {random_double(rng, e), random_double(rng, e), random_double(rng, e)};
    D3 c0 = {random_double(rng, 5), random_double(rng, 5), random_double(rng, 5)};
    ExactVec a = ev(a0), b = ev(b0);
    Q3 qa = q3(a0), qb = q3(b0);
    if (i % 3 == 1) {
      a = exact::cross(a, ev(c0));  // degree-2 coordinates
      qa = cross_q(qa, q3(c0));
    }
    if (dot_q(qa, qa) == 0 || dot_q(qb, qb) == 0) continue;
    const mpq_class aa = dot_q(qa, qa), bb = dot_q(qb, qb);
    const Q3 w = cross_q(qa, qb);
    const mpq_class sin2_num = dot_q(w, w), cos2_num = dot_q(qa, qb) * dot_q(qa, qb);
    // s2 random, or the double nearest to the true value (a near tie for the filter).
    for (int which = 0; which < 3; ++which) {
      double s2 = std::uniform_real_distribution<double>(0, 1)(rng);
      if (which == 1) s2 = mpq_class(sin2_num / (aa * bb)).get_d();
      if (which == 2) s2 = mpq_class(cos2_num / (aa * bb)).get_d();
      const Sign sin_expected = sign_of(sin2_num - mpq_class(s2) * aa * bb);
      const Sign cos_expected = sign_of(cos2_num - mpq_class(s2) * aa * bb);
      ASSERT_EQ(exact::sign_sin2_angle_minus(a, b, s2), sin_expected) << i;
      ASSERT_EQ(exact::sign_cos2_angle_minus(a, b, s2), cos_expected) << i;
    }
  }
  // Exact ties: 45 degrees (sin^2 = cos^2 = 1/2) and right angles, at any scale.
  for (double scale : {1.0, 0x1p-600, 0x1p600, 3.0}) {
    const ExactVec x = ev({scale, 0, 0}), xy = ev({1, 1, 0}), pyth = ev({3 * scale, 4 * scale, 5 * scale});
    EXPECT_EQ(exact::sign_sin2_angle_minus(x, xy, 0.5), Sign::kZero);
    EXPECT_EQ(exact::sign_cos2_angle_minus(x, xy, 0.5), Sign::kZero);
    EXPECT_EQ(exact::sign_sin2_angle_minus(iv(0, 0, 1), pyth, 0.5), Sign::kZero);
    EXPECT_EQ(exact::sign_sin2_angle_minus(x, xy, std::nextafter(0.5, 1.0)), Sign::kNegative);
    EXPECT_EQ(exact::sign_cos2_angle_minus(x, xy, std::nextafter(0.5, 0.0)), Sign::kPositive);
    EXPECT_EQ(exact::sign_sin2_angle_minus(x, ev({0, 0, scale}), 1.0), Sign::kZero);
    EXPECT_EQ(exact::sign_cos2_angle_minus(x, ev({0, 0, scale}), 0.0), Sign::kZero);
  }
}

// --- quarter splits ---

TEST(SphereClearance, SplitArcQuarters) {
  constexpr uint64_t kSeed = 9090;
  SCOPED_TRACE("seed " + std::to_string(kSeed));
  std::mt19937_64 rng(kSeed);
  auto check = [](const Arc& arc, size_t expected_pieces) {
    const std::vector<ExactVec> v = split_arc_quarters(arc);
    ASSERT_GE(v.size(), 2u);
    if (expected_pieces) ASSERT_EQ(v.size() - 1, expected_pieces);
    if (arc.full) {
      EXPECT_TRUE(exact::same_direction(v.front(), v.back()));
      EXPECT_EQ(v.size(), 5u);
    } else {
      EXPECT_TRUE(exact::same_direction(v.front(), arc.start));
      EXPECT_TRUE(exact::same_direction(v.back(), arc.end));
    }
    for (size_t i = 0; i < v.size(); ++i) {
      EXPECT_EQ(exact::sign_dot(v[i], arc.normal), Sign::kZero);
      EXPECT_TRUE(arc_contains(arc, v[i]));
      if (i + 1 == v.size()) break;
      // Counter-clockwise, positive and at most 90 degrees; every piece but the last
      // exactly a quarter turn (so no fewer pieces would do).
      EXPECT_EQ(exact::sign_det(arc.normal, v[i], v[i + 1]), Sign::kPositive);
      EXPECT_NE(exact::sign_dot(v[i], v[i + 1]), Sign::kNegative);
      if (i + 2 < v.size()) EXPECT_EQ(exact::sign_dot(v[i], v[i + 1]), Sign::kZero);
    }
  };
  const ExactVec z = iv(0, 0, 1);
  check({iv(1, 0, 0), iv(1, 1, 0), z}, 1);     // 45
  check({iv(1, 0, 0), iv(0, 1, 0), z}, 1);     // 90
  check({iv(1, 0, 0), iv(-1, 1, 0), z}, 2);    // 135
  check({iv(1, 0, 0), iv(-1, 0, 0), z}, 2);    // 180
  check({iv(1, 0, 0), iv(-1, -1, 0), z}, 3);   // 225
  check({iv(1, 0, 0), iv(0, -1, 0), z}, 3);    // 270
  check({iv(1, 0, 0), iv(1, -1, 0), z}, 4);    // 315
  check({{}, {}, iv(1, 2, 3), true}, 4);       // full circle
  check({iv(2, 0, 0), iv(0, 5, 0), iv(0, 0, 3)}, 1);  // vectors of different lengths
  for (int i = 0; i < 500; ++i) {
    const Arc a = testing::random_arc(rng);
    check(a, 0);
    if (::testing::Test::HasFailure()) return;
  }
}

// --- distances in long double, by sampling and refinement along the arcs ---

L3 unit_l(const ExactVec& v) {
  const D3 d = v.unit();
  return {d[0], d[1], d[2]};
}
L3 unit_l(const D3& d) {
  const long double n = std::sqrt((long double)d[0] * d[0] + (long double)d[1] * d[1] + (long double)d[2] * d[2]);
  return {d[0] / n, d[1] / n, d[2] / n};
}
long double dot_l(const L3& a, const L3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
L3 cross_l(const L3& a, const L3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
long double angle_l(const L3& a, const L3& b) {
  const L3 c = cross_l(a, b);
  return std::atan2(std::sqrt(dot_l(c, c)), dot_l(a, b));
}

// Minimal angle from u to the minor arc a -> b: u . p(t) along p(t) = a cos t + w sin t
// is a sinusoid, so the best of 256 samples brackets the maximum, refined by ternary
// search; the ends count too.
long double distance_to_piece(const L3& u, const L3& a, const L3& b) {
  const L3 n = cross_l(a, b);
  const long double nn = std::sqrt(dot_l(n, n));
  L3 w = cross_l({n[0] / nn, n[1] / nn, n[2] / nn}, a);
  const long double length = angle_l(a, b);
  auto at = [&](long double t) {
    return L3{a[0] * std::cos(t) + w[0] * std::sin(t), a[1] * std::cos(t) + w[1] * std::sin(t),
              a[2] * std::cos(t) + w[2] * std::sin(t)};
  };
  constexpr int kSamples = 256;
  int best = 0;
  for (int k = 1; k <= kSamples; ++k) {
    if (dot_l(u, at(length * k / kSamples)) > dot_l(u, at(length * best / kSamples))) best = k;
  }
  long double lo = length * std::max(0, best - 1) / kSamples, hi = length * std::min(kSamples, best + 1) / kSamples;
  for (int it = 0; it < 200; ++it) {
    const long double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (dot_l(u, at(m1)) < dot_l(u, at(m2))) lo = m1; else hi = m2;
  }
  return std::min({angle_l(u, at((lo + hi) / 2)), angle_l(u, a), angle_l(u, b)});
}

long double distance_to_arc(const L3& u, const Arc& arc) {
  const std::vector<ExactVec> v = split_arc(arc);
  long double d = kPiL;
  for (size_t i = 0; i + 1 < v.size(); ++i) d = std::min(d, distance_to_piece(u, unit_l(v[i]), unit_l(v[i + 1])));
  return d;
}

long double distance_to_face_boundary(const L3& u, const Face& f) {
  long double d = kPiL;
  for (const Loop& l : f.loops) {
    for (const Arc& a : l.arcs) d = std::min(d, distance_to_arc(u, a));
  }
  return d;
}

// Canonical sets with 2-cells: one LVM, or set operations on two (non-convex faces,
// holes, faces touching at points).
SphericalImage random_face_set(std::mt19937_64& rng) {
  const SphericalImage a = testing::random_lvm(rng), b = testing::random_lvm(rng);
  switch (testing::uniform(rng, 0, 3)) {
    case 0:
      return set_difference(a, b);
    case 1:
      return set_union(a, b);
    case 2:
      return set_union(set_difference(a, b), set_difference(b, a));
    default:
      return a;
  }
}

TEST(SphereClearance, CapsAgainstLongDoubleDistancesAwayFromTies) {
  constexpr uint64_t kBaseSeed = 5150;
  int inside = 0, outside = 0;
  for (uint64_t s = 0; s < 150; ++s) {
    const uint64_t seed = kBaseSeed + s;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    const SphericalImage set = random_face_set(rng);
    SCOPED_TRACE(set.description());
    for (int i = 0; i < 40; ++i) {
      const ExactVec c = testing::random_direction(rng, 6);
      const long double theta = std::uniform_real_distribution<double>(0, 1.5707963)(rng);
      const double s2 = std::pow(std::sin(double(theta)), 2);
      const long double theta_exact = std::asin(std::sqrt((long double)s2));
      bool expected = false, near_tie = false;
      for (const Face& f : set.faces()) {
        if (!face_contains(f, c)) continue;
        const long double d = distance_to_face_boundary(unit_l(c), f);
        near_tie |= std::fabs(d - theta_exact) < 1e-9L;
        expected |= d >= theta_exact;
      }
      if (near_tie) continue;
      ASSERT_EQ(contains_cap(set, c, s2), expected) << "theta " << double(theta);
      (expected ? inside : outside) += 1;
      // The approximate clearance agrees away from ties.
      const double clearance = approx_signed_clearance(set, c.unit());
      if (std::fabs(clearance - double(theta_exact)) > 1e-9) ASSERT_EQ(clearance > double(theta_exact), expected);
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

// Faces in the square {|x| <= z, |y| <= z}, whose sides are 45 degrees from +z.
SphericalImage unit_square() {
  const std::vector<ExactVec> n = {iv(1, 0, 1), iv(-1, 0, 1), iv(0, 1, 1), iv(0, -1, 1)};
  return local_visibility_map(n);
}

TEST(SphereClearance, CapsExactlyTouchingTheBoundary) {
  const double half = 0.5, above = std::nextafter(0.5, 1.0), below = std::nextafter(0.5, 0.0);
  // Touching four sides at their middles (the closest points of their circles).
  const SphericalImage square = unit_square();
  for (const ExactVec& c : {iv(0, 0, 1), iv(0, 0, 7)}) {
    EXPECT_TRUE(contains_cap(square, c, half));
    EXPECT_TRUE(contains_cap(square, c, below));
    EXPECT_FALSE(contains_cap(square, c, above));
  }
  // Touching a reflex corner (3, 4, 5), 45 degrees from +z, whose sides' closest points
  // to +z are off the sides: the distance is to the corner.
  const SphericalImage big = local_visibility_map(std::vector<ExactVec>{iv(1, 0, 4), iv(-1, 0, 4), iv(0, 1, 4), iv(0, -1, 4)});
  const SphericalImage notch = local_visibility_map(std::vector<ExactVec>{iv(5, 0, -3), iv(0, 5, -4)});
  const SphericalImage l_shape = set_difference(big, notch);
  ASSERT_EQ(l_shape.faces().size(), 1u);
  EXPECT_FALSE(l_shape.faces()[0].convex);
  EXPECT_TRUE(contains_cap(l_shape, iv(0, 0, 1), half));
  EXPECT_FALSE(contains_cap(l_shape, iv(0, 0, 1), above));
  // Hemispheres: the 90-degree cap is the hemisphere itself; a side at 45 degrees.
  EXPECT_TRUE(contains_cap(SphericalImage::hemisphere(iv(0, 0, 1)), iv(0, 0, 5), 1.0));
  EXPECT_FALSE(contains_cap(SphericalImage::hemisphere(iv(0, 0, 1)), iv(0, 1, 5), 1.0));
  EXPECT_TRUE(contains_cap(SphericalImage::hemisphere(iv(0, -1, 1)), iv(0, 0, 1), half));
  EXPECT_FALSE(contains_cap(SphericalImage::hemisphere(iv(0, -1, 1)), iv(0, 0, 1), above));
  // s2 = 0 is membership: points and arcs hold the degenerate cap, nothing more.
  SphericalImage lower_dims;
  lower_dims.add_point(iv(1, 2, 3));
  lower_dims.add_curve({iv(1, 0, 0), iv(0, 1, 0), iv(0, 0, 1)});
  EXPECT_TRUE(contains_cap(lower_dims, iv(2, 4, 6), 0.0));
  EXPECT_TRUE(contains_cap(lower_dims, iv(1, 1, 0), 0.0));
  EXPECT_FALSE(contains_cap(lower_dims, iv(1, 1, 0), 0x1p-1000));
  EXPECT_FALSE(contains_cap(lower_dims, iv(1, 1, 1), 0.0));
  EXPECT_TRUE(contains_cap(SphericalImage::full_sphere(), iv(1, 1, 1), 1.0));
  EXPECT_FALSE(contains_cap(SphericalImage::empty(), iv(1, 1, 1), 0.0));
}

TEST(SphereClearance, CapsAcrossFacesThatOverlapOrShareEdges) {
  // Two hemispheres as separate faces: the whole sphere together.
  const SphericalImage halves = testing::combine({SphericalImage::hemisphere(iv(0, 0, 1)), SphericalImage::hemisphere(iv(0, 0, -1))});
  EXPECT_TRUE(contains_cap(halves, iv(1, 0, 0), 1.0));
  // The square as two halves sharing an edge, and as two overlapping rectangles: the
  // same answers as the one convex face, for caps straddling the seam.
  auto rect = [](int x0, int x1) {
    return local_visibility_map(std::vector<ExactVec>{iv(1, 0, -x0), iv(-1, 0, x1), iv(0, 1, 2), iv(0, -1, 2)});
  };
  const SphericalImage whole = rect(-2, 2);
  const SphericalImage split = testing::combine({rect(-2, 0), rect(0, 2)});
  const SphericalImage overlapping = testing::combine({rect(-2, 1), rect(-1, 2)});
  constexpr uint64_t kSeed = 808;
  SCOPED_TRACE("seed " + std::to_string(kSeed));
  std::mt19937_64 rng(kSeed);
  int held = 0;
  for (int i = 0; i < 300; ++i) {
    const ExactVec c = iv(testing::uniform(rng, -3, 3), testing::uniform(rng, -3, 3), 2);
    const double s2 = std::uniform_real_distribution<double>(0, 0.6)(rng);
    const bool expected = contains_cap(whole, c, s2);
    held += expected;
    ASSERT_EQ(contains_cap(split, c, s2), expected) << i;
    ASSERT_EQ(contains_cap(overlapping, c, s2), expected) << i;
  }
  EXPECT_GT(held, 20);
}

TEST(SphereClearance, ApproximateSignedClearance) {
  EXPECT_DOUBLE_EQ(approx_signed_clearance(SphericalImage::full_sphere(), {0, 0, 1}), M_PI);
  EXPECT_DOUBLE_EQ(approx_signed_clearance(SphericalImage::empty(), {0, 0, 1}), -M_PI);
  EXPECT_NEAR(approx_signed_clearance(unit_square(), {0, 0, 1}), M_PI / 4, 1e-15);
  EXPECT_NEAR(approx_signed_clearance(SphericalImage::hemisphere(iv(0, 0, 1)), {1, 0, 0}), 0, 0);
  constexpr uint64_t kBaseSeed = 2718;
  for (uint64_t s = 0; s < 100; ++s) {
    const uint64_t seed = kBaseSeed + s;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    const SphericalImage set = s % 3 == 0 ? testing::random_image(rng) : random_face_set(rng);
    SCOPED_TRACE(set.description());
    if (set.is_full_sphere() || set.is_empty()) continue;
    std::normal_distribution<double> g;
    for (int i = 0; i < 30; ++i) {
      const D3 u = {g(rng), g(rng), g(rng)};
      const L3 ul = unit_l(u);
      const double value = approx_signed_clearance(set, u);
      const ExactVec exact_u = ev(u);
      long double expected = -kPiL;
      bool in_face = false;
      for (const Face& f : set.faces()) {
        if (!face_contains(f, exact_u)) continue;
        in_face = true;
        expected = std::max(expected, distance_to_face_boundary(ul, f));
      }
      if (!in_face && set.contains(exact_u)) expected = 0;
      if (!in_face && !set.contains(exact_u)) {
        long double d = kPiL;
        for (const Face& f : set.faces()) d = std::min(d, distance_to_face_boundary(ul, f));
        for (const Arc& a : set.curves()) d = std::min(d, distance_to_arc(ul, a));
        for (const ExactVec& p : set.points()) d = std::min(d, angle_l(ul, unit_l(p)));
        expected = -d;
      }
      ASSERT_NEAR(value, double(expected), 1e-9) << u[0] << " " << u[1] << " " << u[2];
    }
  }
}

// --- nearness: the planner's tolerance ---

// The long-double distance from u to the set (0 inside).
long double distance_to_set(const SphericalImage& set, const D3& u) {
  if (set.contains(ev(u))) return 0;
  const L3 ul = unit_l(u);
  long double d = kPiL;
  for (const Face& f : set.faces()) d = std::min(d, distance_to_face_boundary(ul, f));
  for (const Arc& a : set.curves()) d = std::min(d, distance_to_arc(ul, a));
  for (const ExactVec& p : set.points()) d = std::min(d, angle_l(ul, unit_l(p)));
  return d;
}

TEST(SphereNearness, WithinAngleAgainstLongDoubleDistances) {
  constexpr uint64_t kBaseSeed = 6021;
  int near = 0, far = 0;
  for (uint64_t s = 0; s < 200; ++s) {
    std::mt19937_64 rng(kBaseSeed + s);
    const SphericalImage set = s % 3 == 0 ? testing::random_image(rng) : random_face_set(rng);
    if (set.is_full_sphere() || set.is_empty()) continue;
    std::normal_distribution<double> g;
    for (int i = 0; i < 20; ++i) {
      const D3 u = {g(rng), g(rng), g(rng)};
      const long double d = distance_to_set(set, u);
      // A tolerance near the distance, so that both answers come up.
      const double theta = std::clamp(double(d) * std::uniform_real_distribution<double>(0.5, 1.5)(rng), 1e-6, 1.5);
      const double s2 = std::sin(theta) * std::sin(theta);
      const long double theta_exact = std::asin(std::sqrt((long double)s2));
      if (std::fabs(d - theta_exact) < 1e-9) continue;
      const bool expected = d <= theta_exact;
      (expected ? near : far) += 1;
      ASSERT_EQ(within_angle(set, ev(u), s2), expected) << set.description() << " d " << double(d) << " theta " << theta;
    }
  }
  EXPECT_GT(near, 500);
  EXPECT_GT(far, 500);
}

TEST(SphereNearness, WithinAngleAtExactTies) {
  // sin^2 45 degrees = 1/2 exactly: a point, a circle and an arc's end 45 degrees away.
  const ExactVec x = iv(1, 0, 0);
  const double half = 0.5, below = std::nextafter(0.5, 0.0);
  EXPECT_TRUE(within_angle(SphericalImage::point(iv(1, 1, 0)), x, half));
  EXPECT_FALSE(within_angle(SphericalImage::point(iv(1, 1, 0)), x, below));
  EXPECT_TRUE(within_angle(SphericalImage::great_circle(iv(1, 0, 1)), x, half));
  EXPECT_FALSE(within_angle(SphericalImage::great_circle(iv(1, 0, 1)), x, below));
  EXPECT_TRUE(within_angle(SphericalImage::hemisphere(iv(-1, 0, 1)), x, half));
  EXPECT_FALSE(within_angle(SphericalImage::hemisphere(iv(-1, 0, 1)), x, below));
  SphericalImage arc;  // from (1, 1, 0) on around +z: x is nearest its start
  arc.add_curve({iv(1, 1, 0), iv(-1, 1, 0), iv(0, 0, 1), false});
  EXPECT_TRUE(within_angle(arc, x, half));
  EXPECT_FALSE(within_angle(arc, x, below));
  EXPECT_FALSE(within_angle(SphericalImage::point(iv(-1, 0, 0)), x, 0.999));  // beyond 90 degrees
  EXPECT_TRUE(within_angle(SphericalImage::point(iv(1, 0, 0)), x, 0));        // zero is an answer
}

TEST(SphereNearness, SetsWithinAngleAgainstSampledDistances) {
  constexpr uint64_t kBaseSeed = 7057;
  int near = 0, far = 0;
  for (uint64_t s = 0; s < 300; ++s) {
    std::mt19937_64 rng(kBaseSeed + s);
    const SphericalImage a = s % 2 ? testing::random_image(rng) : random_face_set(rng);
    const SphericalImage b = s % 3 ? testing::random_image(rng) : random_face_set(rng);
    if (a.is_empty() || b.is_empty() || a.is_full_sphere() || b.is_full_sphere()) continue;
    // The distance sampled from a's side: its corners, points along its arcs and
    // boundaries, each to b -- an upper bound of the distance between the sets, and equal
    // to it when the sets are nearest at a corner of a.
    long double sampled = kPiL;
    auto sample_arc = [&](const Arc& arc) {
      for (const ExactVec& v : split_arc(arc)) sampled = std::min(sampled, distance_to_set(b, v.unit()));
    };
    for (const Face& f : a.faces())
      for (const Loop& l : f.loops)
        for (const Arc& arc : l.arcs) sample_arc(arc);
    for (const Arc& arc : a.curves()) sample_arc(arc);
    for (const ExactVec& p : a.points()) sampled = std::min(sampled, distance_to_set(b, p.unit()));
    for (const double theta : {0.02, 0.2, 0.6}) {
      const double s2 = std::sin(theta) * std::sin(theta);
      const bool within = sets_within_angle(a, b, s2);
      // Near at a sampled point means within; not within means every sample is farther.
      if (sampled < theta - 1e-9) EXPECT_TRUE(within) << a.description() << " / " << b.description();
      if (!within) EXPECT_GT(sampled, theta - 1e-9);
      if (!within) {
        // From b's side as well, and no common direction.
        for (const ExactVec& v : corners(b)) EXPECT_GT(distance_to_set(a, v.unit()), theta - 1e-9);
        EXPECT_TRUE(set_intersection(a, b).is_empty());
      }
      (within ? near : far) += 1;
    }
  }
  EXPECT_GT(near, 200);
  EXPECT_GT(far, 60);
}

// Every direction within theta of the set lies in its dilation cover: random directions,
// and directions just under theta beyond every corner and off every arc's middle.
TEST(SphereNearness, DilationCoverHoldsTheNeighbourhood) {
  constexpr uint64_t kBaseSeed = 8093;
  int tested = 0;
  for (uint64_t s = 0; s < 120; ++s) {
    std::mt19937_64 rng(kBaseSeed + s);
    const SphericalImage set = s % 3 == 0 ? testing::random_image(rng) : random_face_set(rng);
    if (set.is_full_sphere() || set.is_empty()) continue;
    const double theta = s % 2 ? 1e-6 : 0.02;
    const double s2 = std::sin(theta) * std::sin(theta);
    const std::optional<SphericalImage> cover = dilation_cover(set, theta, s2 * (1 + 1e-12));
    ASSERT_TRUE(cover.has_value()) << set.description();
    std::vector<D3> probes;
    std::normal_distribution<double> g;
    for (int i = 0; i < 20; ++i) probes.push_back({g(rng), g(rng), g(rng)});
    for (const ExactVec& c : corners(set)) {
      const D3 u = c.unit();
      for (int i = 0; i < 4; ++i) {
        D3 w = {g(rng), g(rng), g(rng)};
        const double along = w[0] * u[0] + w[1] * u[1] + w[2] * u[2];
        for (int k = 0; k < 3; ++k) w[k] -= along * u[k];
        const double n = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        const double t = 0.999 * theta;
        probes.push_back({u[0] * std::cos(t) + w[0] / n * std::sin(t), u[1] * std::cos(t) + w[1] / n * std::sin(t),
                          u[2] * std::cos(t) + w[2] / n * std::sin(t)});
      }
    }
    for (const D3& u : probes) {
      if (!within_angle(set, ev(u), s2 * (1 - 1e-12))) continue;
      ++tested;
      EXPECT_TRUE(cover->contains(ev(u))) << set.description() << " theta " << theta;
    }
  }
  EXPECT_GT(tested, 500);
}

}  // namespace
}  // namespace gvm::sphere
