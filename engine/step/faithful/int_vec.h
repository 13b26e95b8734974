// Integer vectors for the faithful tessellation: the directions it keeps exactly and the
// mesh points, both on integer lattices, so that every relation it promises (a facet
// containing a hole's axis, two walls parallel) is an integer identity, checked in
// integers, and holds exactly in the doubles the engine reads (a point is its grid
// coordinates times a power of two).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <numeric>

namespace gvm::faithful {

using i128 = __int128;

struct IVec {
  int64_t x = 0, y = 0, z = 0;
  int64_t operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  friend bool operator==(const IVec&, const IVec&) = default;
  friend IVec operator+(const IVec& a, const IVec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend IVec operator-(const IVec& a, const IVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend IVec operator*(int64_t k, const IVec& a) { return {k * a.x, k * a.y, k * a.z}; }
  bool is_zero() const { return x == 0 && y == 0 && z == 0; }
};

inline i128 dot(const IVec& a, const IVec& b) { return i128(a.x) * b.x + i128(a.y) * b.y + i128(a.z) * b.z; }

// Components of class vectors stay below 2^31, so their cross products fit.
inline IVec cross(const IVec& a, const IVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

inline int64_t gcd3(const IVec& v) { return std::gcd(std::gcd(std::llabs(v.x), std::llabs(v.y)), std::llabs(v.z)); }

// The vector divided by the gcd of its components, its first non-zero component positive:
// one representative for a line of directions.
inline IVec canonical(IVec v) {
  const int64_t g = gcd3(v);
  if (g == 0) return v;
  v = {v.x / g, v.y / g, v.z / g};
  const int64_t lead = v.x != 0 ? v.x : (v.y != 0 ? v.y : v.z);
  return lead < 0 ? (-1) * v : v;
}

inline int64_t max_abs(const IVec& v) { return std::max({std::llabs(v.x), std::llabs(v.y), std::llabs(v.z)}); }

// Rounds n / d to the nearest integer (ties away from zero), d > 0.
inline i128 round_div(i128 n, i128 d) {
  const i128 q = n / d, r = n % d;
  if (2 * (r < 0 ? -r : r) >= d) return q + (n < 0 ? -1 : 1);
  return q;
}

}  // namespace gvm::faithful
