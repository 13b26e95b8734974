// What open intervals of an arc leave uncovered, checked point by point exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "sphere/arc_intervals.h"

namespace gvm::sphere {
namespace {

using exact::ExactVec;

// Nested intervals of a quarter circle, as the occlusion probe gets them from pairwise
// maps: ends shared exactly by distinct nodes (the same direction scaled by powers of
// two), ends 1e-9 radians apart (closer than the margin of the angles that leave out
// nested intervals before the exact sort), and ends 1e-20 apart (closer than the angles
// can tell). Sparse sets, so that an interval left out wrongly shows.
TEST(ArcIntervals, ComplementOfNestedAndTiedIntervalsIsExact) {
  const Arc arc{ExactVec::from_point({1, 0, 0}), ExactVec::from_point({0, 1, 0}),
                ExactVec::from_point({0, 0, 1})};
  const ArcOrder order{arc.normal};
  // Every direction on the circle z = 0 is exactly on the arc's circle.
  std::vector<std::array<double, 2>> base = {{1, 1e-20}, {1, 2e-20}, {1, 3e-20}};
  for (int k = 1; k < 24; ++k) {
    base.push_back({std::cos(k * M_PI / 48), std::sin(k * M_PI / 48)});
    if (k % 3 == 0) base.push_back({std::cos(k * M_PI / 48 + 1e-9), std::sin(k * M_PI / 48 + 1e-9)});
  }
  std::sort(base.begin(), base.end(), [](const auto& a, const auto& b) { return a[1] * b[0] < b[1] * a[0]; });
  auto at = [&](size_t k, double scale) { return ExactVec::from_point({scale * base[k][0], scale * base[k][1], 0}); };
  std::vector<ExactVec> samples;  // every end, and a direction between each two neighbours
  for (size_t k = 0; k < base.size(); ++k) {
    samples.push_back(at(k, 1));
    if (k + 1 < base.size()) samples.push_back(at(k, 1) + at(k + 1, 1));
  }
  std::mt19937 rng(11);
  std::uniform_int_distribution<size_t> pick(0, base.size() - 1);
  const double scales[] = {1, 2, 0.5, 4};
  int inside = 0, outside = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Interval> covered;
    for (int i = 0; i < 12; ++i) {
      size_t lo = pick(rng), hi = pick(rng);
      if (lo == hi) continue;
      if (lo > hi) std::swap(lo, hi);
      if (i % 3 != 0) hi = std::min(hi, lo + 1 + rng() % 3);  // short ones, nested in long ones
      covered.push_back({at(lo, scales[rng() % 4]), at(hi, scales[rng() % 4])});
    }
    const std::vector<Arc> pieces = complement(arc, covered);
    for (const ExactVec& x : samples) {
      bool in_interval = false;
      for (const Interval& c : covered) in_interval |= order.before(c.lo, x) && order.before(x, c.hi);
      bool in_piece = false;
      for (const Arc& p : pieces) in_piece |= !order.before(x, p.start) && !order.before(p.end, x);
      ASSERT_NE(in_interval, in_piece) << "trial " << trial << ", sample at " << x.unit()[0] << ", " << x.unit()[1];
      (in_interval ? inside : outside) += 1;
    }
  }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 1000);
}

}  // namespace
}  // namespace gvm::sphere
