// The spans of pairs of triangles along an arc, in doubles, against the exact intervals
// of their pairwise maps; and the pairs they leave out, against the arc left uncovered.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "exact/predicates.h"
#include "sphere/arc_intervals.h"
#include "visibility/arc_spans.h"
#include "visibility/convex_decomposition.h"

namespace gvm {
namespace {

using exact::ExactVec;
using sphere::Arc;
using sphere::Interval;
using Kind = ArcSpans::Span::Kind;
using sphere::D3;

// Triangles of S at x in [-2, 0] and of O at x in [0, 2], on a small integer grid: many
// differences lie exactly in the plane z = 0 of the arcs below, some pairs share corners
// (at x = 0) or are coplanar, and many intervals share ends. Triangles 0-39 are S's.
SolidMesh grid_triangles(std::mt19937& rng, size_t count) {
  SolidMesh mesh;
  std::uniform_int_distribution<int> coordinate(-3, 3), side(0, 2);
  for (int i = 0; i < 60; ++i) {
    const int x = i < 30 ? -side(rng) : side(rng);
    mesh.points.push_back({double(x), double(coordinate(rng)), double(coordinate(rng)) / 2});
  }
  std::uniform_int_distribution<uint32_t> corner(0, 29);
  while (mesh.triangles.size() < count) {
    const uint32_t offset = mesh.triangles.size() < 40 ? 0 : 30;
    const Triangle t{offset + corner(rng), offset + corner(rng), offset + corner(rng)};
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    if (exact::collinear(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]])) continue;
    mesh.triangles.push_back(t);
  }
  return mesh;
}

// Arcs of z = 0 around +x from very short to nearly a half circle, one around -x (behind
// every pair), and one on a tilted circle.
std::vector<Arc> arcs() {
  std::vector<Arc> out;
  const ExactVec z = ExactVec::from_point({0, 0, 1});
  for (double half : {1e-6, 0.3, 0.785, 1.5, 1.5707}) {
    out.push_back({ExactVec::from_point({std::cos(half), -std::sin(half), 0}),
                   ExactVec::from_point({std::cos(half), std::sin(half), 0}), z});
  }
  out.push_back({ExactVec::from_point({-1, 0.3, 0}), ExactVec::from_point({-1, -0.3, 0}), z});
  const ExactVec a = ExactVec::from_point({1, 1, 1}), b = ExactVec::from_point({1, -2, 0.5});
  out.push_back({a, b, exact::cross(a, b)});
  return out;
}

// The exact open interval of the open arc inside the pair's map, if any.
std::optional<Interval> exact_interval(const SolidMesh& mesh, const Arc& arc, uint32_t fs, uint32_t ft,
                                       bool& whole) {
  std::vector<ExactVec> d;
  for (uint32_t q : mesh.triangles[ft]) {
    for (uint32_t p : mesh.triangles[fs]) {
      if (q != p) d.push_back(ExactVec::from_point(mesh.points[q]) - ExactVec::from_point(mesh.points[p]));
    }
  }
  whole = false;
  const sphere::SphericalImage map = pairwise_occlusion_map(d);
  if (map.dimension() < 2) return std::nullopt;
  std::vector<ExactVec> normals;
  if (!map.is_full_sphere()) {
    for (const Arc& side : map.faces()[0].loops[0].arcs) normals.push_back(side.normal);
  }
  Interval interval;
  if (!sphere::clip(arc, normals, interval, &whole)) return std::nullopt;
  return interval;
}

TEST(ArcSpans, SpansBoundTheExactIntervals) {
  std::mt19937 rng(5);
  const SolidMesh mesh = grid_triangles(rng, 120);
  int crosses = 0, misses = 0, unknown = 0;
  for (const Arc& arc : arcs()) {
    const ArcSpans frame(arc);
    ASSERT_TRUE(frame.usable());
    const double start = frame.start(), end = frame.end(), e_end = ArcSpans::kEndError;
    for (uint32_t fs = 0; fs < 40; ++fs) {
      for (uint32_t ft = 40; ft < mesh.triangles.size(); ++ft) {
        const ArcSpans::Span span = frame.of_pair(mesh, fs, ft);
        bool whole = false;
        const std::optional<Interval> exact = exact_interval(mesh, arc, fs, ft, whole);
        const std::string where = "pair " + std::to_string(fs) + ", " + std::to_string(ft);
        if (span.kind == Kind::kUnknown) {
          ++unknown;
          continue;
        }
        if (span.kind == Kind::kMisses) {
          ++misses;
          ASSERT_FALSE(exact) << where;
          continue;
        }
        ++crosses;
        ASSERT_LT(span.lo, span.hi) << where;
        // The inside of the span, away from the arc's ends, is inside the exact interval.
        const double in_lo = std::max(span.lo + span.error, start + e_end);
        const double in_hi = std::min(span.hi - span.error, end - e_end);
        if (in_lo < in_hi) {
          ASSERT_TRUE(exact) << where;
          ASSERT_LE(frame.angle(exact->lo.unit()), in_lo + 1e-14) << where;
          ASSERT_GE(frame.angle(exact->hi.unit()), in_hi - 1e-14) << where;
        }
        // The exact interval is inside the span widened by its error.
        if (exact) {
          ASSERT_GE(frame.angle(exact->lo.unit()), std::max(span.lo - span.error, start - e_end) - 1e-14) << where;
          ASSERT_LE(frame.angle(exact->hi.unit()), std::min(span.hi + span.error, end + e_end) + 1e-14) << where;
        }
      }
    }
  }
  // The doubles decide most pairs (all of them were undecided once, near half circles).
  EXPECT_GT(crosses, 10 * unknown) << crosses << " crossing, " << misses << " missing, " << unknown << " undecided";
  EXPECT_GT(misses, 0);
}

// The arc left uncovered by the exact intervals of the kept pairs is the one left by all:
// pieces and points between touching intervals alike.
TEST(ArcSpans, KeptPairsLeaveTheArcUncoveredAsAllDo) {
  std::mt19937 rng(9);
  const SolidMesh mesh = grid_triangles(rng, 200);
  size_t pairs = 0, kept = 0;
  for (const Arc& arc : arcs()) {
    const ArcSpans frame(arc);
    for (int trial = 0; trial < 30; ++trial) {
      std::vector<std::pair<uint32_t, uint32_t>> chosen;
      std::vector<ArcSpans::Span> spans;
      for (int i = 0; i < 60; ++i) {
        const uint32_t fs = rng() % 40, ft = 40 + rng() % 160;  // S x O
        const ArcSpans::Span span = frame.of_pair(mesh, fs, ft);
        if (span.kind == Kind::kMisses) continue;
        chosen.emplace_back(fs, ft);
        spans.push_back(span);
      }
      auto intervals = [&](const std::vector<uint32_t>& which) {
        std::vector<Interval> out;
        for (uint32_t k : which) {
          bool whole = false;
          if (auto i = exact_interval(mesh, arc, chosen[k].first, chosen[k].second, whole)) out.push_back(*i);
        }
        return out;
      };
      std::vector<uint32_t> all(chosen.size());
      for (uint32_t k = 0; k < all.size(); ++k) all[k] = k;
      const std::vector<uint32_t> matter = spans_that_matter(frame, spans);
      pairs += all.size();
      kept += matter.size();
      const std::vector<Arc> expected = sphere::complement(arc, intervals(all));
      const std::vector<Arc> found = sphere::complement(arc, intervals(matter));
      ASSERT_EQ(found.size(), expected.size()) << "trial " << trial;
      for (size_t k = 0; k < found.size(); ++k) {
        ASSERT_TRUE(exact::same_direction(found[k].start, expected[k].start)) << "trial " << trial << " piece " << k;
        ASSERT_TRUE(exact::same_direction(found[k].end, expected[k].end)) << "trial " << trial << " piece " << k;
      }
    }
  }
  EXPECT_LT(kept * 2, pairs) << kept << " of " << pairs << " pairs kept";
}

// Spans whose shrunk insides touch leave the point between them uncovered: a narrower span
// over that point is kept, and one inside either of them is not.
TEST(ArcSpans, TouchingSpansDoNotHoldWhatLiesBetweenThem) {
  const Arc arc{ExactVec::from_point({1, -1, 0}), ExactVec::from_point({1, 1, 0}), ExactVec::from_point({0, 0, 1})};
  const ArcSpans frame(arc);
  const double e = 1e-9;
  const std::vector<ArcSpans::Span> spans = {
      {Kind::kCrosses, -0.7, 0, e},        // 0: widest, ends where 1 starts
      {Kind::kCrosses, 0, 0.69, e},        // 1
      {Kind::kCrosses, -0.3, 0.3, e},      // 2: over the point between them: kept
      {Kind::kCrosses, 0.1, 0.5, e},       // 3: inside 1: left out
      {Kind::kCrosses, -0.6, -1e-3, e},    // 4: inside 0: left out
      {Kind::kCrosses, 0.9, 1.2, e},       // 5: beyond the arc's end (pi / 4): left out
      {Kind::kUnknown, 0, 0, 0},           // 6: always kept
  };
  std::vector<uint32_t> kept = spans_that_matter(frame, spans);
  std::sort(kept.begin(), kept.end());
  EXPECT_EQ(kept, (std::vector<uint32_t>{0, 1, 2, 6}));
  // A span ending within the error of a wider one's end may reach beyond it: kept.
  const std::vector<ArcSpans::Span> close = {{Kind::kCrosses, -0.7, 0, e}, {Kind::kCrosses, -0.2, -e / 2, 0}};
  EXPECT_EQ(spans_that_matter(frame, close), (std::vector<uint32_t>{0, 1}));
}

// Directions along arcs with exact ties (one direction scaled), near ties 1e-10, 1e-15 and 1e-25 rad apart,
// directions on the ends (scaled too) and beyond them: the same list as the exact sort gives.
TEST(ArcSpans, DirectionsInOrderAlongAnArcAsTheExactSortGivesThem) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-1.7, 1.7);
  for (const Arc& arc : arcs()) {
    const sphere::ArcOrder order{arc.normal};
    const exact::UnitEstimate a = exact::unit_estimate(arc.start), b = exact::unit_estimate(arc.end);
    const exact::UnitEstimate n = exact::unit_estimate(arc.normal);
    const D3 e1 = sphere::normalized(sphere::add(a.unit, b.unit)), e2 = sphere::cross(n.unit, e1);
    std::vector<ExactVec> directions = {arc.start, arc.end, arc.start + arc.start, arc.end + arc.end};
    for (int i = 0; i < 300; ++i) {
      const double t = angle(rng);
      const D3 d = sphere::add(sphere::add(D3{}, e1, std::cos(t)), e2, std::sin(t));
      const ExactVec x = ExactVec::from_point({d[0], d[1], d[2]});
      // 1e-25 rad beyond x along the arc, listed first: no estimate tells them apart.
      if (i % 4 == 0) directions.push_back(x + ExactVec::from_point({1e-25 * e2[0], 1e-25 * e2[1], 1e-25 * e2[2]}));
      directions.push_back(x);
      if (i % 3 == 0) directions.push_back(x + x);  // the same direction, another node
      if (i % 6 == 0) directions.push_back(x + x + x);
      for (double step : {1e-10, 3e-15, -2e-15}) {  // near ties, the last ones within the estimates' error
        if (i % 5 != 0) continue;
        const D3 near = sphere::add(sphere::add(D3{}, e1, std::cos(t + step)), e2, std::sin(t + step));
        directions.push_back(ExactVec::from_point({near[0], near[1], near[2]}));
      }
    }
    std::vector<ExactVec> expected;
    for (const ExactVec& d : directions) {
      if (order.before(arc.start, d) && order.before(d, arc.end)) expected.push_back(d);
    }
    std::sort(expected.begin(), expected.end(), [&](const ExactVec& x, const ExactVec& y) { return order.before(x, y); });
    expected.erase(std::unique(expected.begin(), expected.end(), exact::same_direction), expected.end());
    const std::vector<std::vector<uint32_t>> found = in_order_along(arc, directions);
    ASSERT_EQ(found.size(), expected.size());
    std::vector<int> listed(directions.size(), 0);
    for (size_t k = 0; k < found.size(); ++k) {
      for (uint32_t i : found[k]) {
        ASSERT_TRUE(exact::same_direction(directions[i], expected[k])) << k;
        ++listed[i];
      }
    }
    // Every direction inside the open arc is in exactly one group.
    for (size_t i = 0; i < directions.size(); ++i) {
      const bool inside = order.before(arc.start, directions[i]) && order.before(directions[i], arc.end);
      EXPECT_EQ(listed[i], inside ? 1 : 0) << i;
    }
  }
}

}  // namespace
}  // namespace gvm
