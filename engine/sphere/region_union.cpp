#include "sphere/region_union.h"

#include <tbb/parallel_for.h>

#include <array>

#include "parallel/interrupt.h"
#include "sphere/image_overlay.h"

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

SphericalImage outside_interior(const SphericalImage& set, const Region& r, const exact::ExactVec& reference) {
  constexpr int kSet = 0, kRegion = 1;
  std::vector<ArrangementArc> arcs;
  std::vector<ArrangementPoint> points;
  add_image(set, kSet, arcs, points);
  for (const ArrangementArc& a : r.boundary) arcs.push_back({a.from, a.to, a.normal, kRegion, a.weight});
  const std::array<int, 2> coverage{face_winding(set, reference), r.contains_reference ? 1 : 0};
  const Arrangement arr(arcs, points, 2, reference, coverage);
  const auto& half = arr.half_edges();
  auto in_set = [&](uint32_t f) { return arr.coverage(f, kSet) > 0; };
  auto in_region = [&](uint32_t f) { return arr.coverage(f, kRegion) > 0; };
  // An edge or a vertex lies in Int(r) when every face around it does.
  auto edge_in = [&](uint32_t e) {
    const uint32_t left = half[2 * e].face, right = half[2 * e + 1].face;
    const bool on_set = arr.edge_on_layer(e, kSet) || in_set(left) || in_set(right);
    return on_set && !(in_region(left) && in_region(right));
  };
  auto vertex_in = [&](uint32_t v) {
    const Arrangement::Vertex& vertex = arr.vertices()[v];
    bool on_set = arr.vertex_has_point(v, kSet);
    bool interior = vertex.out.empty() ? in_region(0) : true;
    for (uint32_t h : vertex.out) {
      on_set = on_set || arr.edge_on_layer(half[h].edge, kSet) || in_set(half[h].face);
      interior = interior && in_region(half[h].face);
    }
    if (vertex.out.empty()) on_set = on_set || in_set(0);
    return on_set && !interior;
  };
  return arr.extract([&](uint32_t f) { return in_set(f) && !in_region(f); }, edge_in, vertex_in);
}

}  // namespace gvm::sphere
