// Steps of one unit in the last place and scaling by powers of two, without libm calls:
// boxes are rounded outwards and unit estimates scaled by the million per part, where
// std::nextafter and std::ldexp cost a call each (visible in profiles:
// docs/performance-history.md).
// Each returns exactly what the libm function returns, for every double.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace gvm::exact {

// std::nextafter(x, +infinity).
inline double next_up(double x) {
  if (std::isnan(x) || x == HUGE_VAL) return x;
  if (x == 0) return 0x1p-1074;
  const uint64_t bits = std::bit_cast<uint64_t>(x);
  return std::bit_cast<double>(x > 0 ? bits + 1 : bits - 1);
}

// std::nextafter(x, -infinity).
inline double next_down(double x) { return -next_up(-x); }

// std::ldexp(x, e): one multiplication where 2^e is a normal double, as the product is
// then rounded exactly as ldexp rounds (only a subnormal result is rounded at all).
inline double scale_by_power_of_two(double x, int e) {
  if (e < -1022 || e > 1023) return std::ldexp(x, e);
  return x * std::bit_cast<double>(static_cast<uint64_t>(e + 1023) << 52);
}

// std::ilogb(x) for finite nonzero x.
inline int binary_exponent(double x) {
  const int biased = static_cast<int>(std::bit_cast<uint64_t>(x) >> 52 & 0x7ff);
  return biased == 0 ? std::ilogb(x) : biased - 1023;  // subnormals: rare, left to libm
}

}  // namespace gvm::exact
