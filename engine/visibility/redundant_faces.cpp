#include "visibility/redundant_faces.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <optional>

#include "parallel/interrupt.h"
#include "sphere/d3.h"

namespace gvm {
namespace {

using namespace sphere;  // D3

constexpr int kGrid = 128;               // cells along an edge of a cube face
// The largest faces, all kept, may cover the others (so that no two faces are left out
// for covering each other). More tiers (the largest 1% covering the next 9%) left out no
// more faces of the largest envelope measured (occt_TR12J_OCC F234).
constexpr double kLargeFraction = 0.1;
// Estimates of unit vertices are within kRadius of the exact directions (else the face is
// kept as it is). Inside-tests of grid corners are then off by less than 1e-11, and
// gnomonic coordinates (vertices at least kMinHeight above the cube face's plane) by less
// than 1e-9: the slacks below are far above both.
constexpr double kRadius = 1e-12;
constexpr double kMinHeight = 0.05;
constexpr double kCornerSlack = 1e-9;
constexpr double kCoordinateSlack = 1e-7;

// A face in doubles: unit vertices, edge normals and (for ranking) its approximate area.
struct Estimate {
  std::vector<D3> u, n;
  double area = 0;
  bool certain = false;  // every vertex located within kRadius
};

Estimate estimate(const std::vector<exact::ExactVec>& face) {
  Estimate e;
  for (const exact::ExactVec& v : face) {
    const exact::UnitEstimate u = exact::unit_estimate(v);
    if (!(u.radius <= kRadius)) return e;
    e.u.push_back(u.unit);
  }
  for (size_t i = 0; i < e.u.size(); ++i) e.n.push_back(cross(e.u[i], e.u[(i + 1) % e.u.size()]));
  for (size_t i = 1; i + 1 < e.u.size(); ++i) {
    e.area += norm(cross(add(e.u[i], e.u[0], -1), add(e.u[i + 1], e.u[0], -1))) / 2;
  }
  e.certain = true;
  return e;
}

// A face of the cube map: directions x with x . axis > 0, at (s, t) = (x . e1, x . e2) /
// (x . axis) on its plane; the grid's lines are great circles.
struct CubeFace {
  D3 axis, e1, e2;
  D3 point(double s, double t) const { return add(add(axis, e1, s), e2, t); }
};

const std::array<CubeFace, 6> kCube = {{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                        {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                        {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},
                                        {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                                        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
                                        {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}}};

double grid_line(int i) { return -1 + 2.0 * i / kGrid; }

struct Rect {
  int i0, i1, j0, j1;  // cells i0 .. i1 - 1, j0 .. j1 - 1
};

// The face's gnomonic coordinates on a cube face, grown by `slack` (false when a vertex is
// too close to the plane of the cube face to project reliably).
bool project(const Estimate& f, const CubeFace& c, double slack, double (&s)[2], double (&t)[2]) {
  s[0] = t[0] = INFINITY;
  s[1] = t[1] = -INFINITY;
  for (const D3& u : f.u) {
    const double h = dot(u, c.axis);
    if (!(h > kMinHeight)) return false;
    const double su = dot(u, c.e1) / h, tu = dot(u, c.e2) / h;
    s[0] = std::min(s[0], su - slack);
    s[1] = std::max(s[1], su + slack);
    t[0] = std::min(t[0], tu - slack);
    t[1] = std::max(t[1], tu + slack);
  }
  return true;
}

int cell_of(double x) { return std::clamp(static_cast<int>(std::floor((x + 1) * kGrid / 2)), 0, kGrid - 1); }

// The cells of a cube face where f may lie, for the search of covered cells only (the
// corner tests decide): f cut at the height kMinHeight above the plane, projected.
std::optional<Rect> search_rect(const Estimate& f, const CubeFace& c) {
  double s[2] = {INFINITY, -INFINITY}, t[2] = {INFINITY, -INFINITY};
  auto add = [&](const D3& u) {
    const double h = dot(u, c.axis), su = dot(u, c.e1) / h, tu = dot(u, c.e2) / h;
    s[0] = std::min(s[0], su);
    s[1] = std::max(s[1], su);
    t[0] = std::min(t[0], tu);
    t[1] = std::max(t[1], tu);
  };
  for (size_t i = 0; i < f.u.size(); ++i) {
    const D3 &a = f.u[i], &b = f.u[(i + 1) % f.u.size()];
    const double ha = dot(a, c.axis) - kMinHeight, hb = dot(b, c.axis) - kMinHeight;
    if (ha >= 0) add(a);
    if ((ha < 0) != (hb < 0)) {
      const double x = ha / (ha - hb);
      add({a[0] + x * (b[0] - a[0]), a[1] + x * (b[1] - a[1]), a[2] + x * (b[2] - a[2])});
    }
  }
  if (!(s[0] <= s[1]) || s[1] < -1 || s[0] > 1 || t[1] < -1 || t[0] > 1) return std::nullopt;
  return Rect{cell_of(s[0]), cell_of(s[1]) + 1, cell_of(t[0]), cell_of(t[1]) + 1};
}

class CoveredCells {
 public:
  CoveredCells() : covered_(6 * kGrid * kGrid) {}

  // Marks the cells of every cube face whose corners certainly lie inside f.
  void mark(const Estimate& f) {
    for (int k = 0; k < 6; ++k) {
      std::optional<Rect> found = search_rect(f, kCube[k]);
      if (!found) continue;
      const Rect r = *found;
      Run below = corners_inside(f, kCube[k], r, r.j0);
      for (int j = r.j0; j < r.j1; ++j) {
        const Run above = corners_inside(f, kCube[k], r, j + 1);
        // Cell i has its corners i and i + 1 on both grid lines.
        const int to = std::min(below.last, above.last);
        for (int i = std::max(below.first, above.first); i < to; ++i) {
          covered_[index(k, i, j)].store(1, std::memory_order_relaxed);
        }
        below = above;
      }
    }
  }

  // Whether the cells of one cube face around f are all covered.
  bool hold(const Estimate& f) const {
    int best = 0;
    for (int k = 1; k < 6; ++k) {
      if (dot(f.u[0], kCube[k].axis) > dot(f.u[0], kCube[best].axis)) best = k;
    }
    double s[2], t[2];
    if (!project(f, kCube[best], kCoordinateSlack, s, t)) return false;
    if (s[0] < -1 || s[1] > 1 || t[0] < -1 || t[1] > 1) return false;  // beyond this cube face
    for (int j = cell_of(t[0]); j <= cell_of(t[1]); ++j) {
      for (int i = cell_of(s[0]); i <= cell_of(s[1]); ++i) {
        if (!covered_[index(best, i, j)].load(std::memory_order_relaxed)) return false;
      }
    }
    return true;
  }

 private:
  struct Run {
    int first = 0, last = -1;  // empty when first > last
  };
  // The run of corners i0 <= i <= i1 of grid line j that lie inside f (`inside`): each
  // side's value is linear along the line, so solving for the coordinate bounds the run,
  // and its ends are checked by the test itself; the corners between have every side's
  // value at least the smaller of the ends', up to a rounding far below the slack. One
  // pass over the sides per grid line instead of one per corner (the marking per corner
  // showed in profiles: docs/performance-history.md).
  static Run corners_inside(const Estimate& f, const CubeFace& c, const Rect& r, int j) {
    const double t = grid_line(j);
    double lo = -INFINITY, hi = INFINITY;
    for (const D3& n : f.n) {
      const double a = dot(n, c.point(0, t)), b = dot(n, c.e1);  // n . point(s, t) = a + b s
      if (b > 0) {
        lo = std::max(lo, (kCornerSlack - a) / b);
      } else if (b < 0) {
        hi = std::min(hi, (kCornerSlack - a) / b);
      } else if (!(a > kCornerSlack)) {
        return {};
      }
    }
    if (!(lo <= hi)) return {};
    int first = std::max(r.i0, static_cast<int>(std::ceil(std::clamp(lo, -2.0, 2.0) * kGrid / 2 + kGrid / 2)) - 1);
    int last = std::min(r.i1, static_cast<int>(std::floor(std::clamp(hi, -2.0, 2.0) * kGrid / 2 + kGrid / 2)) + 1);
    auto inside = [&](int i) {
      const D3 p = c.point(grid_line(i), t);
      for (const D3& n : f.n) {
        if (!(dot(n, p) > kCornerSlack)) return false;
      }
      return true;
    };
    while (first <= last && !inside(first)) ++first;
    while (last >= first && !inside(last)) --last;
    return {first, last};
  }

  static size_t index(int k, int i, int j) { return (size_t(k) * kGrid + j) * kGrid + i; }
  std::vector<std::atomic<uint8_t>> covered_;
};

}  // namespace

std::vector<uint8_t> redundant_faces(std::span<const std::vector<exact::ExactVec>> faces) {
  std::vector<Estimate> est(faces.size());
  tbb::parallel_for(size_t{0}, faces.size(), [&](size_t i) { est[i] = estimate(faces[i]); });
  interruption_point();
  std::vector<double> areas;
  for (const Estimate& e : est) {
    if (e.certain) areas.push_back(e.area);
  }
  std::vector<uint8_t> redundant(faces.size(), 0);
  if (areas.size() < 2) return redundant;
  const auto nth = areas.begin() + static_cast<std::ptrdiff_t>(areas.size() * (1 - kLargeFraction));
  std::nth_element(areas.begin(), nth, areas.end());
  const double large = *nth;
  CoveredCells cells;
  tbb::parallel_for(size_t{0}, faces.size(), [&](size_t i) {
    if (est[i].certain && est[i].area >= large) cells.mark(est[i]);
  });
  interruption_point();
  tbb::parallel_for(size_t{0}, faces.size(), [&](size_t i) {
    redundant[i] = est[i].certain && est[i].area < large && cells.hold(est[i]);
  });
  return redundant;
}

}  // namespace gvm
