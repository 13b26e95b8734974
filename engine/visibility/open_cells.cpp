#include "visibility/open_cells.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <iterator>
#include <optional>
#include <span>

#include "sphere/arc_intervals.h"

namespace gvm {
namespace {

using exact::ExactVec;

// Whether a cell holds x in its open inside, from the unit estimates where they decide
// (nothing where a side is too close to x to tell).
std::optional<bool> estimated_inside(std::span<const exact::UnitEstimate> normals, const exact::UnitEstimate& x) {
  bool certain = true;
  for (const exact::UnitEstimate& n : normals) {
    const std::optional<Sign> s = exact::estimated_sign_dot(x, n);
    if (s == Sign::kNegative) return false;
    certain = certain && s == Sign::kPositive;
  }
  if (!certain) return std::nullopt;
  return true;
}

bool strictly_inside(const OpenCells::Cell& c, std::span<const exact::UnitEstimate> normals, const ExactVec& x,
                     const exact::UnitEstimate& ex) {
  for (size_t k = 0; k < c.normals.size(); ++k) {
    if (exact::sign_dot(x, c.normals[k], ex, normals[k]) != Sign::kPositive) return false;
  }
  return true;
}

// A box around the closed cell: around its sides, and reaching +-1 along an axis whose
// direction the cell may hold (the only place inside where a coordinate can peak).
// `normals` are the estimates of the cell's normals.
sphere::Box box_of(const OpenCells::Cell& c, std::span<const exact::UnitEstimate> normals) {
  if (!c.minor_sides || c.vertices.empty()) return {{-1, -1, -1}, {1, 1, 1}};
  std::vector<exact::UnitEstimate> v;
  for (const ExactVec& x : c.vertices) v.push_back(exact::unit_estimate(x));
  sphere::Box box = sphere::arc_box(v.back(), v.front());
  for (size_t k = 0; k + 1 < v.size(); ++k) {
    const sphere::Box side = sphere::arc_box(v[k], v[k + 1]);
    for (int i = 0; i < 3; ++i) {
      box.lo[i] = std::min(box.lo[i], side.lo[i]);
      box.hi[i] = std::max(box.hi[i], side.hi[i]);
    }
  }
  // The axis e = sign * (unit vector i) is in the cell iff e . n = sign * n_i >= 0 for
  // every normal n; it may be unless an estimate shows n_i's sign. Exact signs here cost
  // an exact evaluation for every coordinate that is zero, as most are on CAD parts.
  for (int i = 0; i < 3; ++i) {
    bool plus = true, minus = true;
    for (const exact::UnitEstimate& n : normals) {
      plus = plus && !(n.unit[i] < -n.radius);
      minus = minus && !(n.unit[i] > n.radius);
    }
    if (plus) box.hi[i] = 1;
    if (minus) box.lo[i] = -1;
  }
  return box;
}

}  // namespace

void OpenCells::absorb(OpenCells&& other) {
  cells_.insert(cells_.end(), std::make_move_iterator(other.cells_.begin()),
                std::make_move_iterator(other.cells_.end()));
  tree_.reset();
}

void OpenCells::index() {
  first_normal_.assign(1, 0);
  for (const Cell& c : cells_) first_normal_.push_back(first_normal_.back() + c.normals.size());
  normal_estimates_.resize(first_normal_.back());
  std::vector<sphere::Box> boxes(cells_.size());
  tbb::parallel_for(size_t{0}, cells_.size(), [&](size_t i) {
    for (size_t k = 0; k < cells_[i].normals.size(); ++k) {
      normal_estimates_[first_normal_[i] + k] = exact::unit_estimate(cells_[i].normals[k]);
    }
    boxes[i] = box_of(cells_[i], normals_of(i));
  });
  tree_.emplace(boxes);
}

std::span<const exact::UnitEstimate> OpenCells::normals_of(uint32_t i) const {
  return {normal_estimates_.data() + first_normal_[i], cells_[i].normals.size()};
}

std::vector<uint32_t> OpenCells::near(const sphere::Box& query) {
  if (!tree_) index();
  return tree_->overlapping(query);
}

// The estimates first, the exact tests only where no cell holds u certainly: a point deep
// in the occluded directions lies in the boxes of a few hundred cells, whose normals'
// nodes, scattered over the heap, cost a cache miss each, and seam candidates lie on the
// sides of many (`prusa_y-rod-holder`: 1.27 M exact zeros over 10,302 points).
bool OpenCells::hold(const ExactVec& u) {
  if (!tree_) index();
  const exact::UnitEstimate eu = exact::unit_estimate(u);
  std::vector<uint32_t> undecided;
  const bool held = tree_->visit_overlapping(sphere::point_box(eu), [&](uint32_t i) {
    const std::optional<bool> inside = estimated_inside(normals_of(i), eu);
    if (!inside) undecided.push_back(i);
    return inside == true;
  });
  return held || std::any_of(undecided.begin(), undecided.end(),
                             [&](uint32_t i) { return strictly_inside(cells_[i], normals_of(i), u, eu); });
}

std::vector<sphere::Arc> OpenCells::uncovered(const sphere::Arc& open_arc) {
  std::vector<sphere::Interval> covered;
  for (uint32_t i : near(sphere::arc_box(exact::unit_estimate(open_arc.start), exact::unit_estimate(open_arc.end)))) {
    sphere::Interval inside;
    bool whole = false;
    if (sphere::clip(open_arc, cells_[i].normals, inside, &whole)) {
      if (whole) return {};
      covered.push_back(std::move(inside));
    }
  }
  return sphere::complement(open_arc, std::move(covered));
}

}  // namespace gvm
