#include "sphere/region_union.h"

#include <tbb/parallel_for.h>

#include "exact/interrupt.h"

namespace gvm::sphere {

Region positive_region(std::span<const ArrangementArc> arcs, const exact::ExactVec& reference,
                       int reference_coverage) {
  const int coverage[1] = {reference_coverage};
  std::vector<ArrangementArc> input(arcs.begin(), arcs.end());
  for (ArrangementArc& a : input) a.layer = 0;
  const Arrangement arr(input, {}, 1, reference, coverage);
  const auto& half = arr.half_edges();
  Region region;
  region.contains_reference = reference_coverage > 0;
  region.arrangement_vertices = arr.vertices().size();
  Interruptions interruptions;
  for (uint32_t e = 0; e < arr.edges().size(); ++e) {
    interruptions.tick();
    const Arrangement::Edge& edge = arr.edges()[e];
    // half[2e] runs v0 -> v1 with its face on the left.
    const bool left = arr.coverage(half[2 * e].face, 0) > 0;
    const bool right = arr.coverage(half[2 * e + 1].face, 0) > 0;
    if (left == right) continue;
    const exact::ExactVec& a = arr.vertices()[edge.v0].p;
    const exact::ExactVec& b = arr.vertices()[edge.v1].p;
    if (left) {
      region.boundary.push_back({a, b, edge.normal, 0, 1});
    } else {
      region.boundary.push_back({b, a, -edge.normal, 0, 1});
    }
  }
  return region;
}

Region region_union(std::vector<Region> parts, const exact::ExactVec& reference) {
  if (parts.empty()) return {};
  while (parts.size() > 1) {
    std::vector<Region> merged((parts.size() + 1) / 2);
    tbb::parallel_for(size_t{0}, merged.size(), [&](size_t i) {
      if (2 * i + 1 == parts.size()) {
        merged[i] = std::move(parts[2 * i]);
        return;
      }
      const Region &a = parts[2 * i], &b = parts[2 * i + 1];
      if (a.boundary.empty() || b.boundary.empty()) {
        // A region without boundary is empty or the whole sphere.
        const Region& bare = a.boundary.empty() ? a : b;
        const Region& other = &bare == &a ? b : a;
        merged[i] = bare.contains_reference ? bare : other;
        merged[i].arrangement_vertices = a.arrangement_vertices + b.arrangement_vertices;
        return;
      }
      std::vector<ArrangementArc> arcs = a.boundary;
      arcs.insert(arcs.end(), b.boundary.begin(), b.boundary.end());
      merged[i] = positive_region(arcs, reference, int(a.contains_reference) + int(b.contains_reference));
      merged[i].arrangement_vertices += a.arrangement_vertices + b.arrangement_vertices;
    });
    interruption_point();  // pairs left unmerged when cancelled
    parts = std::move(merged);
  }
  return std::move(parts[0]);
}

}  // namespace gvm::sphere
