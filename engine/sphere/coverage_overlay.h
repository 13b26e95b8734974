// The N-way overlay: the exact arrangement of the boundaries of many closed sets of
// directions at once (hundreds of GVMs), with the coverage set of every vertex, edge and
// face -- the indices of the sets that contain the cell. Coverage is constant on each
// cell; the sets being closed, cov(face) is contained in cov(each edge around it) and
// cov(edge) in cov(each of its ends), so the inclusion-maximal coverage sets are all
// attained at vertices.
//
// No limit on the number of sets: faces are labelled by one depth-first walk that keeps
// a single running coverage count per set, and only sets containing a cell are listed.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/spherical_image.h"

namespace gvm::sphere {

class CoverageOverlay {
 public:
  explicit CoverageOverlay(std::span<const SphericalImage> sets);
  CoverageOverlay(CoverageOverlay&&) noexcept;
  CoverageOverlay& operator=(CoverageOverlay&&) noexcept;
  ~CoverageOverlay();

  size_t set_count() const;
  size_t vertex_count() const;
  size_t edge_count() const;
  size_t face_count() const;

  enum class CellKind { kVertex, kEdge, kFace };
  struct Cell {
    CellKind kind;
    uint32_t index;                     // vertex, edge or face index
    // A direction in the cell, exactly: the vertex; a direction strictly inside the edge;
    // a direction strictly inside the face.
    exact::ExactVec witness;
    std::span<const uint32_t> coverage; // ascending indices of the sets containing the cell
  };
  // Visits every cell once, in an order that depends on the input only.
  void for_each_cell(const std::function<void(const Cell&)>& visit) const;

  struct MaximalCoverage {
    exact::ExactVec witness;            // a vertex with this coverage
    std::vector<uint32_t> coverage;     // ascending, never empty
  };
  // The distinct inclusion-maximal non-empty coverage sets, each once with a witness
  // vertex, in an order that depends on the input only. When no set has a boundary (all
  // are empty or the whole sphere) the witness is any direction.
  std::vector<MaximalCoverage> maximal_coverage() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gvm::sphere
