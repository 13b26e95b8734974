#include "mesh/exact_scale.h"

#include <algorithm>
#include <cmath>

namespace gvm::mesh_internal {

int magnitude_exponent(std::span<const Point3> points) {
  double largest = 0;
  for (const Point3& p : points) {
    largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  }
  return largest > 0 ? std::ilogb(largest) : 0;
}

bool scale_exactly(std::vector<Point3>& points, int k) {
  if (k == 0) return true;
  bool exact = true;
  auto scale = [&](double x) {
    const double y = std::ldexp(x, -k);
    exact &= std::ldexp(y, k) == x;  // false when it went subnormal (or overflowed) on the way
    return y;
  };
  std::vector<Point3> scaled(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    scaled[i] = {scale(points[i].x), scale(points[i].y), scale(points[i].z)};
  }
  if (exact) points = std::move(scaled);
  return exact;
}

}  // namespace gvm::mesh_internal
