#include "visibility/seam_pieces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <optional>

#include "sphere/box_tree.h"
#include "sphere/spherical_image.h"

namespace gvm {
namespace {

using exact::ExactVec;
using sphere::ArrangementArc;

// The arcs on one great circle (normals exactly parallel), each circle oriented by its
// first arc's normal. Sign-normalized unit estimates (by the largest component) of
// parallel normals lie within their certified radii, far below the 1e-9 grid, so a circle
// is always found in the arc's grid cell or a neighbouring one.
std::vector<std::vector<GrazingArc>> by_circle(std::vector<GrazingArc> arcs) {
  constexpr double kCell = 1e-9;
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells;  // grid cell -> circles
  std::vector<std::vector<GrazingArc>> circles;
  auto key = [](int64_t x, int64_t y, int64_t z) {
    return (uint64_t(x) * 73856093u) ^ (uint64_t(y) * 19349663u) ^ (uint64_t(z) * 83492791u);
  };
  for (GrazingArc& a : arcs) {
    std::array<double, 3> u = exact::unit_estimate(a.arc.normal).unit;
    int big = 0;
    for (int i = 1; i < 3; ++i) big = std::abs(u[i]) > std::abs(u[big]) ? i : big;
    if (u[big] < 0) u = {-u[0], -u[1], -u[2]};
    const int64_t c[3] = {std::llround(u[0] / kCell), std::llround(u[1] / kCell), std::llround(u[2] / kCell)};
    std::optional<uint32_t> found;
    for (int64_t dx = -1; dx <= 1 && !found; ++dx) {
      for (int64_t dy = -1; dy <= 1 && !found; ++dy) {
        for (int64_t dz = -1; dz <= 1 && !found; ++dz) {
          const auto it = cells.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it == cells.end()) continue;
          for (uint32_t g : it->second) {
            if (exact::parallel(circles[g].front().arc.normal, a.arc.normal)) {
              found = g;
              break;
            }
          }
        }
      }
    }
    if (!found) {
      found = static_cast<uint32_t>(circles.size());
      circles.emplace_back();
      cells[key(c[0], c[1], c[2])].push_back(*found);
    } else {
      const ExactVec& n = circles[*found].front().arc.normal;
      if (exact::sign_dot(n, a.arc.normal) == Sign::kNegative) {
        a = {{a.arc.to, a.arc.from, n, a.arc.layer, a.arc.weight}, -a.side};
      } else {
        a.arc.normal = n;
      }
    }
    circles[*found].push_back(std::move(a));
  }
  return circles;
}

// Whether u, a direction on the circle of minor arc (from, to) around n, lies on the arc:
// the arcs and ends grouped on one circle lie on it exactly, so only the ends are tested.
bool on_arc(const ExactVec& n, const ExactVec& from, const ExactVec& to, const ExactVec& u) {
  return exact::sign_det(n, from, u) != Sign::kNegative && exact::sign_det(n, u, to) != Sign::kNegative;
}

// Arcs on one circle (their common normal n), merged in order of their starts along it:
// an arc starting on the current one extends it while the result stays shorter than 180
// degrees. The order is by angle in doubles, from the estimates (rounding the exact
// directions took a tenth of the seams of small surfaces); every merge is decided
// exactly, so a misordering only merges less.
std::vector<ArrangementArc> merged(std::vector<ArrangementArc> arcs) {
  if (arcs.size() < 2) return arcs;
  const ExactVec n = arcs.front().normal;
  const std::array<double, 3> e1 = exact::unit_estimate(arcs.front().from).unit, nu = exact::unit_estimate(n).unit;
  const std::array<double, 3> e2{nu[1] * e1[2] - nu[2] * e1[1], nu[2] * e1[0] - nu[0] * e1[2],
                                 nu[0] * e1[1] - nu[1] * e1[0]};
  auto angle = [&](const ExactVec& v) {
    const std::array<double, 3> u = exact::unit_estimate(v).unit;
    return std::atan2(u[0] * e2[0] + u[1] * e2[1] + u[2] * e2[2], u[0] * e1[0] + u[1] * e1[1] + u[2] * e1[2]);
  };
  std::vector<std::pair<double, size_t>> by_start;
  for (size_t i = 0; i < arcs.size(); ++i) by_start.push_back({angle(arcs[i].from), i});
  std::sort(by_start.begin(), by_start.end());
  std::vector<ArrangementArc> out;
  std::optional<ArrangementArc> current;
  for (const auto& [_, i] : by_start) {
    const ArrangementArc& next = arcs[i];
    if (current) {
      if (on_arc(n, current->from, current->to, next.from)) {
        if (on_arc(n, current->from, current->to, next.to)) continue;
        if (exact::sign_det(n, current->from, next.to) == Sign::kPositive) {
          current->to = next.to;
          continue;
        }
      }
      out.push_back(*current);
    }
    current = next;
  }
  out.push_back(*current);
  return out;
}

// The common part of two closed arcs on one circle, each shorter than 180 degrees (so it
// is one piece at most): from the start that lies on the other arc to the end that does.
std::optional<sphere::Arc> overlap(const ArrangementArc& x, const ArrangementArc& y) {
  const ExactVec& n = x.normal;  // y's too
  std::optional<ExactVec> lo, hi;
  if (on_arc(n, x.from, x.to, y.from)) {
    lo = y.from;
  } else if (on_arc(n, y.from, y.to, x.from)) {
    lo = x.from;
  } else {
    return std::nullopt;
  }
  hi = on_arc(n, y.from, y.to, x.to) ? x.to : y.to;
  return sphere::Arc{*lo, *hi, n};
}

// X strictly inside arc a (on its circle, strictly between its ends).
bool strictly_on(const ArrangementArc& a, const ExactVec& x) {
  return exact::sign_dot(x, a.normal) == Sign::kZero && exact::sign_det(a.normal, a.from, x) == Sign::kPositive &&
         exact::sign_det(a.normal, x, a.to) == Sign::kPositive;
}

// Points strictly inside arcs of three distinct circles (circle[i]: arc i's circle).
std::vector<ExactVec> triple_points(const std::vector<ArrangementArc>& arcs, const std::vector<uint32_t>& circle) {
  std::vector<sphere::Box> boxes;
  for (const ArrangementArc& a : arcs) {
    boxes.push_back(sphere::arc_box(exact::unit_estimate(a.from), exact::unit_estimate(a.to)));
  }
  const sphere::BoxTree tree(boxes);
  std::vector<ExactVec> out;
  // Arcs with a common end (one node) cross only there, at no point strictly inside them:
  // their circles meet at that end and its antipode, which no minor arc from it reaches.
  auto common_end = [](const ArrangementArc& a, const ArrangementArc& b) {
    return a.from.node() == b.from.node() || a.from.node() == b.to.node() || a.to.node() == b.from.node() ||
           a.to.node() == b.to.node();
  };
  for (auto [i, j] : tree.overlapping_pairs()) {
    if (circle[i] == circle[j] || common_end(arcs[i], arcs[j])) continue;
    ExactVec x = exact::cross(arcs[i].normal, arcs[j].normal);
    if (exact::sign_det(arcs[i].normal, arcs[i].from, x) != Sign::kPositive) x = -x;
    if (!strictly_on(arcs[i], x) || !strictly_on(arcs[j], x)) continue;
    // Each point once for the first two of its arcs (pairs come with i < j).
    for (uint32_t k : tree.overlapping(sphere::point_box(exact::unit_estimate(x)))) {
      if (k > j && circle[k] != circle[i] && circle[k] != circle[j] && strictly_on(arcs[k], x)) {
        out.push_back(x);
        break;
      }
    }
  }
  return out;
}

}  // namespace

SeamPieces seam_pieces(std::vector<GrazingArc> arcs) {
  SeamPieces out;
  std::vector<ArrangementArc> all;  // merged per circle, for the crossings
  std::vector<uint32_t> circle_of;
  uint32_t circle = 0;
  for (std::vector<GrazingArc>& on_circle : by_circle(std::move(arcs))) {
    std::vector<ArrangementArc> left, right, any;
    for (const GrazingArc& a : on_circle) {
      if (a.side >= 0) left.push_back(a.arc);
      if (a.side <= 0) right.push_back(a.arc);
      any.push_back(a.arc);
    }
    left = merged(std::move(left));
    right = merged(std::move(right));
    for (const ArrangementArc& l : left) {
      for (const ArrangementArc& r : right) {
        const std::optional<sphere::Arc> both = overlap(l, r);
        if (!both) continue;
        if (exact::same_direction(both->start, both->end)) {
          out.points.push_back(both->start);
        } else {
          out.arcs.push_back({both->start, both->end, both->normal, 0, 0});
        }
      }
    }
    for (ArrangementArc& a : merged(std::move(any))) {
      all.push_back(std::move(a));
      circle_of.push_back(circle);
    }
    ++circle;
  }
  const std::vector<ExactVec> triples = triple_points(all, circle_of);
  out.points.insert(out.points.end(), triples.begin(), triples.end());
  return out;
}

}  // namespace gvm
