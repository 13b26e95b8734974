#include "sphere/arc_intervals.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace gvm::sphere {

using exact::ExactVec;

bool clip(const Arc& arc, std::span<const ExactVec> normals, Interval& out, bool* whole) {
  const ArcOrder order{arc.normal};
  out = {arc.start, arc.end};
  *whole = true;
  for (const ExactVec& m : normals) {
    const Sign sa = exact::sign_dot(arc.start, m), sb = exact::sign_dot(arc.end, m);
    // x . m is a sinusoid along the circle with zeros 180 degrees apart: on an arc
    // shorter than that it changes sign at most once.
    if (sa != Sign::kNegative && sb != Sign::kNegative && (sa != Sign::kZero || sb != Sign::kZero)) {
      continue;  // positive on the whole open arc
    }
    if (sa == Sign::kZero || sb == Sign::kZero || sa == sb) return *whole = false;
    ExactVec c = exact::cross(arc.normal, m);
    if (!order.before(arc.start, c)) c = -c;
    *whole = false;
    if (sa == Sign::kPositive) {
      if (order.before(c, out.hi)) out.hi = c;
    } else if (order.before(out.lo, c)) {
      out.lo = c;
    }
    if (!order.before(out.lo, out.hi)) return false;
  }
  return true;
}

namespace {

// The intervals without those certainly inside another one, which leaves their union as it
// was. The occlusion probe clips an arc to thousands of pairwise maps, nested in one
// another and sharing circles: sorting them all exactly evaluated their tied ends (TR12J
// F188: a seventh of the surface's time). Angles along the arc from unit estimates (within
// 2^-30 of the directions) decide containment with a margin of 2^-20; an interval whose
// start the angles cannot tell from the start of the interval holding it is compared there
// exactly, once.
std::vector<Interval> outermost(const Arc& arc, std::vector<Interval> covered) {
  if (covered.size() < 2) return covered;
  constexpr double kMargin = 0x1p-20;
  // Angles from the arc's middle, which keeps them within a right angle of 0 (the arc is
  // shorter than 180 degrees), far from where atan2 wraps.
  const auto a = exact::unit_estimate(arc.start).unit, b = exact::unit_estimate(arc.end).unit;
  const auto n = exact::unit_estimate(arc.normal).unit;
  std::array<double, 3> e1 = {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
  const double len = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  if (!(len > 0x1p-20)) return covered;
  for (double& x : e1) x /= len;
  const std::array<double, 3> e2 = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2],
                                    n[0] * e1[1] - n[1] * e1[0]};
  auto angle = [&](const ExactVec& x) {
    const auto u = exact::unit_estimate(x).unit;
    return std::atan2(u[0] * e2[0] + u[1] * e2[1] + u[2] * e2[2], u[0] * e1[0] + u[1] * e1[1] + u[2] * e1[2]);
  };
  struct Span {
    double lo, hi;
    uint32_t index;
  };
  std::vector<Span> spans(covered.size());
  for (uint32_t i = 0; i < covered.size(); ++i) spans[i] = {angle(covered[i].lo), angle(covered[i].hi), i};
  std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.lo < b.lo; });
  const ArcOrder order{arc.normal};
  std::vector<Interval> kept;
  const Span* widest = nullptr;  // of the kept intervals, the one reaching farthest
  for (const Span& s : spans) {
    const Interval& c = covered[s.index];
    if (widest && s.hi < widest->hi - kMargin) {
      const Interval& w = covered[widest->index];
      if (s.lo > widest->lo + kMargin || !order.before(c.lo, w.lo)) continue;
    }
    kept.push_back(c);
    if (!widest || s.hi > widest->hi) widest = &s;
  }
  return kept;
}

}  // namespace

std::vector<Arc> complement(const Arc& arc, std::vector<Interval> covered) {
  const ArcOrder order{arc.normal};
  covered = outermost(arc, std::move(covered));
  std::sort(covered.begin(), covered.end(),
            [&](const Interval& x, const Interval& y) { return order.before(x.lo, y.lo); });
  std::vector<Arc> pieces;
  ExactVec frontier = arc.start;  // everything before it is decided
  bool at_start = true;           // the frontier is the arc's own (excluded) start
  for (const Interval& c : covered) {
    if (order.before(frontier, c.lo)) {
      pieces.push_back({frontier, c.lo, arc.normal});
    } else if (!at_start && !order.before(c.lo, frontier)) {
      pieces.push_back({frontier, frontier, arc.normal});
    }
    if (order.before(frontier, c.hi)) {
      frontier = c.hi;
      at_start = false;
    }
  }
  if (order.before(frontier, arc.end)) pieces.push_back({frontier, arc.end, arc.normal});
  return pieces;
}

}  // namespace gvm::sphere
