// The vertices of an arrangement (arrangement.cpp's first step): every occurrence of a
// direction on the arcs -- their ends, their meetings, the input points and the reference
// inside them -- and the vertex each occurrence is.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "sphere/arrangement.h"

namespace gvm::sphere::arrangement_internal {

// Point occurrences: arc endpoints, split points, input points, the reference, with the
// arc each lies on as one flat list of (arc, occurrence), grouped by arc later: a vector per
// arc cost two or three allocations per arc of every arrangement.
struct Occurrences {
  std::vector<exact::ExactVec> occ;
  std::vector<std::pair<uint32_t, uint32_t>> on_arc;
  std::vector<uint32_t> point_occ;
  uint32_t reference_occ = 0;
  uint64_t compared_pairs = 0;

  uint32_t add(const exact::ExactVec& p) {
    occ.push_back(p);
    return static_cast<uint32_t>(occ.size() - 1);
  }
  void on(size_t arc, uint32_t k) { on_arc.push_back({static_cast<uint32_t>(arc), k}); }
};

// Every occurrence: the arcs' ends, their meetings (candidate pairs from a tree of boxes),
// and the input points and the reference, on the arcs they lie inside.
Occurrences occurrences(std::span<const ArrangementArc* const> arcs, std::span<const ArrangementPoint> points,
                        const exact::ExactVec& reference);

// The vertex of each occurrence: occurrences of one shared node are one direction (arcs
// that meet share their endpoint's node, often dozens of times); the distinct nodes are
// compared exactly when their boxes overlap. New vertices (the first occurrence of each
// direction) are appended to `vertices`.
std::vector<uint32_t> vertices_of(std::span<const exact::ExactVec> occ, std::vector<Arrangement::Vertex>& vertices,
                                  uint64_t& compared_pairs);

}  // namespace gvm::sphere::arrangement_internal
