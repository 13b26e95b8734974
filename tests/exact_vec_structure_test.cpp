// Structural zeros of ExactVec predicates, and that they never fire on non-zero values.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "exact/exact_vec.h"

namespace gvm::exact {
namespace {

ExactVec v(const Point3& p) { return ExactVec::from_point(p); }

// Ground truth on integer coordinates: exact in __int128 for the degrees used below.
using I3 = std::array<__int128, 3>;

I3 to_i(const Point3& p) { return {__int128(p.x), __int128(p.y), __int128(p.z)}; }
I3 cross_i(const I3& a, const I3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
__int128 dot_i(const I3& a, const I3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
I3 neg_i(const I3& a) { return {-a[0], -a[1], -a[2]}; }
I3 sub_i(const I3& a, const I3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
bool zero_i(const I3& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }
Sign sign_i(__int128 x) {
  return x > 0 ? Sign::kPositive : (x < 0 ? Sign::kNegative : Sign::kZero);
}

std::string str(const Point3& p) {
  std::string s = "(";  // appended piecewise: GCC 12 warns falsely on "(" + std::string
  s += std::to_string(p.x);
  s += ", ";
  s += std::to_string(p.y);
  s += ", ";
  s += std::to_string(p.z);
  s += ")";
  return s;
}

// Doubles of very different magnitudes (where the filter may give up), nearly parallel
// pairs among them.
Point3 random_double_point(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> e(-60, 60), kind(0, 3);
  switch (kind(rng)) {
    case 0:
      return {u(rng), u(rng), u(rng)};
    case 1:
      return {std::ldexp(u(rng), e(rng)), std::ldexp(u(rng), e(rng)), std::ldexp(u(rng), e(rng))};
    case 2:
      return {std::ldexp(u(rng), 500), std::ldexp(u(rng), -500), u(rng)};
    default:
      return {1e300 * u(rng), 1e-300 * u(rng), 1e150 * u(rng)};
  }
}

Point3 nudge(const Point3& p) {  // one ulp off in one coordinate: nearly parallel
  return {std::nextafter(p.x, 2 * p.x + 1), p.y, p.z};
}

TEST(ExactVecStructure, ZerosKnownFromConstruction) {
  std::mt19937_64 rng(1);
  for (int t = 0; t < 300; ++t) {
    const Point3 pa = random_double_point(rng), pb = random_double_point(rng),
                 pc = random_double_point(rng);
    const ExactVec a = v(pa), b = v(t % 5 == 0 ? nudge(pa) : pb), c = v(pc);
    const ExactVec ab = cross(a, b), na = -a, nna = -na;
    SCOPED_TRACE(str(pa) + " " + str(pb) + " " + str(pc));
    // A factor of a cross product is orthogonal to it.
    EXPECT_EQ(sign_dot(a, ab), Sign::kZero);
    EXPECT_EQ(sign_dot(ab, a), Sign::kZero);
    EXPECT_EQ(sign_dot(b, ab), Sign::kZero);
    EXPECT_EQ(sign_dot(ab, b), Sign::kZero);
    EXPECT_EQ(sign_dot(na, ab), Sign::kZero);
    EXPECT_EQ(sign_dot(a, -ab), Sign::kZero);
    EXPECT_EQ(sign_dot(-nna, cross(b, nna)), Sign::kZero);
    EXPECT_EQ(sign_dot(a, cross(na, c)), Sign::kZero);
    EXPECT_EQ(sign_dot(ab, cross(c, ab)), Sign::kZero);
    EXPECT_EQ(sign_dot(-ab, -cross(-ab, c)), Sign::kZero);
    // Two equal arguments up to negation: a zero determinant.
    EXPECT_EQ(sign_det(a, a, c), Sign::kZero);
    EXPECT_EQ(sign_det(a, c, a), Sign::kZero);
    EXPECT_EQ(sign_det(c, a, a), Sign::kZero);
    EXPECT_EQ(sign_det(a, na, c), Sign::kZero);
    EXPECT_EQ(sign_det(nna, c, na), Sign::kZero);
    EXPECT_EQ(sign_det(c, -ab, ab), Sign::kZero);
    EXPECT_EQ(sign_det(ab, b, ab), Sign::kZero);
    // The cross product of a vector with itself (up to negation) is zero.
    EXPECT_TRUE(is_zero(cross(a, a)));
    EXPECT_TRUE(is_zero(cross(a, na)));
    EXPECT_TRUE(is_zero(-cross(na, a)));
    EXPECT_TRUE(is_zero(cross(nna, -nna)));
    EXPECT_TRUE(is_zero(cross(ab, -ab)));
    EXPECT_TRUE(parallel(a, a));
    EXPECT_TRUE(parallel(a, na));
    EXPECT_TRUE(parallel(-ab, ab));
    EXPECT_TRUE(same_direction(a, a));
    EXPECT_TRUE(same_direction(nna, a));
    EXPECT_FALSE(same_direction(a, na));
    EXPECT_FALSE(same_direction(ab, -ab));
    // The same facts through the arithmetic: separately built copies of a.
    const ExactVec a2 = v(pa), a3 = v(pa);
    EXPECT_EQ(sign_dot(a2, ab), Sign::kZero);
    EXPECT_EQ(sign_det(a, a2, c), Sign::kZero);
    EXPECT_EQ(sign_det(a2, -a3, c), Sign::kZero);
    EXPECT_TRUE(is_zero(cross(a, a2)));
    EXPECT_TRUE(is_zero(cross(-a2, a3)));
    EXPECT_TRUE(parallel(a2, na));
    EXPECT_TRUE(same_direction(a2, nna));
    EXPECT_TRUE(is_zero(a - a2));
  }
}

// Expressions that share nodes with a cross product or with each other, but whose value
// is not zero: the structural shortcut must not answer them. Their signs are compared
// with the same expressions over separately built copies (which take the arithmetic
// path), and with signs known by hand where there is one.
TEST(ExactVecStructure, LookalikesMatchSeparatelyBuiltCopies) {
  std::mt19937_64 rng(2);
  int nonzero = 0;
  for (int t = 0; t < 400; ++t) {
    const Point3 pa = random_double_point(rng);
    const Point3 pb = t % 4 == 0 ? nudge(pa) : random_double_point(rng);
    const Point3 pc = t % 7 == 0 ? nudge(pb) : random_double_point(rng);
    SCOPED_TRACE(str(pa) + " " + str(pb) + " " + str(pc));
    // Shared nodes.
    const ExactVec a = v(pa), b = v(pb), c = v(pc);
    const ExactVec ab = cross(a, b), na = -a;
    // Every use of a vector is a fresh node.
    auto A = [&] { return v(pa); };
    auto B = [&] { return v(pb); };
    auto C = [&] { return v(pc); };
    const bool a_par_b = is_zero(cross(A(), B()));
    // a . ((a x b) x c) = (a . b)(a . c) - |a|^2 (b . c): not zero in general.
    const Sign s1 = sign_dot(a, cross(ab, c));
    EXPECT_EQ(s1, sign_dot(A(), cross(cross(A(), B()), C())));
    nonzero += s1 != Sign::kZero;
    // (a x b) . (a x c): shares a factor, not orthogonal.
    EXPECT_EQ(sign_dot(ab, cross(a, c)), sign_dot(cross(A(), B()), cross(A(), C())));
    EXPECT_EQ(sign_dot(ab, cross(na, c)), -sign_dot(cross(A(), B()), cross(A(), C())));
    // Hand signs: a . a > 0, a . (-a) < 0, (a x b) . (a x b) = |a x b|^2 >= 0, and
    // (a x b) . (b x a) <= 0, zero exactly when a and b are parallel.
    EXPECT_EQ(sign_dot(a, a), Sign::kPositive);
    EXPECT_EQ(sign_dot(a, na), Sign::kNegative);
    EXPECT_EQ(sign_dot(-na, a), Sign::kPositive);
    EXPECT_EQ(sign_dot(ab, ab), a_par_b ? Sign::kZero : Sign::kPositive);
    EXPECT_EQ(sign_dot(ab, cross(b, a)), a_par_b ? Sign::kZero : Sign::kNegative);
    EXPECT_EQ(sign_dot(-ab, -ab), a_par_b ? Sign::kZero : Sign::kPositive);
    // det(a, b, a x b) = |a x b|^2; det(a, a x b, b) = (a . b)^2 - |a|^2 |b|^2 <= 0.
    EXPECT_EQ(sign_det(a, b, ab), a_par_b ? Sign::kZero : Sign::kPositive);
    EXPECT_EQ(sign_det(ab, a, b), a_par_b ? Sign::kZero : Sign::kPositive);
    EXPECT_EQ(sign_det(a, ab, b), a_par_b ? Sign::kZero : Sign::kNegative);
    EXPECT_EQ(sign_det(na, b, ab), a_par_b ? Sign::kZero : Sign::kNegative);
    // Mixed: shared nodes in non-repeated positions.
    EXPECT_EQ(sign_det(a, b, c), sign_det(A(), B(), C()));
    EXPECT_EQ(sign_det(a, -b, c), -sign_det(A(), B(), C()));
    EXPECT_EQ(sign_det(a, b, a + c), sign_det(A(), B(), A() + C()));
    EXPECT_EQ(sign_det(cross(a, c), ab, b), sign_det(cross(A(), C()), cross(A(), B()), B()));
    EXPECT_EQ(sign_dot(a, cross(b, c)), sign_det(A(), B(), C()));
    // Not zero: a x (a x b) = a (a . b) - b |a|^2, and a is not parallel to a x b.
    EXPECT_EQ(is_zero(cross(a, ab)), a_par_b);
    EXPECT_EQ(parallel(a, ab), a_par_b);
    EXPECT_EQ(is_zero(cross(a, b)), is_zero(cross(A(), B())));
    EXPECT_EQ(parallel(a, b), parallel(A(), B()));
    EXPECT_EQ(parallel(a, b + a), parallel(A(), B() + A()));
    EXPECT_EQ(same_direction(a, b), same_direction(A(), B()));
    EXPECT_FALSE(is_zero(a));
    EXPECT_FALSE(is_zero(-na));
    EXPECT_EQ(is_zero(a - b), is_zero(A() - B()));
  }
  EXPECT_GT(nonzero, 200);
}

// Small integer vectors, exactly in __int128: every predicate over nodes that are shared,
// negated, separately built copies, multiples, near multiples and zero vectors.
TEST(ExactVecStructure, IntegerGroundTruth) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> tiny(-2, 2), pick(0, 7);
  std::uniform_int_distribution<int64_t> big(-(int64_t(1) << 20), int64_t(1) << 20);
  int zeros = 0, parallels = 0, cases = 0;
  for (int t = 0; t < 4000; ++t) {
    // Points and the nodes that stand for them.
    std::vector<Point3> pts;
    std::vector<ExactVec> nodes;
    for (int i = 0; i < 3; ++i) {
      Point3 p;
      ExactVec n;
      const int k = i == 0 ? pick(rng) % 2 : pick(rng);
      if (k == 0 || i == 0) {  // fresh small or large coordinates
        if (k == 0) {
          p = {double(tiny(rng)), double(tiny(rng)), double(tiny(rng))};
        } else {
          p = {double(big(rng)), double(big(rng)), double(big(rng))};
        }
        n = v(p);
      } else {
        const int j = int(rng() % uint64_t(i));  // refers to an earlier vector
        switch (k) {
          case 1:  // the same node
            p = pts[j], n = nodes[j];
            break;
          case 2:  // its negation
            p = {-pts[j].x, -pts[j].y, -pts[j].z}, n = -nodes[j];
            break;
          case 3:  // a separately built copy
            p = pts[j], n = v(p);
            break;
          case 4: {  // a multiple
            const double m = double(tiny(rng) * 3 + 1);
            p = {m * pts[j].x, m * pts[j].y, m * pts[j].z}, n = v(p);
            break;
          }
          case 5:  // a near multiple
            p = {3 * pts[j].x, 3 * pts[j].y, 3 * pts[j].z + 1}, n = v(p);
            break;
          case 6:  // double negation of the node
            p = pts[j], n = -(-nodes[j]);
            break;
          default:
            p = {double(big(rng)), double(big(rng)), double(big(rng))}, n = v(p);
        }
      }
      pts.push_back(p);
      nodes.push_back(n);
    }
    const I3 a = to_i(pts[0]), b = to_i(pts[1]), c = to_i(pts[2]);
    const ExactVec &A = nodes[0], &B = nodes[1], &C = nodes[2];
    SCOPED_TRACE(str(pts[0]) + " " + str(pts[1]) + " " + str(pts[2]));
    ++cases;
    const __int128 det = dot_i(a, cross_i(b, c));
    zeros += det == 0;
    parallels += zero_i(cross_i(a, b));
    ASSERT_EQ(sign_det(A, B, C), sign_i(det));
    ASSERT_EQ(sign_det(B, C, A), sign_i(det));
    ASSERT_EQ(sign_det(A, C, B), sign_i(-det));
    ASSERT_EQ(sign_det(-A, B, C), sign_i(-det));
    ASSERT_EQ(sign_dot(A, cross(B, C)), sign_i(det));
    ASSERT_EQ(sign_dot(cross(C, A), B), sign_i(det));
    ASSERT_EQ(sign_dot(A, B), sign_i(dot_i(a, b)));
    ASSERT_EQ(sign_dot(-A, C), sign_i(-dot_i(a, c)));
    ASSERT_EQ(sign_dot(B, C), sign_i(dot_i(b, c)));
    ASSERT_EQ(is_zero(cross(A, B)), zero_i(cross_i(a, b)));
    ASSERT_EQ(is_zero(cross(-B, C)), zero_i(cross_i(b, c)));
    ASSERT_EQ(parallel(A, C), zero_i(cross_i(a, c)));
    ASSERT_EQ(parallel(B, -C), zero_i(cross_i(b, c)));
    ASSERT_EQ(is_zero(A - B), zero_i(sub_i(a, b)));
    ASSERT_EQ(is_zero(B), zero_i(b));
    ASSERT_EQ(same_direction(A, B), zero_i(cross_i(a, b)) && dot_i(a, b) > 0);
    // Degree four: a . ((a x b) x c) and (a x b) . (a x c), b . (a x b), det(a, b, a x b).
    const I3 ab = cross_i(a, b);
    ASSERT_EQ(sign_dot(A, cross(cross(A, B), C)), sign_i(dot_i(a, cross_i(ab, c))));
    ASSERT_EQ(sign_dot(cross(A, B), cross(A, C)), sign_i(dot_i(ab, cross_i(a, c))));
    ASSERT_EQ(sign_dot(B, cross(A, B)), sign_i(dot_i(b, ab)));
    ASSERT_EQ(sign_det(A, B, cross(A, B)), sign_i(dot_i(a, cross_i(b, ab))));
    ASSERT_EQ(sign_det(cross(A, B), C, -cross(A, B)), sign_i(dot_i(ab, cross_i(c, neg_i(ab)))));
    ASSERT_EQ(is_zero(cross(cross(A, B), cross(B, A))), zero_i(cross_i(ab, cross_i(b, a))));
    ASSERT_EQ(parallel(A, cross(A, B)), zero_i(cross_i(a, ab)));
  }
  // The generator really produces the degenerate cases.
  EXPECT_GT(zeros, 1000);
  EXPECT_GT(parallels, 500);
  EXPECT_EQ(cases, 4000);
}

// Nearly parallel large integers: the double filter cannot decide, the exact path must.
TEST(ExactVecStructure, NearlyParallelLargeIntegers) {
  std::mt19937_64 rng(4);
  std::uniform_int_distribution<int64_t> big(-(int64_t(1) << 38), int64_t(1) << 38);
  std::uniform_int_distribution<int> e(-1, 1);
  for (int t = 0; t < 2000; ++t) {
    const Point3 pa{double(big(rng)), double(big(rng)), double(big(rng))};
    const Point3 pb{3 * pa.x + e(rng), 3 * pa.y + e(rng), 3 * pa.z + e(rng)};
    const Point3 pc{5 * pa.x + e(rng), 5 * pa.y + e(rng), 5 * pa.z + e(rng)};
    SCOPED_TRACE(str(pa) + " " + str(pb) + " " + str(pc));
    const I3 a = to_i(pa), b = to_i(pb), c = to_i(pc);
    const ExactVec A = v(pa), B = v(pb), C = v(pc);
    ASSERT_EQ(sign_det(A, B, C), sign_i(dot_i(a, cross_i(b, c))));
    ASSERT_EQ(sign_det(A, -B, C), sign_i(-dot_i(a, cross_i(b, c))));
    ASSERT_EQ(parallel(A, B), zero_i(cross_i(a, b)));
    ASSERT_EQ(is_zero(cross(B, C)), zero_i(cross_i(b, c)));
    ASSERT_EQ(sign_det(A, B, A), Sign::kZero);
    ASSERT_EQ(sign_dot(A, cross(B, -A)), Sign::kZero);
  }
}

// Boxes around vertices come from unit estimates: the crossing of two nearly tangent great
// circles (CAD parts make them by the hundred thousand: a planar face seen from occluders
// near its plane) must still be located within 2^-30, or every arrangement around it
// compares all its near vertices exactly (r103ec's face 6: 114 M tests, 2,432 equal).
TEST(UnitEstimate, CrossingsOfNearlyTangentCirclesAreLocatedTightly) {
  const ExactVec a = v({3, -4, 12});
  for (int k : {20, 30, 40, 50}) {
    const ExactVec n1 = cross(a, v({1, 0, 0}));
    const ExactVec n2 = cross(a, v({1, 0, std::ldexp(1.0, -k)}));  // circles at about 2^-k radians
    const ExactVec x = cross(n1, n2);                               // +-a, exactly
    ASSERT_TRUE(parallel(x, a)) << k;
    const double s = sign_dot(x, a) == Sign::kPositive ? 1.0 : -1.0;
    const std::array<double, 3> expect = {s * 3 / 13, s * -4 / 13, s * 12 / 13};
    const UnitEstimate e = unit_estimate(x);
    EXPECT_LE(e.radius, 0x1p-30) << "circles 2^-" << k << " apart";
    double d2 = 0;
    for (int i = 0; i < 3; ++i) d2 += (e.unit[i] - expect[i]) * (e.unit[i] - expect[i]);
    EXPECT_LE(std::sqrt(d2), e.radius + 1e-16) << "circles 2^-" << k << " apart";
  }
}

}  // namespace
}  // namespace gvm::exact
