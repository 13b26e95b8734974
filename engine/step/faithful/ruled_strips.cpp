// Cells between neighbouring rulings, and their ladders (ruled_strips.h). The comparisons
// of v here only order boundary points of one face along one ruling; the relations that
// matter (two corners of every triangle on one ruling) hold by construction.
#include "step/faithful/ruled_strips.h"

#include <algorithm>
#include <set>

namespace gvm::faithful {
namespace {

struct Segment {
  const StripPoint* from;
  const StripPoint* to;
  double mid;
  bool bottom;  // runs towards larger u: the face lies above it
};

// The boundary points on ruling k with v in [lo, hi], by v.
std::vector<const StripPoint*> on_ruling(const std::vector<std::vector<const StripPoint*>>& by_ruling,
                                         uint32_t k, double lo, double hi) {
  std::vector<const StripPoint*> out;
  for (const StripPoint* p : by_ruling[k])
    if (p->v >= lo && p->v <= hi) out.push_back(p);
  return out;
}

// Triangles between the left and right chains of a cell, each with two corners on one
// side. A point on every ruling (a cone's apex) must not take two corners of one side with
// it, which would put three corners on one line: while one side stands on it, the other
// side advances; a triangle that only joins the apex to itself collapses and is dropped
// later.
bool ladder(const std::vector<const StripPoint*>& left, const std::vector<const StripPoint*>& right,
            const std::set<uint32_t>& apex, std::vector<std::array<uint32_t, 3>>& out) {
  size_t i = 0, j = 0;
  auto on_apex = [&](const StripPoint* p) { return apex.count(p->id) > 0; };
  while (i + 1 < left.size() || j + 1 < right.size()) {
    const bool can_right =
        j + 1 < right.size() && (!on_apex(left[i]) || right[j + 1]->id == left[i]->id);
    const bool can_left = i + 1 < left.size() && (!on_apex(right[j]) || left[i + 1]->id == right[j]->id);
    if (!can_right && !can_left) {
      if (i + 1 == left.size() || j + 1 == right.size()) return false;
      out.push_back({left[i]->id, right[j + 1]->id, left[i + 1]->id});  // both sides on the apex
      ++i, ++j;
      continue;
    }
    const bool advance_right = can_right && (!can_left || right[j + 1]->v <= left[i + 1]->v);
    if (advance_right) {
      out.push_back({left[i]->id, right[j]->id, right[j + 1]->id});
      ++j;
    } else {
      out.push_back({left[i]->id, right[j]->id, left[i + 1]->id});
      ++i;
    }
  }
  return true;
}

}  // namespace

bool ruled_strips(const std::vector<std::vector<StripPoint>>& loops, uint32_t rulings,
                  std::vector<std::array<uint32_t, 3>>& out, std::string& why) {
  std::vector<std::vector<const StripPoint*>> by_ruling(rulings);
  std::vector<std::vector<Segment>> spanning(rulings > 0 ? rulings - 1 : 0);
  for (const auto& loop : loops) {
    for (size_t k = 0; k < loop.size(); ++k) {
      const StripPoint& a = loop[k];
      const StripPoint& b = loop[(k + 1) % loop.size()];
      if (a.ruling >= rulings || b.ruling >= rulings) {
        why = "a boundary point is on no ruling";
        return false;
      }
      auto& here = by_ruling[a.ruling];
      if (std::none_of(here.begin(), here.end(), [&](const StripPoint* p) { return p->id == a.id; }))
        here.push_back(&a);
      if (a.ruling == b.ruling) continue;  // along a ruling
      const uint32_t lo = std::min(a.ruling, b.ruling);
      if (std::max(a.ruling, b.ruling) != lo + 1) {
        why = "a boundary segment skips a ruling";
        return false;
      }
      spanning[lo].push_back({&a, &b, 0.5 * (a.v + b.v), b.ruling > a.ruling});
    }
  }
  for (auto& points : by_ruling)
    std::sort(points.begin(), points.end(), [](const StripPoint* a, const StripPoint* b) { return a->v < b->v; });
  // Points on two neighbouring rulings are on all of them: an apex.
  std::set<uint32_t> apex;
  for (uint32_t k = 0; k + 1 < rulings; ++k)
    for (const StripPoint* p : by_ruling[k])
      if (std::any_of(by_ruling[k + 1].begin(), by_ruling[k + 1].end(), [&](const StripPoint* q) { return q->id == p->id; }))
        apex.insert(p->id);
  for (uint32_t k = 0; k + 1 < rulings; ++k) {
    std::vector<Segment>& segs = spanning[k];
    std::sort(segs.begin(), segs.end(), [](const Segment& a, const Segment& b) { return a.mid < b.mid; });
    if (segs.size() % 2 != 0) {
      why = "between two rulings the boundary crosses an odd number of times";
      return false;
    }
    for (size_t s = 0; s < segs.size(); s += 2) {
      const Segment& bottom = segs[s];
      const Segment& top = segs[s + 1];
      if (!bottom.bottom || top.bottom) {
        why = "between two rulings the boundary is not oriented with the face on its left";
        return false;
      }
      if (!ladder(on_ruling(by_ruling, k, bottom.from->v, top.to->v),
                  on_ruling(by_ruling, k + 1, bottom.to->v, top.from->v), apex, out)) {
        why = "a cell between two rulings has an apex on both sides and nothing between";
        return false;
      }
    }
  }
  return true;
}

}  // namespace gvm::faithful
