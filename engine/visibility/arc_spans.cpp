#include "visibility/arc_spans.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>

#include "exact/exact_vec.h"
#include "exact/predicates.h"
#include "sphere/arc_intervals.h"

namespace gvm {
namespace {

using exact::ExactVec;
using sphere::D3;
using Kind = ArcSpans::Span::Kind;

constexpr double kEps = 0x1p-52;
// The frame's estimates (unit vectors within 1e-12) move an angle by a few times that.
constexpr double kFrameError = 1e-11;
// A span whose ends are less certain than this is left to the exact map.
constexpr double kLargestError = 1e-7;
// Angles this far from +-pi are read without wrapping; spans wider than pi minus this are
// not pointed for certain.
constexpr double kWrapMargin = 0.1;

struct Difference {
  D3 d;
  double length, along_normal, error;  // d . n and its error bound
  Sign side;
};

}  // namespace

ArcSpans::ArcSpans(const sphere::Arc& arc) : arc_(arc) {
  const exact::UnitEstimate a = exact::unit_estimate(arc.start), b = exact::unit_estimate(arc.end),
                            n = exact::unit_estimate(arc.normal);
  if (arc.full || !(a.radius < 1e-12 && b.radius < 1e-12 && n.radius < 1e-12)) return;
  // The middle of the arc, from whichever sum is longer: a + b is short for arcs near a
  // half circle, n x a - n x b (the ends turned towards each other) for short ones.
  const D3 sum = sphere::add(a.unit, b.unit);
  const D3 turned = sphere::add(sphere::cross(n.unit, a.unit), sphere::cross(n.unit, b.unit), -1);
  const D3 middle = sphere::norm(sum) > sphere::norm(turned) ? sum : turned;
  n_ = n.unit;
  normal_error_ = n.radius;
  e1_ = sphere::normalized(middle);
  e2_ = sphere::cross(n_, e1_);
  start_ = angle(a.unit);
  end_ = angle(b.unit);
  usable_ = start_ < end_ - 4 * kEndError;
}

double ArcSpans::angle(const D3& x) const { return std::atan2(sphere::dot(x, e2_), sphere::dot(x, e1_)); }

ArcSpans::Span ArcSpans::of_pair(const SolidMesh& mesh, uint32_t fs, uint32_t ft) const {
  if (!usable_) return {};
  const auto& P = mesh.points;
  const Triangle &s = mesh.triangles[fs], &t = mesh.triangles[ft];
  // Coplanar triangles have a map without inside (their differences span a plane).
  if (std::all_of(t.begin(), t.end(), [&](uint32_t q) { return exact::orient3d(P[s[0]], P[s[1]], P[s[2]], P[q]) == Sign::kZero; })) {
    return {Kind::kMisses};
  }
  std::array<Difference, 9> diff;
  size_t count = 0;
  bool above = false, below = false;
  for (uint32_t q : t) {
    for (uint32_t p : s) {
      if (q == p) continue;
      Difference& x = diff[count++];
      x.d = {P[q].x - P[p].x, P[q].y - P[p].y, P[q].z - P[p].z};
      x.length = sphere::norm(x.d);
      x.along_normal = sphere::dot(x.d, n_);
      // Rounding of d and of the product, and the normal's estimate.
      x.error = x.length * (16 * kEps + normal_error_);
      if (x.along_normal > x.error) {
        x.side = Sign::kPositive;
      } else if (x.along_normal < -x.error) {
        x.side = Sign::kNegative;
      } else {
        x.side = exact::sign_dot(exact::point_difference(P[q], P[p]), arc_.normal);
      }
      above |= x.side == Sign::kPositive;
      below |= x.side == Sign::kNegative;
    }
  }
  // All differences in one closed side of H: the map's inside misses H.
  if (!above || !below) return {Kind::kMisses};

  // The points spanning the cone over P n H, with the error of each one's angle.
  double lo = INFINITY, hi = -INFINITY, error = 0;
  bool behind = true;  // every point certainly more than a right angle from the middle
  auto add_point = [&](const D3& x, double x_error) {
    const double length = sphere::norm(x);
    const double e = (length > 0 ? x_error / length : INFINITY) + kFrameError;
    const double a = angle(x);
    lo = std::min(lo, a);
    hi = std::max(hi, a);
    error = std::max(error, e);
    behind = behind && std::fabs(a) > M_PI / 2 + e + kEndError;
  };
  for (size_t i = 0; i < count; ++i) {
    const Difference& x = diff[i];
    if (x.side == Sign::kZero) add_point(x.d, 4 * kEps * x.length);
    if (x.side != Sign::kPositive) continue;
    for (size_t j = 0; j < count; ++j) {
      const Difference& y = diff[j];
      if (y.side != Sign::kNegative) continue;
      // -(y . n) x + (x . n) y: on the segment's ray, in H; its error from the products'.
      const D3 c = sphere::add(sphere::add(D3{}, x.d, -y.along_normal), y.d, x.along_normal);
      add_point(c, 2 * (x.length * y.error + y.length * x.error) + 16 * kEps * x.length * y.length);
    }
  }
  if (behind) return {Kind::kMisses};  // a pointed cone in the half-plane behind the arc
  if (!(error < kLargestError) || lo < -M_PI + kWrapMargin || hi > M_PI - kWrapMargin ||
      hi - lo > M_PI - kWrapMargin) {
    return {};
  }
  return {Kind::kCrosses, lo, hi, error};
}

std::vector<uint32_t> spans_that_matter(const ArcSpans& arc, const std::vector<ArcSpans::Span>& spans) {
  // The exact open arc lies within (a, b).
  const double a = arc.start() - ArcSpans::kEndError, b = arc.end() + ArcSpans::kEndError;
  std::vector<uint32_t> out, crossing;
  for (uint32_t i = 0; i < spans.size(); ++i) {
    const ArcSpans::Span& s = spans[i];
    if (s.kind == Kind::kUnknown) out.push_back(i);
    if (s.kind == Kind::kCrosses && s.hi + s.error > a && s.lo - s.error < b) crossing.push_back(i);
  }
  auto width = [&](uint32_t i) { return std::min(spans[i].hi, b) - std::max(spans[i].lo, a); };
  std::stable_sort(crossing.begin(), crossing.end(), [&](uint32_t i, uint32_t j) { return width(i) > width(j); });
  // The union of the kept spans shrunk by their errors: disjoint open spans, lo -> hi.
  // Touching spans stay apart: the point between them is covered by neither.
  std::map<double, double> covered;
  auto holds = [&](double lo, double hi) {
    auto it = covered.upper_bound(lo);
    if (it == covered.begin()) return false;
    --it;
    return it->first < lo && hi < it->second;
  };
  auto cover = [&](double lo, double hi) {
    if (!(lo < hi)) return;
    auto it = covered.upper_bound(lo);
    if (it != covered.begin() && std::prev(it)->second > lo) --it;
    while (it != covered.end() && it->first < hi) {
      lo = std::min(lo, it->first);
      hi = std::max(hi, it->second);
      it = covered.erase(it);
    }
    covered.emplace(lo, hi);
  };
  for (uint32_t i : crossing) {
    const ArcSpans::Span& s = spans[i];
    if (holds(std::max(s.lo - s.error, a), std::min(s.hi + s.error, b))) continue;
    out.push_back(i);
    cover(s.lo + s.error, s.hi - s.error);
  }
  return out;
}

std::vector<std::vector<uint32_t>> in_order_along(const sphere::Arc& open_arc,
                                                  const std::vector<ExactVec>& directions) {
  constexpr double kTie = 1e-8;  // far above the angles' errors (ArcSpans::kEndError and less)
  const sphere::ArcOrder order{open_arc.normal};
  auto before = [&](uint32_t x, uint32_t y) { return order.before(directions[x], directions[y]); };
  auto inside = [&](uint32_t i) {
    return order.before(open_arc.start, directions[i]) && order.before(directions[i], open_arc.end);
  };
  // Equal directions are neighbours once sorted: one group each.
  auto grouped = [&](const std::vector<uint32_t>& sorted) {
    std::vector<std::vector<uint32_t>> out;
    for (uint32_t i : sorted) {
      if (out.empty() || !exact::same_direction(directions[out.back()[0]], directions[i])) out.emplace_back();
      out.back().push_back(i);
    }
    return out;
  };
  auto all_exact = [&] {
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < directions.size(); ++i) {
      if (inside(i)) out.push_back(i);
    }
    std::sort(out.begin(), out.end(), before);
    return grouped(out);
  };
  const ArcSpans frame(open_arc);
  if (!frame.usable()) return all_exact();
  std::vector<std::pair<double, uint32_t>> keyed;
  for (uint32_t i = 0; i < directions.size(); ++i) {
    const exact::UnitEstimate u = exact::unit_estimate(directions[i]);
    if (!(u.radius <= 1e-12)) return all_exact();
    const double a = frame.angle(u.unit);
    if (a < frame.start() - kTie || a > frame.end() + kTie) continue;
    if ((a < frame.start() + kTie || a > frame.end() - kTie) && !inside(i)) continue;
    keyed.emplace_back(a, i);
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<uint32_t> out;
  for (const auto& [a, i] : keyed) out.push_back(i);
  // Runs of angles less than kTie apart hold every pair the angles may misorder.
  for (size_t b = 0; b < keyed.size();) {
    size_t e = b + 1;
    while (e < keyed.size() && keyed[e].first - keyed[e - 1].first < kTie) ++e;
    if (e - b > 1) std::sort(out.begin() + b, out.begin() + e, before);
    b = e;
  }
  return grouped(out);
}

}  // namespace gvm
