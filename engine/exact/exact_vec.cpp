#include "exact/exact_vec.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cfloat>
#include <climits>
#include <cmath>
#include <new>
#include <type_traits>
#include <utility>

#include "exact/approx.h"
#include "exact/block_cache.h"
#include "exact/dyadic.h"
#include "exact/filtered.h"
#include "exact/float_steps.h"

namespace gvm::exact {
namespace {

enum class Op { kLeaf, kAdd, kSub, kNeg, kCross, kPointDifference, kTriangleNormal };

template <class T>
using V3 = std::array<T, 3>;

template <class T>
V3<T> cross3(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The cached exact value lives in a block of the per-thread caches, as nodes do.
void release_exact(const V3<Dyadic>* v) {
  if (!v) return;
  v->~V3<Dyadic>();
  CachedAllocator<V3<Dyadic>>().deallocate(const_cast<V3<Dyadic>*>(v), 1);
}

}  // namespace

struct ExactVec::Node {
  Op op = Op::kLeaf;
  Point3 leaf;
  std::shared_ptr<const Node> a, b;
  V3<Approx> approx;  // filtered value, computed once at construction
  // Exact value, computed the first time a predicate needs it: an arrangement vertex is
  // tested against many arcs, and degenerate input makes those tests exact.
  mutable std::atomic<const V3<Dyadic>*> exact{nullptr};

  Node() = default;
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;
  ~Node() { release_exact(exact.load(std::memory_order_relaxed)); }

  // The filtered value by copy, the exact one by reference to the cache.
  template <class T>
  decltype(auto) eval() const {
    if constexpr (std::is_same_v<T, Approx>) {
      return approx;
    } else {
      return exact_value();
    }
  }
  const V3<Dyadic>& exact_value() const;
  V3<Dyadic> compute_exact() const;
};

namespace {

// Two expressions of mesh points in one node each, the first point in `leaf`: q - p (a
// vertex of the Minkowski sum, an edge), and a triangle's normal (b - a) x (c - a). As
// trees of points and differences they took three and six nodes, and building the
// 185,404 distinct normals of occt_brep_Bottom's largest region cost 0.4 s, most of it
// allocating. No fact of construction (below) looks inside a difference, so none is lost.
struct PointDifferenceNode : ExactVec::Node {
  Point3 p;
};
struct TriangleNormalNode : ExactVec::Node {
  Point3 b, c;
};

}  // namespace

V3<Dyadic> ExactVec::Node::compute_exact() const {
  switch (op) {
    case Op::kLeaf:
      return {Dyadic(leaf.x), Dyadic(leaf.y), Dyadic(leaf.z)};
    case Op::kAdd: {
      const auto &x = a->exact_value(), &y = b->exact_value();
      return {x[0] + y[0], x[1] + y[1], x[2] + y[2]};
    }
    case Op::kSub: {
      const auto &x = a->exact_value(), &y = b->exact_value();
      return {x[0] - y[0], x[1] - y[1], x[2] - y[2]};
    }
    case Op::kNeg: {
      const auto& x = a->exact_value();
      return {-x[0], -x[1], -x[2]};
    }
    case Op::kCross:
      return cross3(a->exact_value(), b->exact_value());
    case Op::kPointDifference: {
      const Point3& p = static_cast<const PointDifferenceNode&>(*this).p;
      return {Dyadic(leaf.x) - Dyadic(p.x), Dyadic(leaf.y) - Dyadic(p.y), Dyadic(leaf.z) - Dyadic(p.z)};
    }
    case Op::kTriangleNormal: {
      const auto& t = static_cast<const TriangleNormalNode&>(*this);
      const Dyadic ax(leaf.x), ay(leaf.y), az(leaf.z);
      return cross3(V3<Dyadic>{Dyadic(t.b.x) - ax, Dyadic(t.b.y) - ay, Dyadic(t.b.z) - az},
                    V3<Dyadic>{Dyadic(t.c.x) - ax, Dyadic(t.c.y) - ay, Dyadic(t.c.z) - az});
    }
  }
  return {};
}

const V3<Dyadic>& ExactVec::Node::exact_value() const {
  if (const V3<Dyadic>* cached = exact.load(std::memory_order_acquire)) return *cached;
  V3<Dyadic> value = compute_exact();
  auto* fresh = new (CachedAllocator<V3<Dyadic>>().allocate(1)) V3<Dyadic>(std::move(value));
  const V3<Dyadic>* expected = nullptr;
  if (exact.compare_exchange_strong(expected, fresh, std::memory_order_acq_rel)) return *fresh;
  release_exact(fresh);  // another thread cached the same value first
  return *expected;
}

namespace {

const ExactVec::Node& zero_node() {
  static const ExactVec::Node kZero{};
  return kZero;
}

const ExactVec::Node& node_of(const ExactVec& v) { return v.node() ? *v.node() : zero_node(); }

std::shared_ptr<ExactVec::Node> new_node() {
  return std::allocate_shared<ExactVec::Node>(CachedAllocator<ExactVec::Node>{});
}

template <class T>
decltype(auto) eval(const ExactVec& v) {
  return node_of(v).eval<T>();
}

// Facts known from how vectors were built, which decide the zero cases that are common
// in arrangements (an arc's endpoint against its own circle, a vertex against the circles
// it was cut from) without any arithmetic: the same node up to negation is parallel, a
// factor of a cross product is orthogonal to it.
const ExactVec::Node* peel(const ExactVec::Node* n) {
  while (n && n->op == Op::kNeg) n = n->a.get();
  return n;
}

bool same_node(const ExactVec& a, const ExactVec& b) {
  const ExactVec::Node* x = peel(a.node());
  return x && x == peel(b.node());
}

bool factor_of(const ExactVec::Node* x, const ExactVec::Node* c) {
  c = peel(c);
  return x && c && c->op == Op::kCross && (peel(c->a.get()) == x || peel(c->b.get()) == x);
}

bool orthogonal_by_construction(const ExactVec& a, const ExactVec& b) {
  const ExactVec::Node *x = peel(a.node()), *y = peel(b.node());
  return factor_of(x, y) || factor_of(y, x);
}

}  // namespace

ExactVec ExactVec::from_point(const Point3& p) {
  auto n = new_node();
  n->op = Op::kLeaf;
  n->leaf = p;
  n->approx = {Approx(p.x), Approx(p.y), Approx(p.z)};
  return ExactVec(std::move(n));
}

ExactVec operator+(const ExactVec& a, const ExactVec& b) {
  auto n = new_node();
  n->op = Op::kAdd;
  n->a = a.node_ ? a.node_ : ExactVec::from_point({}).node_;
  n->b = b.node_ ? b.node_ : ExactVec::from_point({}).node_;
  for (int i = 0; i < 3; ++i) n->approx[i] = n->a->approx[i] + n->b->approx[i];
  return ExactVec(std::move(n));
}

ExactVec operator-(const ExactVec& a, const ExactVec& b) {
  auto n = new_node();
  n->op = Op::kSub;
  n->a = a.node_ ? a.node_ : ExactVec::from_point({}).node_;
  n->b = b.node_ ? b.node_ : ExactVec::from_point({}).node_;
  for (int i = 0; i < 3; ++i) n->approx[i] = n->a->approx[i] - n->b->approx[i];
  return ExactVec(std::move(n));
}

ExactVec operator-(const ExactVec& a) {
  auto n = new_node();
  n->op = Op::kNeg;
  n->a = a.node_ ? a.node_ : ExactVec::from_point({}).node_;
  for (int i = 0; i < 3; ++i) n->approx[i] = -n->a->approx[i];
  return ExactVec(std::move(n));
}

ExactVec cross(const ExactVec& a, const ExactVec& b) {
  auto n = new_node();
  n->op = Op::kCross;
  n->a = a.node_ ? a.node_ : ExactVec::from_point({}).node_;
  n->b = b.node_ ? b.node_ : ExactVec::from_point({}).node_;
  n->approx = cross3(n->a->approx, n->b->approx);
  return ExactVec(std::move(n));
}

std::array<double, 3> ExactVec::approx() const {
  const auto& a = node_of(*this).approx;
  return {a[0].value(), a[1].value(), a[2].value()};
}

std::array<double, 3> ExactVec::unit() const {
  // The exact coordinates scaled by one power of two so that the largest is in [0.5, 1):
  // no overflow or underflow whatever the magnitude (a degree-12 construction of large
  // coordinates exceeds the double range), then normalized.
  const auto& e = eval<Dyadic>(*this);
  int64_t exp[3];
  double f[3];
  for (int i = 0; i < 3; ++i) f[i] = e[i].frexp(exp[i]);
  int64_t top = INT64_MIN;
  for (int i = 0; i < 3; ++i) {
    if (f[i] != 0) top = std::max(top, exp[i]);
  }
  std::array<double, 3> d{};
  for (int i = 0; i < 3; ++i) {
    // Components 2^1100 times smaller than the largest become 0: below its rounding.
    const int64_t shift = std::max<int64_t>(exp[i] - top, -1100);
    d[i] = f[i] == 0 ? 0 : std::ldexp(f[i], static_cast<int>(shift));
  }
  const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return {d[0] / len, d[1] / len, d[2] / len};
}

namespace {

// Sign of v - (a + b) / 2 for v = sqrt(x2 / s) >= 0 and doubles 0 <= a < b: the sign of
// x2 - ((a + b) / 2)^2 s, all exact in dyadics.
Sign past_midpoint(const Dyadic& x2, const Dyadic& s, double a, double b) {
  const Dyadic mid = (Dyadic(a) + Dyadic(b)) * Dyadic(0.5);
  return (x2 - mid * mid * s).sign();
}

bool odd(double d) { return (std::bit_cast<uint64_t>(d) & 1) != 0; }

// The double nearest sqrt(x2 / s) (ties to even), from an estimate r a few units in the
// last place off: steps towards it while it lies past a midpoint.
double nearest_root(const Dyadic& x2, const Dyadic& s, double r) {
  for (;;) {
    const double up = next_up(r);
    const Sign past = past_midpoint(x2, s, r, up);
    if (past == Sign::kNegative || (past == Sign::kZero && !odd(r))) break;
    r = up;
  }
  while (r > 0) {
    const double down = next_down(r);  // r > 0
    const Sign past = past_midpoint(x2, s, down, r);
    if (past == Sign::kPositive || (past == Sign::kZero && !odd(r))) break;
    r = down;
  }
  return r;
}

}  // namespace

std::array<double, 3> ExactVec::nearest_unit() const {
  const auto& e = eval<Dyadic>(*this);
  const Dyadic s = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
  const std::array<double, 3> estimate = unit();
  std::array<double, 3> out{};
  for (int i = 0; i < 3; ++i) {
    const double r = nearest_root(e[i] * e[i], s, std::fabs(estimate[i]));
    out[i] = e[i].sign() == Sign::kNegative ? -r : r;
  }
  return out;
}

ExactVec point_difference(const Point3& q, const Point3& p) {
  auto n = std::allocate_shared<PointDifferenceNode>(CachedAllocator<PointDifferenceNode>{});
  n->op = Op::kPointDifference;
  n->leaf = q;
  n->p = p;
  n->approx = {Approx(q.x) - Approx(p.x), Approx(q.y) - Approx(p.y), Approx(q.z) - Approx(p.z)};
  return ExactVec(std::shared_ptr<const ExactVec::Node>(std::move(n)));
}

ExactVec triangle_normal(const Point3& a, const Point3& b, const Point3& c) {
  auto n = std::allocate_shared<TriangleNormalNode>(CachedAllocator<TriangleNormalNode>{});
  n->op = Op::kTriangleNormal;
  n->leaf = a;
  n->b = b;
  n->c = c;
  // The filtered value of the expression: exact points, then their differences.
  const V3<Approx> pa{Approx(a.x), Approx(a.y), Approx(a.z)};
  n->approx = cross3(V3<Approx>{Approx(b.x) - pa[0], Approx(b.y) - pa[1], Approx(b.z) - pa[2]},
                     V3<Approx>{Approx(c.x) - pa[0], Approx(c.y) - pa[1], Approx(c.z) - pa[2]});
  return ExactVec(std::shared_ptr<const ExactVec::Node>(std::move(n)));
}

Sign sign_dot(const ExactVec& a, const ExactVec& b) {
  if (orthogonal_by_construction(a, b)) return Sign::kZero;
  return filtered_sign([&](auto tag) {
    using T = decltype(tag);
    const auto &x = eval<T>(a), &y = eval<T>(b);
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
  });
}

Sign sign_det(const ExactVec& a, const ExactVec& b, const ExactVec& c) {
  if (same_node(a, b) || same_node(b, c) || same_node(a, c)) return Sign::kZero;
  return filtered_sign([&](auto tag) {
    using T = decltype(tag);
    const auto &x = eval<T>(a), &y = eval<T>(b), &z = eval<T>(c);
    auto w = cross3(y, z);
    return x[0] * w[0] + x[1] * w[1] + x[2] * w[2];
  });
}

Sign sign_sin2_angle_minus(const ExactVec& a, const ExactVec& b, double s2) {
  return filtered_sign([&](auto tag) {
    using T = decltype(tag);
    const auto &x = eval<T>(a), &y = eval<T>(b);
    auto w = cross3(x, y);
    T aa = x[0] * x[0] + x[1] * x[1] + x[2] * x[2], bb = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
    return (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) - T(s2) * aa * bb;
  });
}

Sign sign_cos2_angle_minus(const ExactVec& a, const ExactVec& b, double s2) {
  return filtered_sign([&](auto tag) {
    using T = decltype(tag);
    const auto &x = eval<T>(a), &y = eval<T>(b);
    T d = x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    T aa = x[0] * x[0] + x[1] * x[1] + x[2] * x[2], bb = y[0] * y[0] + y[1] * y[1] + y[2] * y[2];
    return d * d - T(s2) * aa * bb;
  });
}

Sign sign_of_coordinate(const ExactVec& a, int i) {
  return filtered_sign([&](auto tag) {
    using T = decltype(tag);
    return T(eval<T>(a)[i]);
  });
}

bool is_zero(const ExactVec& a) {
  const ExactVec::Node* n = peel(a.node());
  if (n && n->op == Op::kCross && peel(n->a.get()) == peel(n->b.get())) return true;
  const auto& v = node_of(a).approx;
  bool undecided = false;
  for (int i = 0; i < 3; ++i) {
    auto s = v[i].sign();
    if (s && *s != Sign::kZero) return false;
    undecided |= !s;
  }
  if (!undecided) return true;
  const auto& e = eval<Dyadic>(a);  // one exact evaluation for all three coordinates
  return e[0].is_zero() && e[1].is_zero() && e[2].is_zero();
}

bool parallel(const ExactVec& a, const ExactVec& b) { return is_zero(cross(a, b)); }

bool same_direction(const ExactVec& a, const ExactVec& b) {
  return parallel(a, b) && sign_dot(a, b) == Sign::kPositive;
}

namespace {
// The filtered estimate is used while its radius (about 2 err / len) is below 2^-30. Worse
// ones come from crossings of nearly tangent circles and normals of very short arcs, which
// CAD input makes by the hundred thousand (a planar face seen from occluders near its
// plane): boxes of radius 1e-3 around them made arrangements compare 10^8 pairs of
// vertices exactly (r103ec face 6: 114 M same_direction tests, 2,432 equal).
constexpr double kLooseEstimate = 0x1p31;
}  // namespace

UnitEstimate unit_estimate(const ExactVec& a) {
  // The filtered coordinates and their errors scaled by one power of two so that the
  // largest bound is in [1, 2): squares and sums then neither over- nor underflow in a way
  // that would void the radius (scaling is exact except where a value goes subnormal,
  // which the added 2^-1074 covers).
  const auto& v = node_of(a).approx;
  double top = 0;
  for (int i = 0; i < 3; ++i) top = std::max(top, std::fabs(v[i].value()) + v[i].error());
  if (!(top > 0) || !std::isfinite(top)) return {a.unit(), 0x1p-40};
  const int k = binary_exponent(top);
  double w[3], len2 = 0, err2 = 0;
  for (int i = 0; i < 3; ++i) {
    w[i] = scale_by_power_of_two(v[i].value(), -k);
    len2 += w[i] * w[i];
    const double f = scale_by_power_of_two(v[i].error(), -k) + 0x1p-1074;
    err2 += f * f + DBL_MIN;  // DBL_MIN: whatever the square lost to underflow
  }
  const double err = std::sqrt(err2) * (1 + 0x1p-40);
  const double len = std::sqrt(len2);
  if (!(len > kLooseEstimate * err)) {
    // The filter cannot locate the direction well enough: one exact evaluation (kept by
    // the node) is cheaper than the candidate pairs a loose box would bring in.
    return {a.unit(), 0x1p-40};
  }
  // |v/|v| - w/|w|| <= 2 |v - w| / |v| for the exact w within err of v; len is within a
  // few ulps of |v| (it is at least 1/2 here) and 2^-50 covers them.
  double radius = 2 * err / (len - err) + 0x1p-50;
  return {{w[0] / len, w[1] / len, w[2] / len}, radius};
}

std::optional<Sign> estimated_sign_dot(const UnitEstimate& ea, const UnitEstimate& eb) {
  const double d = ea.unit[0] * eb.unit[0] + ea.unit[1] * eb.unit[1] + ea.unit[2] * eb.unit[2];
  const double bound = (ea.radius + eb.radius + ea.radius * eb.radius + 0x1p-50) * (1 + 0x1p-40);
  if (d > bound) return Sign::kPositive;
  if (d < -bound) return Sign::kNegative;
  return std::nullopt;
}

Sign sign_dot(const ExactVec& a, const ExactVec& b, const UnitEstimate& ea, const UnitEstimate& eb) {
  if (const std::optional<Sign> s = estimated_sign_dot(ea, eb)) return *s;
  return sign_dot(a, b);
}

}  // namespace gvm::exact
