#include "sphere/box_tree.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>

#include "exact/float_steps.h"

namespace gvm::sphere {
namespace {

constexpr uint32_t kLeafSize = 8;

Box merge(const Box& a, const Box& b) {
  Box m;
  for (int i = 0; i < 3; ++i) {
    m.lo[i] = std::min(a.lo[i], b.lo[i]);
    m.hi[i] = std::max(a.hi[i], b.hi[i]);
  }
  return m;
}

// lo rounded down and hi rounded up: a box computed in doubles still holds the exact one.
void round_outwards(Box& b) {
  for (int i = 0; i < 3; ++i) {
    b.lo[i] = exact::next_down(b.lo[i]);
    b.hi[i] = exact::next_up(b.hi[i]);
  }
}

// Pairs sorted as std::sort sorts them, by radix on their packed keys: sorting took a
// twelfth of a whole part's analysis (prusa_y-rod-holder, one thread). The radix sort
// needs twice the pairs' memory besides them, so the largest lists are sorted in place:
// with the radix sort for every size, piattello.stp peaked at 12.9 GB in the union of
// its face with 10^5 envelope faces, about 6.5 GB with this bound.
constexpr size_t kRadixFrom = 4096, kRadixUpTo = size_t{1} << 23;

void sort_pairs(std::vector<std::pair<uint32_t, uint32_t>>& pairs) {
  if (pairs.size() < kRadixFrom || pairs.size() > kRadixUpTo) {
    std::sort(pairs.begin(), pairs.end());
    return;
  }
  uint32_t largest = 0;
  for (const auto& [a, b] : pairs) largest = std::max(largest, b);  // a < b
  const int bits = std::bit_width(largest);
  std::vector<uint64_t> keys(pairs.size()), scratch(pairs.size());
  for (size_t i = 0; i < pairs.size(); ++i) keys[i] = uint64_t(pairs[i].first) << bits | pairs[i].second;
  constexpr int kDigit = 11;
  for (int shift = 0; shift < 2 * bits; shift += kDigit) {
    std::vector<size_t> start((size_t{1} << kDigit) + 1, 0);
    for (uint64_t k : keys) ++start[((k >> shift) & ((1u << kDigit) - 1)) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    for (uint64_t k : keys) scratch[start[(k >> shift) & ((1u << kDigit) - 1)]++] = k;
    keys.swap(scratch);
  }
  const uint64_t low = (uint64_t{1} << bits) - 1;
  for (size_t i = 0; i < pairs.size(); ++i) pairs[i] = {uint32_t(keys[i] >> bits), uint32_t(keys[i] & low)};
}

}  // namespace

Box point_box(const exact::UnitEstimate& e) {
  Box b;
  for (int i = 0; i < 3; ++i) {
    b.lo[i] = e.unit[i] - e.radius;
    b.hi[i] = e.unit[i] + e.radius;
  }
  round_outwards(b);
  return b;
}

Box exact_point_box(const exact::ExactVec& a) {
  const std::array<double, 3> u = a.unit();
  Box b;
  for (int i = 0; i < 3; ++i) {
    const double off = std::fabs(u[i]) * 0x1p-49 + 0x1p-1000;  // twice unit()'s bound
    b.lo[i] = u[i] - off;
    b.hi[i] = u[i] + off;
  }
  round_outwards(b);
  return b;
}

Box arc_box(const Box& a, const Box& b) {
  // The exact chord is at most c (the far corners of the two boxes), and the minor arc
  // leaves the box of its chord by at most its sagitta 1 - sqrt(1 - c^2/4), computed as
  // x / (1 + sqrt(1 - x)), x = c^2/4: without cancellation, so that arcs 1e-16 long keep
  // boxes that small.
  double chord2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double d = std::max(a.hi[i] - b.lo[i], b.hi[i] - a.lo[i]);
    chord2 += d * d;
  }
  const double c = std::min(2.0, std::sqrt(chord2) * (1 + 0x1p-50));
  const double x = c * c / 4;
  const double sagitta = x / (1 + std::sqrt(1 - x)) * (1 + 0x1p-48);
  Box box;
  for (int i = 0; i < 3; ++i) {
    box.lo[i] = std::min(a.lo[i], b.lo[i]) - sagitta;
    box.hi[i] = std::max(a.hi[i], b.hi[i]) + sagitta;
  }
  round_outwards(box);
  return box;
}

Box arc_box(const exact::UnitEstimate& a, const exact::UnitEstimate& b) {
  return arc_box(point_box(a), point_box(b));
}

BoxTree::BoxTree(std::span<const Box> boxes) : boxes_(boxes.begin(), boxes.end()) {
  order_.resize(boxes_.size());
  std::iota(order_.begin(), order_.end(), 0u);
  if (!boxes_.empty()) build(0, static_cast<uint32_t>(boxes_.size()));
}

uint32_t BoxTree::build(uint32_t begin, uint32_t end) {
  const uint32_t id = static_cast<uint32_t>(nodes_.size());
  nodes_.push_back({boxes_[order_[begin]], begin, end, 0, 0});
  Box box = boxes_[order_[begin]];
  for (uint32_t k = begin + 1; k < end; ++k) box = merge(box, boxes_[order_[k]]);
  nodes_[id].box = box;
  if (end - begin <= kLeafSize) return id;
  // Split at the median centre along the axis where the boxes spread most.
  int axis = 0;
  double spread = -1;
  for (int i = 0; i < 3; ++i) {
    if (box.hi[i] - box.lo[i] > spread) spread = box.hi[i] - box.lo[i], axis = i;
  }
  const uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](uint32_t a, uint32_t b) {
                     return boxes_[a].lo[axis] + boxes_[a].hi[axis] <
                            boxes_[b].lo[axis] + boxes_[b].hi[axis];
                   });
  const uint32_t left = build(begin, mid);
  const uint32_t right = build(mid, end);
  nodes_[id].left = left;
  nodes_[id].right = right;
  return id;
}

void BoxTree::pairs_within(uint32_t n, Pairs& out, size_t limit) const {
  if (out.size() > limit) return;
  const Node& node = nodes_[n];
  if (node.left == 0) {
    for (uint32_t a = node.begin; a < node.end; ++a) {
      for (uint32_t b = a + 1; b < node.end; ++b) {
        if (overlap(boxes_[order_[a]], boxes_[order_[b]])) {
          out.emplace_back(std::min(order_[a], order_[b]), std::max(order_[a], order_[b]));
        }
      }
    }
    return;
  }
  pairs_within(node.left, out, limit);
  pairs_within(node.right, out, limit);
  pairs_between(node.left, node.right, out, limit);
}

void BoxTree::pairs_between(uint32_t a, uint32_t b, Pairs& out, size_t limit) const {
  const Node &na = nodes_[a], &nb = nodes_[b];
  if (out.size() > limit || !overlap(na.box, nb.box)) return;
  const bool a_leaf = na.left == 0, b_leaf = nb.left == 0;
  if (a_leaf && b_leaf) {
    for (uint32_t i = na.begin; i < na.end; ++i) {
      for (uint32_t j = nb.begin; j < nb.end; ++j) {
        if (overlap(boxes_[order_[i]], boxes_[order_[j]])) {
          out.emplace_back(std::min(order_[i], order_[j]), std::max(order_[i], order_[j]));
        }
      }
    }
    return;
  }
  // Descend into the larger of the two.
  if (b_leaf || (!a_leaf && na.end - na.begin >= nb.end - nb.begin)) {
    pairs_between(na.left, b, out, limit);
    pairs_between(na.right, b, out, limit);
  } else {
    pairs_between(a, nb.left, out, limit);
    pairs_between(a, nb.right, out, limit);
  }
}

std::vector<std::pair<uint32_t, uint32_t>> BoxTree::overlapping_pairs(size_t limit) const {
  Pairs out;
  if (!nodes_.empty()) pairs_within(0, out, limit);
  if (out.size() > limit) return out;
  sort_pairs(out);
  return out;
}

bool BoxTree::overlapping_pairs_exceed(size_t limit) const {
  Pairs out;
  if (!nodes_.empty()) pairs_within(0, out, limit);
  return out.size() > limit;
}

std::vector<uint32_t> BoxTree::overlapping(const Box& query) const {
  std::vector<uint32_t> out;
  if (nodes_.empty()) return out;
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& n = nodes_[stack.back()];
    stack.pop_back();
    if (!overlap(n.box, query)) continue;
    if (n.left == 0) {
      for (uint32_t k = n.begin; k < n.end; ++k) {
        if (overlap(boxes_[order_[k]], query)) out.push_back(order_[k]);
      }
    } else {
      stack.push_back(n.left);
      stack.push_back(n.right);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace gvm::sphere
