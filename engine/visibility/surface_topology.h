// The combinatorics of a surface (a set of triangles of the part) that the Minkowski-sum
// methods need: its vertices with their neighbours inside the surface, and its edges with
// the opposite vertex of each incident triangle inside the surface.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "gvm/mesh.h"

namespace gvm {

class SurfaceTopology {
 public:
  struct Edge {
    uint32_t a = 0, b = 0;                 // mesh vertex ids, a < b
    std::array<uint32_t, 2> opposite{};    // third vertex of each incident triangle of S
    uint8_t face_count = 0;                // 1 on the border of the surface, else 2
  };

  SurfaceTopology(const SolidMesh& mesh, std::span<const uint32_t> triangles);

  std::span<const uint32_t> triangles() const { return triangles_; }
  std::span<const uint32_t> vertices() const { return vertices_; }
  // Neighbours (inside the surface) of vertices()[i].
  std::span<const uint32_t> neighbors(size_t vertex_index) const {
    return {neighbors_.data() + neighbor_start_[vertex_index],
            neighbors_.data() + neighbor_start_[vertex_index + 1]};
  }
  std::span<const Edge> edges() const { return edges_; }

 private:
  std::vector<uint32_t> triangles_;
  std::vector<uint32_t> vertices_;          // ascending
  std::vector<uint32_t> neighbor_start_;    // CSR offsets into neighbors_
  std::vector<uint32_t> neighbors_;
  std::vector<Edge> edges_;                 // sorted by (a, b)
};

}  // namespace gvm
