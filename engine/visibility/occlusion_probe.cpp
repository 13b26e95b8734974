#include "visibility/occlusion_probe.h"

#include <tbb/concurrent_vector.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <optional>
#include <span>
#include <tuple>

#include <spdlog/spdlog.h>

#include "parallel/interrupt.h"
#include "sphere/arc_intervals.h"
#include "sphere/d3.h"
#include "sphere/point_in_face.h"
#include "sphere/spherical_image.h"
#include "visibility/arc_spans.h"
#include "visibility/convex_decomposition.h"
#include "visibility/direction_window.h"
#include "visibility/strip_events.h"

namespace gvm {
namespace {

using exact::ExactVec;
using sphere::ArcOrder;
using sphere::clip;
using sphere::complement;
using sphere::Interval;
using Corners = std::array<ExactVec, 3>;

Corners corners(const SolidMesh& mesh, uint32_t t) {
  const Triangle& tri = mesh.triangles[t];
  return {ExactVec::from_point(mesh.points[tri[0]]), ExactVec::from_point(mesh.points[tri[1]]),
          ExactVec::from_point(mesh.points[tri[2]])};
}

// Whether the points t (corners of T, or of one of its edges) and the sweep F_S + R>=0 u
// are weakly separated along w or -w for some w of `axes`: along w when w . u >= 0 (else
// the sweep is unbounded below along w) and w . (t - p) <= 0 for every t and every corner
// p of F_S. Weak separation along the facet normals of their Minkowski difference decides
// that the relative interiors are disjoint (separating axis theorem); `strictly` asks for
// w . (t - p) < 0, which decides that t misses the closed sweep. Both signs of an axis
// from one set of signs: negated axes were a third of the nodes of may_block.
bool separated(std::span<const ExactVec> axes, std::span<const ExactVec> t, const Corners& p,
               const ExactVec& u, bool strictly = false) {
  std::vector<ExactVec> differences;
  for (const ExactVec& x : t) {
    for (const ExactVec& y : p) differences.push_back(x - y);
  }
  for (const ExactVec& w : axes) {
    if (exact::is_zero(w)) continue;
    const Sign along_u = exact::sign_dot(w, u);
    bool plus = along_u != Sign::kNegative, minus = along_u != Sign::kPositive;
    for (size_t k = 0; k < differences.size() && (plus || minus); ++k) {
      const Sign s = exact::sign_dot(w, differences[k]);
      plus = plus && s != Sign::kPositive && !(strictly && s == Sign::kZero);
      minus = minus && s != Sign::kNegative && !(strictly && s == Sign::kZero);
    }
    if (plus || minus) return true;
  }
  return false;
}

// Rays from F_S along a direction u in its plane sweep the strip F_S + R>=0 u. A triangle
// entirely behind F_S along u, or entirely beside the strip, is not met by it, nor are its
// edges and corners, so may_block is false for it. Decided in doubles with the estimates'
// radii and the rounding covered: it only leaves out pairs the exact test would clear, and
// along a long arc most pairs are such (trj10's face 89: 56,877 pairs at each of up to
// 37,389 stretches between events, each with thirty exact cross products).
class StripFilter {
 public:
  StripFilter(const SolidMesh& mesh, const ExactVec& u, double coordinate_bound)
      : mesh_(mesh), u_(exact::unit_estimate(u)), bound_(coordinate_bound) {}

  bool may_meet(uint32_t fs, uint32_t ft, const exact::UnitEstimate& plane_normal) const {
    // w: the in-plane normal of the strip's sides (n x u is a unit vector: u lies in the plane).
    const sphere::D3 w = sphere::cross(plane_normal.unit, u_.unit);
    // |x| <= 2 bound; each estimate is off by its radius, each product by a few ulps.
    const double du = 2 * bound_ * (u_.radius + 1e-12);
    const double dw = 2 * bound_ * (u_.radius + plane_normal.radius + 1e-12);
    const Range su = range(fs, u_.unit), tu = range(ft, u_.unit);
    if (tu.hi < su.lo - 2 * du) return false;  // behind F_S
    const Range sw = range(fs, w), tw = range(ft, w);
    return !(tw.hi < sw.lo - 2 * dw || tw.lo > sw.hi + 2 * dw);  // else beside the strip
  }

 private:
  struct Range {
    double lo, hi;
  };
  Range range(uint32_t t, const sphere::D3& axis) const {
    Range r{INFINITY, -INFINITY};
    for (uint32_t v : mesh_.triangles[t]) {
      const Point3& p = mesh_.points[v];
      const double x = sphere::dot(axis, {p.x, p.y, p.z});
      r.lo = std::min(r.lo, x);
      r.hi = std::max(r.hi, x);
    }
    return r;
  }

  const SolidMesh& mesh_;
  exact::UnitEstimate u_;
  double bound_;
};

}  // namespace

bool OcclusionProbe::may_block(uint32_t fs, uint32_t ft, const ExactVec& u) const {
  const Corners s = corners(mesh_, fs), t = corners(mesh_, ft);
  const ExactVec n_s = exact::cross(s[1] - s[0], s[2] - s[0]);
  const ExactVec n_t = exact::cross(t[1] - t[0], t[2] - t[0]);
  const std::array<ExactVec, 3> s_edges{s[1] - s[0], s[2] - s[1], s[0] - s[2]};
  const std::array<ExactVec, 3> t_edges{t[1] - t[0], t[2] - t[1], t[0] - t[2]};
  const Sign facing = exact::sign_dot(u, n_s);
  if (facing == Sign::kNegative) return true;  // not a direction of the LVM: no claim
  // In the plane of F_S, only a face met from the front lets rays in (below).
  if (facing == Sign::kZero && exact::sign_dot(u, n_t) != Sign::kNegative) return false;

  // The facets of T - (F_S + R>=0 u): the two normals and the cross products of edges
  // (each for both its signs, as separated takes them).
  std::vector<ExactVec> axes{n_s, n_t};
  for (const ExactVec& e : s_edges) axes.push_back(exact::cross(e, u));
  for (const ExactVec& e : t_edges) {
    axes.push_back(exact::cross(e, u));
    for (const ExactVec& f : s_edges) axes.push_back(exact::cross(e, f));
  }
  if (facing == Sign::kPositive) {
    // The rays from F_S sweep an open prism that starts outside the solid: they meet
    // its interior iff the prism meets a triangle of the boundary.
    return !separated(axes, t, s, u);
  }

  // u lies in the plane P of F_S: the rays sweep the planar strip F_S + R>0 u. They enter
  // the solid at a point of the strip where u points into it, which lies on a face met
  // from the front (u . n_T < 0, checked above), across P (caught by the same test: the
  // relative interiors meet) or touching P along an edge or at a corner.
  if (!separated(axes, t, s, u)) return true;
  std::array<Sign, 3> side;
  for (int i = 0; i < 3; ++i) side[i] = exact::sign_dot(n_s, t[i] - s[0]);
  // In-plane normals of the strip's sides.
  std::vector<ExactVec> in_plane{exact::cross(u, n_s)};
  for (const ExactVec& e : s_edges) in_plane.push_back(exact::cross(e, n_s));
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    if (side[k] != Sign::kZero || side[j] != Sign::kZero) continue;
    std::vector<ExactVec> edge_axes = in_plane;
    edge_axes.push_back(exact::cross(t_edges[k], n_s));
    const std::array<ExactVec, 2> ends{t[k], t[j]};
    if (separated(edge_axes, ends, s, u)) continue;
    // The strip crosses the edge: u enters the solid there if the edge is concave or
    // flat (T alone is met from the front), or convex and met from the front by both.
    const uint32_t across = mesh_.neighbor[ft][k];
    const Corners c = corners(mesh_, across);
    const Triangle& tri = mesh_.triangles[across];
    const Triangle& own = mesh_.triangles[ft];
    int far = 0;
    while (tri[far] == own[k] || tri[far] == own[j]) ++far;
    const bool convex = exact::sign_dot(n_t, c[far] - t[0]) == Sign::kNegative;
    if (!convex) return true;
    if (exact::sign_dot(u, exact::cross(c[1] - c[0], c[2] - c[0])) == Sign::kNegative) return true;
  }
  // A corner of T in the closed strip (its sides too: rays from the boundary of F_S are
  // rays from S): u enters the solid there iff it points into the solid's cone there.
  for (int k = 0; k < 3; ++k) {
    if (side[k] == Sign::kZero && !separated(in_plane, std::span(&t[k], 1), s, u, /*strictly=*/true) &&
        enters_at_corner(ft, k, u)) {
      return true;
    }
  }
  return false;
}

bool OcclusionProbe::enters_at_corner(uint32_t t, int corner, const ExactVec& u) const {
  // The cone's boundary on the sphere of directions around v is the link of v: for each
  // triangle (v, a, b) of its star, counter-clockwise seen from outside, the minor arc from
  // b - v to a - v, which has the solid on its left. Walking across the edges (v, a)
  // chains the arcs into one loop.
  const uint32_t v = mesh_.triangles[t][corner];
  const ExactVec at = ExactVec::from_point(mesh_.points[v]);
  sphere::Face cone;
  sphere::Loop& link = cone.loops.emplace_back();
  for (uint32_t f : vertex_star(mesh_, t, corner)) {
    const Triangle& tri = mesh_.triangles[f];
    int i = 0;
    while (tri[i] != v) ++i;
    const ExactVec a = ExactVec::from_point(mesh_.points[tri[(i + 1) % 3]]) - at;
    const ExactVec b = ExactVec::from_point(mesh_.points[tri[(i + 2) % 3]]) - at;
    sphere::Arc arc{b, a, exact::cross(b, a)};
    if (sphere::arc_contains(arc, u)) return false;  // along a face or an edge of the star
    link.arcs.push_back(std::move(arc));
  }
  return sphere::point_in_face(cone, u);
}

// The probe's boxes of O group its triangles as the window's runs do.
constexpr size_t kRun = WindowRows::kRun;

OcclusionProbe::OcclusionProbe(const SolidMesh& mesh, std::span<const uint32_t> s,
                               std::span<const uint32_t> o)
    : mesh_(mesh), s_(s.begin(), s.end()), o_(o.begin(), o.end()),
      coordinate_bound_(coordinate_bound(mesh, s, o)) {
  for (size_t begin = 0; begin < o_.size(); begin += kRun) {
    Point3 lo = mesh.points[mesh.triangles[o_[begin]][0]], hi = lo;
    for (size_t i = begin; i < std::min(o_.size(), begin + kRun); ++i) {
      for (uint32_t v : mesh.triangles[o_[i]]) {
        const Point3& p = mesh.points[v];
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
      }
    }
    std::array<Point3, 8> corners;
    for (int k = 0; k < 8; ++k) corners[k] = {k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
    o_run_corners_.push_back(corners);
  }
}

std::vector<uint32_t> OcclusionProbe::near_runs(const DirectionWindow& window, std::span<const double> s_min) const {
  const size_t K = window.row_size(), sides = window.half_spaces();
  std::vector<uint32_t> near;
  if (K == 0) {
    for (uint32_t i = 0; i < o_.size(); ++i) near.push_back(i);
    return near;
  }
  const WindowRows s_rows(&window, s_.size(), {s_min.begin(), s_min.end()}, WindowRows::Side::surface);
  // The largest values over a run of O are at most those at its box's corners, the
  // computed ones at most 1e-14 of the bound above those (rounding, three products), so
  // a run ruled out holds no triangle whose own row the window would keep.
  const double rounding = 1e-14 * coordinate_bound_;
  std::vector<uint8_t> meets(o_run_corners_.size());
  tbb::parallel_for(size_t{0}, o_run_corners_.size(), [&](size_t r) {
    std::vector<double> run(K), corner(K);
    window.row(mesh_, {mesh_.triangles[o_[r * kRun]][0]}, true, run.data());
    for (const Point3& x : o_run_corners_[r]) {
      window.values(x, corner.data());
      window.fold(run.data(), corner.data(), true);
    }
    for (size_t k = 0; k < sides; ++k) run[k] += rounding;
    for (size_t t = 0; t < s_rows.runs() && !meets[r]; ++t) meets[r] = window.may_meet(run.data(), s_rows.run(t));
  });
  for (size_t r = 0; r < meets.size(); ++r) {
    for (size_t i = r * kRun; meets[r] && i < std::min(o_.size(), (r + 1) * kRun); ++i) {
      near.push_back(static_cast<uint32_t>(i));
    }
  }
  return near;
}

template <class Visit>
void OcclusionProbe::for_each_pair(const sphere::SphericalImage& cell, const Visit& visit) const {
  // Pairs whose segments certainly miss the cell are left out (certified double filter).
  const DirectionWindow window(cell, coordinate_bound_);
  const size_t K = window.row_size();
  const std::vector<double> s_min = window.extremes(mesh_, s_, false);
  std::vector<uint32_t> near;  // triangles of O
  for (uint32_t i : near_runs(window, s_min)) near.push_back(o_[i]);
  const WindowRows o_max(&window, near.size(), window.extremes(mesh_, near, true), WindowRows::Side::occluder);
  tbb::parallel_for(size_t{0}, s_.size(), [&](size_t si) {
    Interruptions interruptions(64);
    o_max.for_each_meeting(s_min.data() + si * K, [&](size_t j) {
      interruptions.tick();
      return visit(s_[si], near[j]);
    });
  });
  interruption_point();  // pairs left unvisited when cancelled
}

bool OcclusionProbe::occluded(const ExactVec& u) const {
  std::atomic<bool> found{false};
  for_each_pair(sphere::SphericalImage::point(u), [&](uint32_t fs, uint32_t ft) {
    if (found.load(std::memory_order_relaxed)) return false;
    if (may_block(fs, ft, u)) found = true;
    return true;
  });
  return found;
}

std::vector<uint32_t> OcclusionProbe::blockers(const ExactVec& u) const {
  std::vector<std::atomic<bool>> blocks(o_.size());
  std::vector<uint32_t> index_of(mesh_.triangles.size());
  for (uint32_t i = 0; i < o_.size(); ++i) index_of[o_[i]] = i;
  for_each_pair(sphere::SphericalImage::point(u), [&](uint32_t fs, uint32_t ft) {
    std::atomic<bool>& b = blocks[index_of[ft]];
    if (!b.load(std::memory_order_relaxed) && may_block(fs, ft, u)) b = true;
    return true;
  });
  std::vector<uint32_t> out;
  for (uint32_t i = 0; i < o_.size(); ++i) {
    if (blocks[i]) out.push_back(o_[i]);
  }
  return out;
}

OcclusionProbe::PrismCover OcclusionProbe::prism_cover(const sphere::Arc& open_arc,
                                                      const std::vector<bool>& in_plane) const {
  // Each pair's span along the arc in doubles first: most lie inside wider ones and need no
  // exact map (tens of thousands of maps for one arc without it: docs/performance-history.md).
  // A span that certainly holds the whole arc ends the search; should its exact map not
  // confirm it (it always does), every pair is looked at.
  const ArcSpans frame(open_arc);
  const double a = frame.start() - ArcSpans::kEndError, b = frame.end() + ArcSpans::kEndError;
  struct Candidate {
    uint32_t fs, ft;
    ArcSpans::Span span;
  };
  std::vector<Candidate> candidates;
  for (bool stop_at_whole : {true, false}) {
    sphere::SphericalImage cell;
    cell.add_curve(open_arc);
    tbb::concurrent_vector<Candidate> found;
    std::atomic<bool> whole{false};
    for_each_pair(cell, [&](uint32_t fs, uint32_t ft) {
      if (whole.load(std::memory_order_relaxed)) return false;
      if (in_plane[fs]) return true;
      const ArcSpans::Span span = frame.of_pair(mesh_, fs, ft);
      if (span.kind == ArcSpans::Span::Kind::kMisses) return true;
      found.push_back({fs, ft, span});
      if (stop_at_whole && span.kind == ArcSpans::Span::Kind::kCrosses && span.lo + span.error < a &&
          span.hi - span.error > b) {
        whole = true;
      }
      return true;
    });
    candidates.assign(found.begin(), found.end());
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& x, const Candidate& y) { return std::tie(x.fs, x.ft) < std::tie(y.fs, y.ft); });
    std::vector<ArcSpans::Span> spans;
    for (const Candidate& c : candidates) spans.push_back(c.span);
    const std::vector<uint32_t> matter = spans_that_matter(frame, spans);
    spdlog::trace("occlusion probe: {} pairs meet the arc's plane, {} exact maps ({} undecided in doubles)",
                  candidates.size(), matter.size(),
                  std::count_if(spans.begin(), spans.end(),
                                [](const ArcSpans::Span& x) { return x.kind == ArcSpans::Span::Kind::kUnknown; }));

    tbb::concurrent_vector<Interval> covered;
    std::atomic<bool> all_covered{false};
    tbb::parallel_for(size_t{0}, matter.size(), [&](size_t k) {
      if (all_covered.load(std::memory_order_relaxed)) return;
      interruption_point();
      const Triangle& s = mesh_.triangles[candidates[matter[k]].fs];
      const Triangle& t = mesh_.triangles[candidates[matter[k]].ft];
      std::vector<ExactVec> d;
      for (uint32_t q : t) {
        for (uint32_t p : s) {
          if (q != p) d.push_back(exact::point_difference(mesh_.points[q], mesh_.points[p]));
        }
      }
      const sphere::SphericalImage map = pairwise_occlusion_map(d);
      if (map.dimension() < 2) return;
      std::vector<ExactVec> normals;
      if (!map.is_full_sphere()) {
        for (const sphere::Arc& arc : map.faces()[0].loops[0].arcs) normals.push_back(arc.normal);
      }
      Interval interval;
      bool whole_arc = false;
      if (clip(open_arc, normals, interval, &whole_arc)) covered.push_back(std::move(interval));
      if (whole_arc) all_covered = true;
    });
    interruption_point();
    if (all_covered) return {true, {}};
    if (!whole) return {false, {covered.begin(), covered.end()}};
  }
  return {};  // not reached: the second pass never stops early
}

std::vector<sphere::Arc> OcclusionProbe::unoccluded(const sphere::Arc& open_arc) const {
  // Triangles of S whose plane holds the arc sweep planar strips all along it, where rays
  // may graze; every other one has u . n_S > 0 on the open arc (it lies in the LVM, and
  // u . n_S is a sinusoid along its circle, so it cannot touch zero inside it) and sweeps
  // open prisms.
  std::vector<bool> in_plane(mesh_.triangles.size(), false);
  std::vector<uint32_t> strips;
  for (uint32_t t : s_) {
    const Corners c = corners(mesh_, t);
    if (exact::parallel(exact::cross(c[1] - c[0], c[2] - c[0]), open_arc.normal)) {
      in_plane[t] = true;
      strips.push_back(t);
    }
  }
  // Prisms: u is occluded iff it lies in the interior of a pairwise map (rays from inside
  // F_S hit the inside of T; conversely a generic ray of an open prism that meets the
  // solid first enters it through the inside of a face, and perturbing both ends covers a
  // neighbourhood of u).
  const PrismCover prisms = prism_cover(open_arc, in_plane);
  if (prisms.whole) return {};
  // Outside the prisms' intervals, only the strips can block: their answer is constant
  // between their events (strip_events.h), so each piece is decided at the events and
  // between them. Points between two intervals are decided on their own (rays through
  // them may still enter the solid in a plane of S).
  std::optional<Strips> along;  // built when a piece needs it
  std::vector<sphere::Arc> pieces;
  for (sphere::Arc& piece : complement(open_arc, prisms.intervals)) {
    if (exact::same_direction(piece.start, piece.end)) {
      if (!occluded(piece.start)) pieces.push_back(std::move(piece));
    } else if (strips.empty()) {
      pieces.push_back(std::move(piece));
    } else {
      if (!along) {
        along = strips_along(strips, open_arc);
        spdlog::debug("occlusion probe: arc in the plane of {} triangles of S, {} strip pairs, {} events",
                      strips.size(), along->pairs.size(), along->events.size());
      }
      decide_between_events(piece, open_arc, *along, pieces);
    }
  }
  return pieces;
}

OcclusionProbe::Strips OcclusionProbe::strips_along(std::span<const uint32_t> in_plane,
                                                    const sphere::Arc& open_arc) const {
  // Only pairs whose segments may have a direction on the arc (certified double filter).
  sphere::SphericalImage cell;
  cell.add_curve(open_arc);
  const DirectionWindow window(cell, coordinate_bound_);
  const size_t K = window.row_size();
  const std::vector<double> o_max = window.extremes(mesh_, o_, true);
  Strips strips;
  struct Found {
    StripEvent event;
    uint32_t plane, triangle;  // the triangle of O it comes from
  };
  tbb::concurrent_vector<Found> found;
  uint32_t plane_index = 0;
  // Not a structured binding: clang 14 (the fuzz preset) cannot capture those.
  for (const auto& strip_plane : strip_planes(mesh_, in_plane)) {
    const auto& plane = strip_plane.first;
    const auto& triangles = strip_plane.second;
    const WindowRows s_min(&window, triangles.size(), window.extremes(mesh_, triangles, false),
                           WindowRows::Side::surface);
    tbb::concurrent_vector<std::pair<uint32_t, uint32_t>> pairs;
    tbb::parallel_for(size_t{0}, o_.size(), [&](size_t oi) {
      std::vector<uint32_t> near;
      s_min.for_each_meeting(o_max.data() + oi * K, [&](size_t si) {
        near.push_back(triangles[si]);
        return true;
      });
      if (near.empty() || !touches(mesh_, plane, o_[oi])) return;
      for (uint32_t fs : near) pairs.emplace_back(fs, o_[oi]);
      std::vector<StripEvent> mine;
      add_strip_events(mesh_, plane, o_[oi], mine);
      for (StripEvent& e : mine) found.push_back({std::move(e), plane_index, o_[oi]});
    });
    interruption_point();
    strips.pairs.insert(strips.pairs.end(), pairs.begin(), pairs.end());
    ++plane_index;
  }
  for (auto [fs, ft] : strips.pairs) {
    const Corners c = corners(mesh_, fs);
    strips.plane_normals.push_back(exact::unit_estimate(exact::cross(c[1] - c[0], c[2] - c[0])));
  }
  // One line per construction, with every triangle that has it (most events are shared),
  // then in order along the arc, both ways round; equal lines built apart meet there.
  std::vector<Found> events(found.begin(), found.end());
  std::sort(events.begin(), events.end(), [](const Found& x, const Found& y) {
    return std::tie(x.plane, x.event.key, x.triangle) < std::tie(y.plane, y.event.key, y.triangle);
  });
  std::vector<ExactVec> both;
  std::vector<std::vector<uint32_t>> sources;  // of each line
  for (size_t i = 0; i < events.size(); ++i) {
    if (i == 0 || events[i].plane != events[i - 1].plane || events[i].event.key != events[i - 1].event.key) {
      both.push_back(events[i].event.line);
      both.push_back(-events[i].event.line);
      sources.emplace_back();
    }
    sources.back().push_back(events[i].triangle);
  }
  for (const std::vector<uint32_t>& equal : in_order_along(open_arc, both)) {
    strips.events.push_back(both[equal[0]]);
    std::vector<uint32_t>& at = strips.event_sources.emplace_back();
    for (uint32_t i : equal) at.insert(at.end(), sources[i / 2].begin(), sources[i / 2].end());
    std::sort(at.begin(), at.end());
  }
  return strips;
}

bool OcclusionProbe::Strips::block(const OcclusionProbe& probe, const ExactVec& u, size_t& last) const {
  const StripFilter filter(probe.mesh_, u, probe.coordinate_bound_);
  auto blocks = [&](size_t i) {
    const auto [fs, ft] = pairs[i];
    return filter.may_meet(fs, ft, plane_normals[i]) && probe.may_block(fs, ft, u);
  };
  // Neighbouring stretches are mostly blocked by the same pair: try the last one first.
  if (last < pairs.size() && blocks(last)) return true;
  std::atomic<size_t> found{pairs.size()};
  tbb::parallel_for(size_t{0}, pairs.size(), [&](size_t i) {
    if (found.load(std::memory_order_relaxed) == pairs.size() && blocks(i)) found = i;
  });
  interruption_point();
  if (found == pairs.size()) return false;
  last = found;
  return true;
}

bool OcclusionProbe::Strips::changes_at(size_t e, size_t i) const {
  return std::binary_search(event_sources[e].begin(), event_sources[e].end(), pairs[i].second);
}

void OcclusionProbe::decide_between_events(const sphere::Arc& piece, const sphere::Arc& open_arc,
                                           const Strips& strips, std::vector<sphere::Arc>& out) const {
  const ArcOrder order{open_arc.normal};
  std::vector<ExactVec> at{piece.start};
  std::vector<size_t> event;  // of at[i + 1], for i + 2 < at.size()
  for (size_t e = 0; e < strips.events.size(); ++e) {
    if (order.before(piece.start, strips.events[e]) && order.before(strips.events[e], piece.end)) {
      at.push_back(strips.events[e]);
      event.push_back(e);
    }
  }
  at.push_back(piece.end);
  // No prism blocks the piece, so only the strips can. The visible set is closed (the
  // blocked one is open: rays meeting the open interior keep meeting it when u moves a
  // little), so a visible stretch between events brings its ends along; an event is
  // otherwise visible on its own. The ends of the whole arc are not in it (the caller
  // decides them).
  // A pair's answer only changes at its triangle's events, so the pair that blocks a
  // stretch blocks the event after it, and the stretch after that, unless the event is one
  // of its own (TR12J F234: 6,000 events per arc, 8,000 pairs to search for each).
  constexpr size_t kVisible = SIZE_MAX;
  size_t last = 0;
  std::vector<size_t> blocker(at.size() - 1, kVisible);  // of each stretch
  auto kept_across = [&](size_t i, size_t stretch) {  // blocker[stretch] blocks at[i] too
    return blocker[stretch] != kVisible && !strips.changes_at(event[i - 1], blocker[stretch]);
  };
  for (size_t i = 0; i + 1 < at.size(); ++i) {
    if (i > 0 && kept_across(i, i - 1)) {
      blocker[i] = blocker[i - 1];
    } else if (strips.block(*this, at[i] + at[i + 1], last)) {
      blocker[i] = last;
    }
  }
  auto between = [&](size_t stretch) { return blocker[stretch] == kVisible; };
  for (size_t i = 0; i < at.size(); ++i) {
    const bool before = i > 0 && between(i - 1), after = i + 1 < at.size() && between(i);
    const bool inner = i > 0 && i + 1 < at.size();  // at[i] is an event, not an end of the piece
    if (after && before) {
      out.back().end = at[i + 1];  // the stretch goes on
    } else if (after) {
      out.push_back({at[i], at[i + 1], open_arc.normal});
    } else if (!before && !(inner && (kept_across(i, i - 1) || kept_across(i, i))) &&
               !exact::same_direction(at[i], open_arc.start) && !exact::same_direction(at[i], open_arc.end) &&
               !strips.block(*this, at[i], last)) {
      out.push_back({at[i], at[i], open_arc.normal});
    }
  }
}

}  // namespace gvm
