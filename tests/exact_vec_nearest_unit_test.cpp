// ExactVec::nearest_unit: the exact unit vector rounded to nearest, coordinate by
// coordinate, whatever the construction -- checked against exact rationals.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "exact/exact_vec.h"

namespace gvm::exact {
namespace {

ExactVec v(double x, double y, double z) { return ExactVec::from_point({x, y, z}); }

// Whether r is a double nearest to x / |c| (c: the exact coordinates): (r - a)^2 |c|^2 <=
// x^2 <= (r + b)^2 |c|^2 for the half gaps a, b to r's neighbours, on magnitudes (same signs).
bool nearest(double r, const mpq_class& x, const std::array<mpq_class, 3>& c) {
  if ((x < 0) != std::signbit(r) && x != 0) return false;
  const mpq_class s = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
  const double m = std::fabs(r);
  const mpq_class lo = m == 0 ? mpq_class(0) : (mpq_class(m) + mpq_class(std::nextafter(m, 0.0))) / 2;
  const mpq_class hi = (mpq_class(m) + mpq_class(std::nextafter(m, INFINITY))) / 2;
  return lo * lo * s <= x * x && x * x <= hi * hi * s;
}

TEST(NearestUnit, KnownDirectionsGiveTheirNearestDoubles) {
  // 0.6, 0.8, 1/sqrt(2), 1/sqrt(3) as literals are the doubles nearest those values.
  EXPECT_EQ(v(3, 4, 0).nearest_unit(), (std::array<double, 3>{0.6, 0.8, 0}));
  EXPECT_EQ(v(0, -3e-200, 4e-200).nearest_unit(), (std::array<double, 3>{0, -0.6, 0.8}));
  EXPECT_EQ(v(5, 5, 0).nearest_unit(), (std::array<double, 3>{0.70710678118654752440, 0.70710678118654752440, 0}));
  const double third = 0.57735026918962576451;
  EXPECT_EQ(v(-7, 7, -7).nearest_unit(), (std::array<double, 3>{-third, third, -third}));
  EXPECT_EQ(v(0, 0, 1e300).nearest_unit(), (std::array<double, 3>{0, 0, 1}));
}

TEST(NearestUnit, OneDirectionBuiltInManyWaysGivesTheSameDoubles) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coord(-1, 1);
  int differed = 0;  // how often the 2^-50 estimate of unit() differs between the copies
  for (int trial = 0; trial < 2000; ++trial) {
    const ExactVec a = v(coord(rng), coord(rng), coord(rng)), b = v(coord(rng), coord(rng), coord(rng));
    const ExactVec d = v(0x1p-3, 0, 0);
    // The same direction as a x b: scaled operands, a sum, and a difference of crossings.
    const ExactVec n = cross(a, b);
    const std::array<ExactVec, 4> same{cross(a + a, b), cross(a, b) + cross(a, b - a),
                                       cross(cross(n, d), cross(n, v(0, 1, 0))),
                                       cross(a - b - b, b + b + b)};
    const std::array<double, 3> expected = n.nearest_unit();
    for (const ExactVec& x : same) {
      const int sign = sign_dot(x, n) == Sign::kPositive ? 1 : -1;
      std::array<double, 3> got = x.nearest_unit();
      for (double& g : got) g *= sign;
      EXPECT_EQ(got, expected);
      std::array<double, 3> rough = x.unit();
      for (double& g : rough) g *= sign;
      differed += rough != n.unit();
    }
  }
  EXPECT_GT(differed, 0);  // the constructions do lead unit() to different doubles
}

TEST(NearestUnit, EachCoordinateIsTheNearestDoubleToTheExactValue) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coord(-1, 1);
  std::uniform_int_distribution<int> exponent(-300, 300);
  for (int trial = 0; trial < 3000; ++trial) {
    // Coordinates of very different magnitudes, and some equal to zero.
    std::array<double, 3> p, q;
    for (int i = 0; i < 3; ++i) {
      p[i] = trial % 7 == i ? 0 : std::ldexp(coord(rng), trial % 3 == 0 ? exponent(rng) : 0);
      q[i] = coord(rng);
    }
    const ExactVec x = cross(v(p[0], p[1], p[2]), v(q[0], q[1], q[2]));
    std::array<mpq_class, 3> c;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      c[i] = mpq_class(p[j]) * mpq_class(q[k]) - mpq_class(p[k]) * mpq_class(q[j]);
    }
    if (c[0] == 0 && c[1] == 0 && c[2] == 0) continue;
    const std::array<double, 3> u = x.nearest_unit();
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(nearest(u[i], c[i], c)) << "trial " << trial << " coordinate " << i;
  }
}

}  // namespace
}  // namespace gvm::exact
