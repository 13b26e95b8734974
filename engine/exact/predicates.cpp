#include "exact/predicates.h"

#include <tbb/parallel_invoke.h>

#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>

#include "exact/approx.h"
#include "exact/dyadic.h"
#include "exact/expansion.h"
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

// The first and cheapest stage for determinants of differences of input doubles, before
// the Approx filter (which tracks an error per operation, several times the cost): plain
// doubles and one error bound from the permanent, as in Shewchuk's orient3d and orient2d
// ("Adaptive precision floating-point arithmetic and fast robust geometric predicates",
// 1997, Sec. 4.3). Evaluated in doubles from the rounded differences, the 3x3 determinant
// is within (7 + 56u) u P of the exact one, P its computed permanent, u = 2^-53, and the
// 2x2 one within (3 + 16u) u P, as long as nothing underflows or overflows. We take 8u
// and 4u: the slack covers the rounding of the bound itself. A product that underflows
// is off by 2^-1075 at most (subnormal sums and differences are exact); after the outer
// products, (|a.x| + |a.y| + |a.z| + 1) 2^-1069 covers those. An overflow makes the
// permanent, hence the bound, infinite or not a number: no sign is decided then.
std::optional<Sign> decided(double det, double bound) {
  if (det > bound) return Sign::kPositive;
  if (det < -bound) return Sign::kNegative;
  return std::nullopt;
}

std::optional<Sign> static_det3(const V<double>& a, const V<double>& b, const V<double>& c) {
  const double yz = b.y * c.z, zy = b.z * c.y, xz = b.x * c.z, zx = b.z * c.x, xy = b.x * c.y,
               yx = b.y * c.x;
  const double det = a.x * (yz - zy) - a.y * (xz - zx) + a.z * (xy - yx);
  const double ax = std::fabs(a.x), ay = std::fabs(a.y), az = std::fabs(a.z);
  const double permanent = ax * (std::fabs(yz) + std::fabs(zy)) + ay * (std::fabs(xz) + std::fabs(zx)) +
                           az * (std::fabs(xy) + std::fabs(yx));
  return decided(det, 0x1p-50 * permanent + (ax + ay + az + 1) * 0x1p-1069);
}

std::optional<Sign> static_det2(double ux, double uy, double vx, double vy) {
  const double left = ux * vy, right = uy * vx;
  const double permanent = std::fabs(left) + std::fabs(right);
  return decided(left - right, 0x1p-51 * permanent + 0x1p-1070);
}

// Coordinates for which the expansion stage is exact: zero, or between 2^-200 and 2^200
// in magnitude. Each is then a multiple of 2^-252 (its ulp), so every value the stage
// forms, a product of at most three differences or a part of one, is zero or a multiple
// of 2^-756 below 2^610: nothing underflows and nothing overflows.
bool expansion_exact(const Point3& p) {
  for (int i = 0; i < 3; ++i) {
    const double a = std::fabs(p[i]);
    if (a != 0 && !(a >= 0x1p-200 && a <= 0x1p200)) return false;
  }
  return true;
}

// The exact stage: expansions in that range, GMP beyond it (coordinates of 1e-300 and
// 1e300 are valid input, only rare).
template <class Filtered, class Expanded>
Sign exact_stage(std::initializer_list<Point3> points, const Filtered& filtered, const Expanded& expanded) {
  if (auto s = filtered(Approx{}).sign()) return *s;
  for (const Point3& p : points) {
    if (!expansion_exact(p)) return filtered(Dyadic{}).sign();
  }
  return expanded();
}

// det(a1 - a0, b1 - b0, c1 - c0): the static stage, the filter, then exactly.
Sign det3_of_differences(const Point3& a0, const Point3& a1, const Point3& b0, const Point3& b1,
                         const Point3& c0, const Point3& c1) {
  if (auto s = static_det3(diff<double>(a1, a0), diff<double>(b1, b0), diff<double>(c1, c0))) return *s;
  auto filtered = [&](auto tag) {
    using T = decltype(tag);
    return det3(diff<T>(a1, a0), diff<T>(b1, b0), diff<T>(c1, c0));
  };
  return exact_stage({a0, a1, b0, b1, c0, c1}, filtered, [&] {
    Expansion<2> a[3], b[3], c[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = difference(a1[i], a0[i]);
      b[i] = difference(b1[i], b0[i]);
      c[i] = difference(c1[i], c0[i]);
    }
    auto minor = [&](int i, int j) {  // b_i c_j - b_j c_i
      Expansion<16> m;
      m.add(b[i] * c[j]);
      m.add(b[j] * c[i], -1);
      return m;
    };
    Expansion<192> det;
    det.add(a[0] * minor(1, 2));
    det.add(a[1] * minor(0, 2), -1);
    det.add(a[2] * minor(0, 1));
    return det.sign();
  });
}

}  // namespace

Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  // A plane normal to an axis (most planes of CAD parts): the determinant is
  // (d - a)[axis] times the orientation of a, b, c seen along the axis, both signs exact
  // without the expensive exact stage, which the filter otherwise needs whenever d lies
  // on the plane (a box corner on a face's plane, a vertex of a coplanar face).
  for (int axis = 0; axis < 3; ++axis) {
    if (a[axis] == b[axis] && a[axis] == c[axis]) {
      const Sign height = d[axis] > a[axis] ? Sign::kPositive : d[axis] < a[axis] ? Sign::kNegative : Sign::kZero;
      return height == Sign::kZero ? Sign::kZero : height * orient2d(a, b, c, axis);
    }
  }
  return det3_of_differences(a, b, a, c, a, d);
}

DifferenceDet::DifferenceDet(const Point3& a0, const Point3& a1, const Point3& b0, const Point3& b1)
    : a0_(a0), a1_(a1), b0_(b0), b1_(b1) {
  const V<double> u = diff<double>(a1, a0), v = diff<double>(b1, b0);
  const double yz = u.y * v.z, zy = u.z * v.y, zx = u.z * v.x, xz = u.x * v.z, xy = u.x * v.y, yx = u.y * v.x;
  minor_[0] = yz - zy, minor_[1] = zx - xz, minor_[2] = xy - yx;
  permanent_[0] = std::fabs(yz) + std::fabs(zy);
  permanent_[1] = std::fabs(zx) + std::fabs(xz);
  permanent_[2] = std::fabs(xy) + std::fabs(yx);
  for (int axis = 0; axis < 3 && axis_ < 0; ++axis) {
    if (a0[axis] == a1[axis] && b0[axis] == b1[axis]) {
      axis_ = axis;
      const Point3 unit{double(axis == 0), double(axis == 1), double(axis == 2)};
      axis_sign_ = det3_of_differences(a0, a1, b0, b1, Point3{0, 0, 0}, unit);
    }
  }
}

// det(c1 - c0, a1 - a0, b1 - b0), the same sign as det(a1 - a0, b1 - b0, c1 - c0),
// evaluated as static_det3 evaluates it, with its bound. Both differences normal to an
// axis (the edges and faces of CAD parts, most of which run along axes): their cross
// product lies along it, and the determinant is its sign times the third difference's
// coordinate there, exact without the exact stage, which zeros (a third vector along the
// plane) would otherwise take.
std::optional<Sign> DifferenceDet::filtered(const Point3& c0, const Point3& c1) const {
  if (axis_ >= 0) {
    const Sign along = c1[axis_] > c0[axis_] ? Sign::kPositive : c1[axis_] < c0[axis_] ? Sign::kNegative : Sign::kZero;
    return along * axis_sign_;
  }
  const V<double> w = diff<double>(c1, c0);
  const double det = w.x * minor_[0] + w.y * minor_[1] + w.z * minor_[2];
  const double ax = std::fabs(w.x), ay = std::fabs(w.y), az = std::fabs(w.z);
  const double permanent = ax * permanent_[0] + ay * permanent_[1] + az * permanent_[2];
  return decided(det, 0x1p-50 * permanent + (ax + ay + az + 1) * 0x1p-1069);
}

Sign DifferenceDet::operator()(const Point3& c0, const Point3& c1) const {
  if (auto s = filtered(c0, c1)) return *s;
  return det3_of_differences(a0_, a1_, b0_, b1_, c0, c1);
}

Sign PlaneSide::operator()(const Point3& d) const {
  if (auto s = det_.filtered(a_, d)) return *s;
  return orient3d(a_, b_, c_, d);
}

Sign det_diff(const Point3& a0, const Point3& a1, const Point3& b0, const Point3& b1,
              const Point3& c0, const Point3& c1) {
  return det3_of_differences(a0, a1, b0, b1, c0, c1);
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
  // Both products vanish when a, b, c share a coordinate (the normal of an axis-aligned
  // plane has zero components): zero, without the exact stage the filter would need.
  if ((a[i] == b[i] && a[i] == c[i]) || (a[j] == b[j] && a[j] == c[j])) return Sign::kZero;
  if (auto s = static_det2(b[i] - a[i], b[j] - a[j], c[i] - a[i], c[j] - a[j])) return *s;
  auto filtered = [&](auto tag) {
    using T = decltype(tag);
    auto u = diff<T>(b, a);
    auto v = diff<T>(c, a);
    return coord(u, i) * coord(v, j) - coord(u, j) * coord(v, i);
  };
  return exact_stage({a, b, c}, filtered, [&] {
    Expansion<16> det;
    det.add(difference(b[i], a[i]) * difference(c[j], a[j]));
    det.add(difference(b[j], a[j]) * difference(c[i], a[i]), -1);
    return det.sign();
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

namespace {

// (b-a) x (c-a) in number type T.
template <class T>
std::array<T, 3> triangle_cross(const Point3& a, const Point3& b, const Point3& c) {
  T ux = T(b.x) - T(a.x), uy = T(b.y) - T(a.y), uz = T(b.z) - T(a.z);
  T vx = T(c.x) - T(a.x), vy = T(c.y) - T(a.y), vz = T(c.z) - T(a.z);
  return {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
}

template <class T>
T dot3(const std::array<T, 3>& u, const std::array<T, 3>& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

// Sums this long have their two halves summed in parallel.
constexpr size_t kParallelSumFrom = 16384;

// term(T{}, i) summed over [lo, hi) pairwise: the rounding committed while accumulating
// the filter's error bound then grows with log n, not with n, so Approx::sign's safety
// factor (a few hundred operations along any path) holds for sums of any length.
template <class T, class Term>
T pairwise_sum(size_t lo, size_t hi, const Term& term) {
  if (hi - lo <= 8) {
    T sum(0.0);
    for (size_t i = lo; i < hi; ++i) sum = sum + term(T{}, i);
    return sum;
  }
  const size_t mid = lo + (hi - lo) / 2;
  if (hi - lo < kParallelSumFrom) return pairwise_sum<T>(lo, mid, term) + pairwise_sum<T>(mid, hi, term);
  // The same tree of sums on any number of threads: the same rounding.
  T left(0.0), right(0.0);
  tbb::parallel_invoke([&] { left = pairwise_sum<T>(lo, mid, term); }, [&] { right = pairwise_sum<T>(mid, hi, term); });
  return left + right;
}

template <class Term>
Sign sum_sign(size_t n, const Term& term) {
  if (auto s = pairwise_sum<Approx>(0, n, term).sign()) return *s;
  return pairwise_sum<Dyadic>(0, n, term).sign();
}

}  // namespace

Sign normal_dot(const Point3& a1, const Point3& b1, const Point3& c1, const Point3& a2, const Point3& b2,
                const Point3& c2) {
  return filtered_sign([&](auto tag) {
    using T = decltype(tag);
    return dot3(triangle_cross<T>(a1, b1, c1), triangle_cross<T>(a2, b2, c2));
  });
}

// n1 . n2 > k |n1| |n2|, by the signs of d = n1 . n2 and of d^2 - k^2 |n1|^2 |n2|^2:
//   k > 0:  d > 0 and d^2 > k^2 |n1|^2 |n2|^2
//   k = 0:  d > 0
//   k < 0:  d >= 0, or d^2 < k^2 |n1|^2 |n2|^2.
bool normals_within(const Point3& a1, const Point3& b1, const Point3& c1, const Point3& a2, const Point3& b2,
                    const Point3& c2, double k) {
  const Sign sd = normal_dot(a1, b1, c1, a2, b2, c2);
  if (k == 0) return sd == Sign::kPositive;
  if (k > 0 && sd != Sign::kPositive) return false;
  if (k < 0 && sd != Sign::kNegative) return true;
  const Sign s = filtered_sign([&](auto tag) {
    using T = decltype(tag);
    const auto n1 = triangle_cross<T>(a1, b1, c1), n2 = triangle_cross<T>(a2, b2, c2);
    const T d = dot3(n1, n2);
    return d * d - T(k) * T(k) * dot3(n1, n1) * dot3(n2, n2);
  });
  return k > 0 ? s == Sign::kPositive : s == Sign::kNegative;
}

Sign polygon_area_sign(std::span<const Point3> points, std::span<const uint32_t> polygon, int drop) {
  const int i = (drop + 1) % 3, j = (drop + 2) % 3;
  const size_t n = polygon.size();
  return sum_sign(n, [&](auto tag, size_t k) {
    using T = decltype(tag);
    const Point3& p = points[polygon[k]];
    const Point3& q = points[polygon[(k + 1) % n]];
    return T(p[i]) * T(q[j]) - T(p[j]) * T(q[i]);
  });
}

Sign signed_volume_sign(std::span<const Point3> points, std::span<const Triangle> triangles,
                        std::span<const uint32_t> which) {
  return sum_sign(which.size(), [&](auto tag, size_t k) {
    using T = decltype(tag);
    const Triangle& t = triangles[which[k]];
    const Point3 &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    const std::array<T, 3> bc = {T(b.y) * T(c.z) - T(b.z) * T(c.y), T(b.z) * T(c.x) - T(b.x) * T(c.z),
                                 T(b.x) * T(c.y) - T(b.y) * T(c.x)};
    return T(a.x) * bc[0] + T(a.y) * bc[1] + T(a.z) * bc[2];
  });
}

}  // namespace gvm::exact
