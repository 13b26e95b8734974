// Boxes around directions and arcs (sphere/box_tree.h) against directions computed
// independently in 512-bit GMP floats, and the work of arrangements over clusters of
// directions closer together than any double estimate can tell apart.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/arrangement.h"
#include "sphere/box_tree.h"

namespace gvm::sphere {
namespace {

using exact::ExactVec;
using Big = std::array<mpf_class, 3>;

constexpr mp_bitcnt_t kBits = 512;

mpf_class big(double x) { return mpf_class(x, kBits); }

// A vector both exactly and in big floats (exact too: differences and cross products of
// doubles need at most a few hundred bits).
struct Twin {
  ExactVec exact;
  Big value;
};

Twin point(double x, double y, double z) {
  return {ExactVec::from_point({x, y, z}), {big(x), big(y), big(z)}};
}

Twin minus(const Twin& a, const Twin& b) {
  Big d;
  for (int i = 0; i < 3; ++i) d[i] = mpf_class(a.value[i] - b.value[i], kBits);
  return {a.exact - b.exact, d};
}

Twin cross(const Twin& a, const Twin& b) {
  Big c;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    c[i] = mpf_class(a.value[j] * b.value[k] - a.value[k] * b.value[j], kBits);
  }
  return {exact::cross(a.exact, b.exact), c};
}

Big normalized(const Big& v) {
  mpf_class n2(0, kBits);
  for (const mpf_class& x : v) n2 += x * x;
  const mpf_class n = sqrt(n2);
  Big u;
  for (int i = 0; i < 3; ++i) u[i] = mpf_class(v[i] / n, kBits);
  return u;
}

bool holds(const Box& b, const Big& u) {
  for (int i = 0; i < 3; ++i) {
    if (u[i] < b.lo[i] || u[i] > b.hi[i]) return false;
  }
  return true;
}

// A point of the minor arc a -> b: (1 - t) a + t b, normalized.
Big on_arc(const Big& a, const Big& b, double t) {
  Big p;
  for (int i = 0; i < 3; ++i) p[i] = mpf_class((1 - big(t)) * a[i] + big(t) * b[i], kBits);
  return normalized(p);
}

// Vectors of the kinds the engine makes: CAD coordinates, differences of points a fraction
// of a micrometre apart whose other coordinates differ in the last bits (directions within
// 1e-13 of an axis), and cross products of such differences.
std::vector<Twin> sample_vectors(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> coord(-200, 200), unit(-1, 1);
  std::uniform_int_distribution<int> ulps(-8, 8);
  std::vector<Twin> out;
  for (int k = 0; k < 300; ++k) {
    const double x = coord(rng), y = coord(rng), z = coord(rng);
    const Twin p = point(x, y, z);
    // The same corner a step of 0.23 um up, x and y a few ulps off.
    auto nudge = [&](double v) {
      double w = v;
      for (int n = ulps(rng); n != 0; n += n > 0 ? -1 : 1) w = std::nextafter(w, n > 0 ? 1e300 : -1e300);
      return w;
    };
    const Twin q = point(nudge(x), nudge(y), z + 2.3e-4);
    out.push_back(point(x, y, z));
    out.push_back(minus(q, p));
    out.push_back(minus(point(coord(rng), coord(rng), coord(rng)), p));
    out.push_back(cross(minus(q, p), minus(point(x + unit(rng), y + unit(rng), z), p)));
  }
  return out;
}

bool is_zero(const Big& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

TEST(DirectionBox, BoxesHoldTheExactDirection) {
  std::mt19937_64 rng(20261128);
  int checked = 0;
  for (const Twin& v : sample_vectors(rng)) {
    if (is_zero(v.value)) continue;
    const Big u = normalized(v.value);
    ASSERT_TRUE(holds(exact_point_box(v.exact), u)) << "exact box, vector " << checked;
    ASSERT_TRUE(holds(point_box(exact::unit_estimate(v.exact)), u)) << "estimate box, vector " << checked;
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST(DirectionBox, ExactBoxesTellApartDirectionsNearAnAxis) {
  // 1e-20 apart, next to -z: a double estimate of radius 2^-50 cannot separate them.
  const ExactVec a = ExactVec::from_point({1e-20, 0, -1}), b = ExactVec::from_point({2e-20, 0, -1});
  EXPECT_FALSE(overlap(exact_point_box(a), exact_point_box(b)));
  EXPECT_TRUE(overlap(point_box(exact::unit_estimate(a)), point_box(exact::unit_estimate(b))));
}

TEST(DirectionBox, ArcBoxesHoldTheirArcsLongAndTiny) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<std::pair<Twin, Twin>> arcs;
  for (int k = 0; k < 200; ++k) arcs.push_back({point(unit(rng), unit(rng), unit(rng)), point(unit(rng), unit(rng), unit(rng))});
  for (int k = 0; k < 100; ++k) {  // tiny, by the pole: ends 1e-16 to 1e-14 apart
    const double s = std::ldexp(1.0, -(46 + k % 8));
    arcs.push_back({point(unit(rng) * s, unit(rng) * s, -1), point(unit(rng) * s, unit(rng) * s, -1)});
  }
  arcs.push_back({point(1, 1e-9, 0), point(-1, 1e-9, 1e-9)});  // nearly a half circle
  int checked = 0;
  for (const auto& [a, b] : arcs) {
    const Big ua = normalized(a.value), ub = normalized(b.value);
    mpf_class dot(0, kBits);
    for (int i = 0; i < 3; ++i) dot += ua[i] * ub[i];
    if (dot <= -1 + 1e-30) continue;  // antipodal: no minor arc
    const Box exact_box = arc_box(exact_point_box(a.exact), exact_point_box(b.exact));
    const Box estimate_box = arc_box(exact::unit_estimate(a.exact), exact::unit_estimate(b.exact));
    for (double t = 0; t <= 1; t += 1.0 / 64) {
      const Big p = on_arc(ua, ub, t);
      ASSERT_TRUE(holds(exact_box, p)) << "arc " << checked << " t " << t;
      ASSERT_TRUE(holds(estimate_box, p)) << "arc " << checked << " t " << t;
    }
    ++checked;
  }
  EXPECT_GT(checked, 290);
  // A tiny arc keeps a tiny box (no absolute padding).
  const Box tiny = arc_box(exact_point_box(ExactVec::from_point({1e-15, 0, -1})),
                           exact_point_box(ExactVec::from_point({0, 1e-15, -1})));
  EXPECT_LT(tiny.hi[0] - tiny.lo[0], 1e-14);
  EXPECT_LT(tiny.hi[1] - tiny.lo[1], 1e-14);
}

// A polygon of n vertices on a circle of radius 1e-14 about -z, plus a triangle far away
// whose long sides pass by it: the arrangement compares each arc with its neighbours, not
// every arc of the cluster with every other (n^2 / 2 pairs with boxes the estimates give).
TEST(DirectionBox, ArrangementOfAClusterComparesNeighboursOnly) {
  const int n = 3000;
  std::vector<ExactVec> ring;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n;
    ring.push_back(ExactVec::from_point({1e-14 * std::cos(t), 1e-14 * std::sin(t), -1}));
  }
  std::vector<ArrangementArc> arcs;
  for (int k = 0; k < n; ++k) {
    // Clockwise about -z seen from inside the sphere: the pole on the left.
    const ExactVec &a = ring[(k + 1) % n], &b = ring[k];
    arcs.push_back({a, b, exact::cross(a, b), 0, 1});
  }
  const ExactVec reference = ExactVec::from_point({0.3, -0.2, 1});
  const int coverage[1] = {0};
  const Arrangement arr(arcs, {}, 1, reference, coverage);
  EXPECT_EQ(arr.vertices().size(), size_t(n) + 1);  // the ring and the reference
  EXPECT_LT(arr.compared_pairs(), uint64_t(20) * n);
  // Inside the ring (the pole) coverage 1, outside 0.
  int inside = 0;
  for (uint32_t f = 0; f < arr.faces().size(); ++f) inside += arr.coverage(f, 0);
  EXPECT_EQ(inside, 1);
}

}  // namespace
}  // namespace gvm::sphere
