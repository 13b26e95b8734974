#include "exact/predicates.h"

#include "exact/approx.h"
#include "exact/dyadic.h"
#include "exact/filtered.h"

namespace gvm::exact {
namespace {

template <class T>
struct V {
  T x, y, z;
};

template <class T>
V<T> diff(const Point3& a, const Point3& b) {
  return {T(a.x) - T(b.x), T(a.y) - T(b.y), T(a.z) - T(b.z)};
}

template <class T>
T det3(const V<T>& a, const V<T>& b, const V<T>& c) {
  return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) +
         a.z * (b.x * c.y - b.y * c.x);
}

template <class T>
T coord(const V<T>& v, int i) {
  return i == 0 ? v.x : (i == 1 ? v.y : v.z);
}

}  // namespace

Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return filtered_sign([&](auto tag) {
    using T = decltype(tag);
    return det3(diff<T>(b, a), diff<T>(c, a), diff<T>(d, a));
  });
}

Sign det_diff(const Point3& a0, const Point3& a1, const Point3& b0, const Point3& b1,
              const Point3& c0, const Point3& c1) {
  return filtered_sign([&](auto tag) {
    using T = decltype(tag);
    return det3(diff<T>(a1, a0), diff<T>(b1, b0), diff<T>(c1, c0));
  });
}

Sign dot_diff(const Point3& a0, const Point3& a1, const Point3& b0, const Point3& b1) {
  return filtered_sign([&](auto tag) {
    using T = decltype(tag);
    auto a = diff<T>(a1, a0);
    auto b = diff<T>(b1, b0);
    return a.x * b.x + a.y * b.y + a.z * b.z;
  });
}

Sign orient2d(const Point3& a, const Point3& b, const Point3& c, int drop) {
  const int i = (drop + 1) % 3, j = (drop + 2) % 3;
  return filtered_sign([&](auto tag) {
    using T = decltype(tag);
    auto u = diff<T>(b, a);
    auto v = diff<T>(c, a);
    return coord(u, i) * coord(v, j) - coord(u, j) * coord(v, i);
  });
}

Sign cross_component(const Point3& a, const Point3& b, const Point3& c, int axis) {
  return orient2d(a, b, c, axis);
}

bool collinear(const Point3& a, const Point3& b, const Point3& c) {
  return orient2d(a, b, c, 0) == Sign::kZero && orient2d(a, b, c, 1) == Sign::kZero &&
         orient2d(a, b, c, 2) == Sign::kZero;
}

int compare_lex(const Point3& a, const Point3& b) {
  for (int i = 0; i < 3; ++i) {
    if (a[i] < b[i]) return -1;
    if (a[i] > b[i]) return 1;
  }
  return 0;
}

}  // namespace gvm::exact
