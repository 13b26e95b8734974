#include "sphere/arc_intervals.h"

#include <algorithm>

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

std::vector<Arc> complement(const Arc& arc, std::vector<Interval> covered) {
  const ArcOrder order{arc.normal};
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
