// Candidate pairs for the arrangement: a static bounding-box tree over axis-aligned boxes
// in R^3 (boxes around arcs and points of the sphere). It finds every pair of
// overlapping boxes in O(n log n + pairs), whatever the clustering; it decides nothing
// by itself (the exact predicates do), so a box only has to contain its object.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "exact/exact_vec.h"

namespace gvm::sphere {

struct Box {
  std::array<double, 3> lo, hi;
};

// A box around a direction given by its certified unit estimate.
Box point_box(const exact::UnitEstimate& e);
// A box around a direction from its exact value (ExactVec::unit): each coordinate bounded
// relative to its own size, so that directions 1e-20 apart near an axis get boxes apart
// (one exact evaluation: for clusters the estimates cannot tell apart).
Box exact_point_box(const exact::ExactVec& a);
// A box around the whole minor arc between two directions, from boxes around its ends:
// theirs grown by the arc's sagitta.
Box arc_box(const Box& a, const Box& b);
Box arc_box(const exact::UnitEstimate& a, const exact::UnitEstimate& b);

class BoxTree {
 public:
  explicit BoxTree(std::span<const Box> boxes);

  // Every pair (i, j), i < j, of overlapping boxes, sorted; or, when there are more than
  // `limit`, some more than `limit` of them, unsorted.
  std::vector<std::pair<uint32_t, uint32_t>> overlapping_pairs(size_t limit = SIZE_MAX) const;
  // Whether more than `limit` pairs of boxes overlap (found without sorting them).
  bool overlapping_pairs_exceed(size_t limit) const;
  // Indices of the boxes that overlap `query`, sorted.
  std::vector<uint32_t> overlapping(const Box& query) const;
  // Calls visit(i) for the boxes i that overlap `query`, in no set order, until it returns
  // true; returns whether it did.
  template <class Visit>
  bool visit_overlapping(const Box& query, const Visit& visit) const;

 private:
  struct Node {
    Box box;
    uint32_t begin, end;       // range of order_
    uint32_t left, right;      // children, 0 for a leaf (the root is never a child)
  };
  uint32_t build(uint32_t begin, uint32_t end);
  using Pairs = std::vector<std::pair<uint32_t, uint32_t>>;
  void pairs_within(uint32_t n, Pairs& out, size_t limit) const;
  void pairs_between(uint32_t a, uint32_t b, Pairs& out, size_t limit) const;

  std::vector<Box> boxes_;
  std::vector<uint32_t> order_;
  std::vector<Node> nodes_;
};

inline bool overlap(const Box& a, const Box& b) {
  for (int i = 0; i < 3; ++i) {
    if (a.hi[i] < b.lo[i] || b.hi[i] < a.lo[i]) return false;
  }
  return true;
}

template <class Visit>
bool BoxTree::visit_overlapping(const Box& query, const Visit& visit) const {
  if (nodes_.empty()) return false;
  uint32_t stack[128];  // the tree is balanced: depth about log2(n)
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (!overlap(n.box, query)) continue;
    if (n.left == 0) {
      for (uint32_t k = n.begin; k < n.end; ++k) {
        if (overlap(boxes_[order_[k]], query) && visit(order_[k])) return true;
      }
    } else {
      stack[top++] = n.left;
      stack[top++] = n.right;
    }
  }
  return false;
}

}  // namespace gvm::sphere
