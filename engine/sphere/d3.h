// Double-precision 3-vectors for what doubles are allowed to do here: estimates, boxes,
// search ranges, output, and tests with a certified slack. Never for a decision that
// the exact predicates (exact/) make.
#pragma once

#include <array>
#include <cmath>

namespace gvm::sphere {

using D3 = std::array<double, 3>;

inline double dot(const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline D3 cross(const D3& a, const D3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const D3& a) { return std::sqrt(dot(a, a)); }
inline D3 normalized(const D3& a) {
  const double n = norm(a);
  return {a[0] / n, a[1] / n, a[2] / n};
}
inline D3 negated(const D3& a) { return {-a[0], -a[1], -a[2]}; }
// a + s b
inline D3 add(const D3& a, const D3& b, double s = 1) {
  return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
}

}  // namespace gvm::sphere
