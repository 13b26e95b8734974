// Basic value types shared by every module of the engine.
#pragma once

#include <array>
#include <cstdint>

namespace gvm {

// A point or vector with the exact double coordinates read from the input.
struct Point3 {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Point3&, const Point3&) = default;
  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

// Sign of an exactly evaluated quantity. Zero is an answer, never a tie to break.
enum class Sign : int { kNegative = -1, kZero = 0, kPositive = 1 };

inline Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
inline Sign operator*(Sign a, Sign b) {
  return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b));
}

using Triangle = std::array<uint32_t, 3>;

}  // namespace gvm
