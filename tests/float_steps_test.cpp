// The libm-free steps against libm itself: they round boxes outwards and scale unit
// estimates, so one wrong bit would make a box miss the exact point it must hold.
#include "exact/float_steps.h"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace gvm::exact {
namespace {

bool same_bits(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
}

std::vector<double> awkward_doubles() {
  std::vector<double> out{0.0, -0.0, 0x1p-1074, -0x1p-1074, DBL_MIN, -DBL_MIN, DBL_MIN - 0x1p-1074, DBL_MAX,
                          -DBL_MAX, HUGE_VAL, -HUGE_VAL, std::numeric_limits<double>::quiet_NaN(), 1.0, -1.0,
                          1.0 - 0x1p-53, 0x1p-1022 * 1.5, 0x1p1023};
  std::mt19937_64 rng(20261203);
  for (int i = 0; i < 20000; ++i) out.push_back(std::bit_cast<double>(rng()));  // every exponent, subnormals too
  return out;
}

TEST(FloatSteps, NextUpAndDownAreNextafter) {
  for (double x : awkward_doubles()) {
    SCOPED_TRACE(x);
    ASSERT_TRUE(same_bits(next_up(x), std::nextafter(x, HUGE_VAL)));
    ASSERT_TRUE(same_bits(next_down(x), std::nextafter(x, -HUGE_VAL)));
  }
}

TEST(FloatSteps, ScalingIsLdexpAndTheExponentIlogb) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> exponent(-1100, 1100);
  int subnormal_results = 0;
  for (double x : awkward_doubles()) {
    if (!std::isfinite(x)) continue;
    SCOPED_TRACE(x);
    if (x != 0) ASSERT_EQ(binary_exponent(x), std::ilogb(x));
    for (int e : {exponent(rng), exponent(rng), -1022, 1023, -1023, -1074, -std::ilogb(x == 0 ? 1.0 : x)}) {
      const double want = std::ldexp(x, e);
      ASSERT_TRUE(same_bits(scale_by_power_of_two(x, e), want)) << "e = " << e;
      subnormal_results += want != 0 && std::fabs(want) < DBL_MIN;
    }
  }
  EXPECT_GT(subnormal_results, 100);  // the rounded results, where a wrong scale shows
}

}  // namespace
}  // namespace gvm::exact
