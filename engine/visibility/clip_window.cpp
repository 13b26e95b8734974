#include "visibility/clip_window.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "sphere/d3.h"

namespace gvm {
namespace {

using exact::ExactVec;
using namespace sphere;  // D3

ExactVec exact_of(const D3& a) { return ExactVec::from_point({a[0], a[1], a[2]}); }

// The circles through L's boundary (inward unit normals, in counter-clockwise order
// around L) and a direction inside L towards which they are pushed out.
struct Outline {
  std::vector<D3> inward;
  D3 centre{};
  std::vector<ExactVec> vertices;      // every vertex of L, checked strictly inside
  std::vector<sphere::Arc> arcs;       // every arc of L, checked minor
};

Outline outline(const sphere::SphericalImage& lvm) {
  Outline out;
  const size_t cells = lvm.faces().size() + lvm.curves().size() + lvm.points().size();
  if (lvm.is_full_sphere() || cells != 1) return out;
  D3 sum{};
  if (!lvm.faces().empty()) {
    const sphere::Face& f = lvm.faces()[0];
    if (!f.convex || f.loops.size() != 1) return out;
    for (const sphere::Arc& arc : f.loops[0].arcs) {
      if (arc.full) return {};
      out.inward.push_back(arc.normal.unit());
      out.vertices.push_back(arc.start);
      out.arcs.push_back(arc);
      sum = add(sum, arc.start.unit());
    }
  } else if (!lvm.curves().empty()) {
    // A thin band along the arc: below it, past its end, above it, before its start.
    const sphere::Arc& arc = lvm.curves()[0];
    if (arc.full) return out;
    const D3 n = arc.normal.unit(), a = arc.start.unit(), b = arc.end.unit();
    out.inward = {n, normalized(cross(b, n)), negated(n), normalized(cross(n, a))};
    out.vertices = {arc.start, arc.end};
    out.arcs = {arc};
    sum = add(a, b);
  } else {
    // A small square around the point.
    const D3 u = lvm.points()[0].unit();
    const D3 helper = std::fabs(u[0]) < 0.6 ? D3{1, 0, 0} : D3{0, 1, 0};
    const D3 n1 = normalized(cross(u, helper)), n2 = cross(u, n1);
    out.inward = {n2, negated(n1), negated(n2), n1};
    out.vertices = {lvm.points()[0]};
    sum = u;
  }
  if (sum == D3{}) return {};
  out.centre = normalized(sum);
  return out;
}

// L's boundary counter-clockwise with every arc minor: arcs of a half circle or more
// (a lune's sides, a hemisphere's full circle) get vertices a quarter turn apart, exactly
// on their circles. Arc i runs from vertices[i] to vertices[i + 1] about normals[i].
struct MinorBoundary {
  std::vector<ExactVec> vertices, normals;
};

std::optional<MinorBoundary> minor_boundary(const sphere::Loop& loop) {
  MinorBoundary b;
  for (const sphere::Arc& arc : loop.arcs) {
    const ExactVec& m = arc.normal;
    const D3 n = m.unit();
    const D3 axis = std::fabs(n[0]) < 0.6 ? D3{1, 0, 0} : D3{0, 1, 0};
    ExactVec at = arc.full ? exact::cross(m, exact_of(axis)) : arc.start;
    const ExactVec end = arc.full ? at : arc.end;
    for (int quarter = 0;; ++quarter) {
      b.vertices.push_back(at);
      b.normals.push_back(m);
      const bool rest_minor = !(arc.full && quarter == 0) && exact::sign_det(at, end, m) == Sign::kPositive;
      if (rest_minor) break;
      if (quarter == 3) return std::nullopt;
      at = exact::cross(m, at);  // a quarter turn on to the arc's end
    }
  }
  return b;
}

// Directions strictly inside L (inside every arc's half-space), guessed in doubles and
// checked exactly: the centre of the vertices, of the normals, of the farthest two
// vertices (for cells whose vertices crowd at one end).
std::vector<ExactVec> inside_directions(const MinorBoundary& b) {
  D3 vertex_sum{}, normal_sum{}, far_pair{};
  double closest = 2;
  for (size_t i = 0; i < b.vertices.size(); ++i) {
    const D3 u = b.vertices[i].unit();
    vertex_sum = add(vertex_sum, u);
    normal_sum = add(normal_sum, b.normals[i].unit());
    for (size_t j = 0; j < i; ++j) {
      const D3 w = b.vertices[j].unit();
      if (dot(u, w) < closest) {
        closest = dot(u, w);
        far_pair = add(u, w);
      }
    }
  }
  std::vector<ExactVec> out;
  for (const D3& guess : {vertex_sum, normal_sum, add(vertex_sum, normal_sum), far_pair}) {
    if (!(norm(guess) > 1e-3)) continue;
    const ExactVec c = exact_of(normalized(guess));
    bool inside = true;
    for (const ExactVec& n : b.normals) inside = inside && exact::sign_dot(n, c) == Sign::kPositive;
    if (inside) out.push_back(c);
  }
  return out;
}

// A piece of L's fan from c: c and consecutive boundary vertices, counter-clockwise, with
// the inward unit normals of its sides and its centre, in doubles.
struct FanPiece {
  std::vector<ExactVec> vertices;
  std::vector<D3> inward;
  D3 centre{};
};

// Pieces turning about a right angle each around c (more where one arc turns more): every
// direction of L lies in one, since L is convex and c inside it.
std::vector<FanPiece> fan_pieces(const MinorBoundary& b, const ExactVec& c) {
  constexpr double kPieceTurn = 1.75;  // radians, a little over a right angle
  const D3 cd = c.unit();
  const D3 helper = std::fabs(cd[0]) < 0.6 ? D3{1, 0, 0} : D3{0, 1, 0};
  const D3 e1 = normalized(cross(helper, cd)), e2 = cross(cd, e1);
  const size_t k = b.vertices.size();
  auto turn = [&](size_t from, size_t to) {  // counter-clockwise around c, in [0, 2 pi)
    const D3 p = b.vertices[from % k].unit(), q = b.vertices[to % k].unit();
    const double t = std::atan2(dot(q, e2), dot(q, e1)) - std::atan2(dot(p, e2), dot(p, e1));
    return t < 0 ? t + 2 * M_PI : t;
  };
  std::vector<size_t> cuts = {0};
  for (size_t i = 2; i <= k; ++i) {
    if (i - 1 > cuts.back() && turn(cuts.back(), i) > kPieceTurn) cuts.push_back(i - 1);
  }
  cuts.push_back(k);
  std::vector<FanPiece> pieces;
  for (size_t j = 0; j + 1 < cuts.size(); ++j) {
    FanPiece piece;
    piece.vertices.push_back(c);
    for (size_t i = cuts[j]; i <= cuts[j + 1]; ++i) piece.vertices.push_back(b.vertices[i % k]);
    piece.inward.push_back(normalized(cross(cd, b.vertices[cuts[j]].unit())));
    for (size_t i = cuts[j]; i < cuts[j + 1]; ++i) piece.inward.push_back(b.normals[i].unit());
    piece.inward.push_back(normalized(cross(b.vertices[cuts[j + 1] % k].unit(), cd)));
    D3 sum{};
    for (const ExactVec& v : piece.vertices) sum = add(sum, v.unit());
    piece.centre = normalized(sum);
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

}  // namespace

ClipWindow::ClipWindow(std::vector<ExactVec> normals) : normals_(std::move(normals)) {
  const size_t k = normals_.size();
  for (size_t i = 0; i < k; ++i) corners_.push_back(exact::cross(normals_[(i + k - 1) % k], normals_[i]));
  for (const ExactVec& w : normals_) estimates_.push_back(exact::unit_estimate(w));
}

bool ClipWindow::proper() const {
  const size_t k = normals_.size();
  if (k < 3) return false;
  for (size_t i = 0; i < k; ++i) {
    for (size_t j = 0; j < k; ++j) {
      if (j != i && j != (i + k - 1) % k && exact::sign_dot(normals_[j], corners_[i]) != Sign::kPositive) {
        return false;
      }
    }
    if (exact::sign_det(corners_[i], corners_[(i + 1) % k], normals_[i]) != Sign::kPositive) return false;
  }
  return true;
}

std::optional<ClipWindow> ClipWindow::fit(const std::vector<D3>& inward, const D3& centre,
                                          std::span<const ExactVec> vertices) {
  // About one and six degrees; the smaller margin keeps W (and the work) smaller, the
  // larger one is for cells whose vertices lie near the edge of their centre's hemisphere.
  for (const double margin : {0.02, 0.1}) {
    std::vector<ExactVec> normals;
    for (const D3& m : inward) normals.push_back(exact_of(add(m, centre, margin)));
    ClipWindow window(std::move(normals));
    bool inside = window.proper();
    for (const ExactVec& v : vertices) inside = inside && window.contains_strictly(v);
    if (inside) return window;
  }
  return std::nullopt;
}

std::optional<ClipWindow> ClipWindow::around(const sphere::SphericalImage& lvm) {
  const Outline l = outline(lvm);
  if (l.inward.empty()) return std::nullopt;
  for (const sphere::Arc& arc : l.arcs) {
    if (exact::sign_det(arc.start, arc.end, arc.normal) != Sign::kPositive) return std::nullopt;
  }
  return fit(l.inward, l.centre, l.vertices);
}

std::vector<ClipWindow> ClipWindow::covering(const sphere::SphericalImage& lvm) {
  if (std::optional<ClipWindow> one = around(lvm)) return {std::move(*one)};
  const size_t cells = lvm.faces().size() + lvm.curves().size() + lvm.points().size();
  if (lvm.is_full_sphere() || cells != 1 || lvm.faces().empty()) return {};
  const sphere::Face& f = lvm.faces()[0];
  if (!f.convex || f.loops.size() != 1) return {};
  const std::optional<MinorBoundary> boundary = minor_boundary(f.loops[0]);
  if (!boundary) return {};
  for (const ExactVec& c : inside_directions(*boundary)) {
    const std::vector<FanPiece> pieces = fan_pieces(*boundary, c);
    if (pieces.size() > kMaxWindows) continue;
    std::vector<ClipWindow> windows;
    for (const FanPiece& piece : pieces) {
      std::optional<ClipWindow> w = fit(piece.inward, piece.centre, piece.vertices);
      if (!w) break;
      windows.push_back(std::move(*w));
    }
    if (windows.size() == pieces.size()) return windows;
  }
  return {};
}

bool ClipWindow::contains_strictly(const ExactVec& u) const {
  const exact::UnitEstimate eu = exact::unit_estimate(u);
  for (size_t j = 0; j < normals_.size(); ++j) {
    if (side(j, u, eu) != Sign::kPositive) return false;
  }
  return true;
}

bool ClipWindow::misses(std::span<const ExactVec> polygon) const {
  std::vector<exact::UnitEstimate> ev;
  for (const ExactVec& v : polygon) ev.push_back(exact::unit_estimate(v));
  for (size_t j = 0; j < normals_.size(); ++j) {
    bool any_positive = false;
    for (size_t i = 0; i < polygon.size() && !any_positive; ++i) {
      any_positive = side(j, polygon[i], ev[i]) == Sign::kPositive;
    }
    if (!any_positive) return true;
  }
  return false;
}

namespace {

// Where an arc crosses the boundary of W, and how the coverage inside W changes there
// when W's boundary is walked counter-clockwise.
struct Crossing {
  ExactVec x;
  int delta;
};

}  // namespace

std::optional<std::vector<sphere::ArrangementArc>> ClipWindow::clip(
    std::span<const sphere::ArrangementArc> arcs, int corner_coverage) const {
  const size_t k = normals_.size();
  std::vector<std::vector<Crossing>> on_edge(k);
  std::vector<sphere::ArrangementArc> out;
  std::vector<Sign> from(k), to(k);
  for (const sphere::ArrangementArc& arc : arcs) {
    bool from_inside = true, to_inside = true;
    const exact::UnitEstimate e_from = exact::unit_estimate(arc.from), e_to = exact::unit_estimate(arc.to);
    for (size_t j = 0; j < k; ++j) {
      from[j] = side(j, arc.from, e_from);
      to[j] = side(j, arc.to, e_to);
      if (from[j] == Sign::kZero || to[j] == Sign::kZero) return std::nullopt;
      from_inside = from_inside && from[j] == Sign::kPositive;
      to_inside = to_inside && to[j] == Sign::kPositive;
    }
    if (from_inside && to_inside) {
      out.push_back(arc);
      continue;
    }
    // A minor arc meets convex W in one piece: it enters at most once and leaves at most once.
    std::optional<ExactVec> entry, exit;
    for (size_t j = 0; j < k; ++j) {
      if (from[j] == to[j]) continue;
      const ExactVec& w = normals_[j];
      // (from x to) x w = (from . w) to - (to . w) from: on the arc.
      const bool entering = from[j] == Sign::kNegative;
      ExactVec x = entering ? exact::cross(w, arc.normal) : exact::cross(arc.normal, w);
      const exact::UnitEstimate ex = exact::unit_estimate(x);
      bool on_boundary = true;
      for (size_t l = 0; l < k && on_boundary; ++l) {
        if (l == j) continue;
        const Sign s = side(l, x, ex);
        if (s == Sign::kZero) return std::nullopt;  // through a corner
        on_boundary = s == Sign::kPositive;
      }
      if (!on_boundary) continue;
      // Walking W's edge forwards crosses from the arc's right to its left where it leaves.
      on_edge[j].push_back({x, entering ? -arc.weight : arc.weight});
      (entering ? entry : exit) = std::move(x);
    }
    const bool consistent = from_inside || to_inside
                                ? entry.has_value() != from_inside && exit.has_value() != to_inside
                                : entry.has_value() == exit.has_value();
    if (!consistent) return std::nullopt;
    if (!entry && !exit) continue;  // outside W
    out.push_back({entry ? *entry : arc.from, exit ? *exit : arc.to, arc.normal, arc.layer, arc.weight});
  }
  // W's boundary, its pieces weighted by the coverage just inside.
  int coverage = corner_coverage;
  for (size_t j = 0; j < k; ++j) {
    const ExactVec& w = normals_[j];
    std::vector<Crossing>& crossings = on_edge[j];
    std::sort(crossings.begin(), crossings.end(), [&](const Crossing& a, const Crossing& b) {
      return exact::sign_det(a.x, b.x, w) == Sign::kPositive;
    });
    const ExactVec* piece_start = &corners_[j];
    auto piece_to = [&](const ExactVec& end) {
      if (coverage != 0 && exact::sign_det(*piece_start, end, w) == Sign::kPositive) {
        out.push_back({*piece_start, end, w, 0, coverage});
      }
      piece_start = &end;
    };
    for (const Crossing& c : crossings) {
      piece_to(c.x);
      coverage += c.delta;
    }
    piece_to(corners_[(j + 1) % k]);
  }
  if (coverage != corner_coverage) return std::nullopt;
  return out;
}

}  // namespace gvm
