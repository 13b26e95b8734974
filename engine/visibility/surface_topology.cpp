#include "visibility/surface_topology.h"

#include <algorithm>
#include <tuple>

namespace gvm {

SurfaceTopology::SurfaceTopology(const SolidMesh& mesh, std::span<const uint32_t> triangles)
    : triangles_(triangles.begin(), triangles.end()) {
  struct HalfEdge {
    uint32_t a, b, opposite;
  };
  std::vector<HalfEdge> half;
  half.reserve(3 * triangles_.size());
  for (uint32_t t : triangles_) {
    const Triangle& v = mesh.triangles[t];
    for (int i = 0; i < 3; ++i) {
      uint32_t a = v[i], b = v[(i + 1) % 3], c = v[(i + 2) % 3];
      half.push_back({std::min(a, b), std::max(a, b), c});
    }
  }
  std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.a, x.b, x.opposite) < std::tie(y.a, y.b, y.opposite);
  });
  for (size_t i = 0; i < half.size();) {
    Edge e;
    e.a = half[i].a;
    e.b = half[i].b;
    while (i < half.size() && half[i].a == e.a && half[i].b == e.b) {
      // A manifold mesh has at most two triangles per edge.
      if (e.face_count < 2) e.opposite[e.face_count++] = half[i].opposite;
      ++i;
    }
    edges_.push_back(e);
  }

  for (const Edge& e : edges_) {
    vertices_.push_back(e.a);
    vertices_.push_back(e.b);
  }
  std::sort(vertices_.begin(), vertices_.end());
  vertices_.erase(std::unique(vertices_.begin(), vertices_.end()), vertices_.end());

  auto index_of = [&](uint32_t v) {
    return static_cast<size_t>(std::lower_bound(vertices_.begin(), vertices_.end(), v) -
                               vertices_.begin());
  };
  std::vector<uint32_t> degree(vertices_.size(), 0);
  for (const Edge& e : edges_) {
    ++degree[index_of(e.a)];
    ++degree[index_of(e.b)];
  }
  neighbor_start_.assign(vertices_.size() + 1, 0);
  for (size_t i = 0; i < vertices_.size(); ++i) neighbor_start_[i + 1] = neighbor_start_[i] + degree[i];
  neighbors_.resize(neighbor_start_.back());
  std::vector<uint32_t> fill(neighbor_start_.begin(), neighbor_start_.end() - 1);
  for (const Edge& e : edges_) {
    neighbors_[fill[index_of(e.a)]++] = e.b;
    neighbors_[fill[index_of(e.b)]++] = e.a;
  }
}

}  // namespace gvm
