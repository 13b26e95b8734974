// The N-way overlay of many closed direction sets (hundreds of GVMs): the exact
// arrangement of all their boundaries, with the coverage set of every vertex, edge and
// face -- the indices of the sets containing the cell. Coverage is constant on each cell,
// so one direction per cell decides every question of the form "which sets contain this
// direction"; the sets being closed, the inclusion-maximal coverage sets are attained at
// vertices, which is what an exact set cover needs.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "gvm/direction.h"
#include "gvm/direction_set.h"

namespace gvm {

class DirectionOverlay {
 public:
  explicit DirectionOverlay(std::span<const DirectionSet> sets);
  DirectionOverlay(DirectionOverlay&&) noexcept;
  DirectionOverlay& operator=(DirectionOverlay&&) noexcept;
  ~DirectionOverlay();

  size_t vertex_count() const;
  size_t edge_count() const;
  size_t face_count() const;

  enum class CellKind { kVertex, kEdge, kFace };
  struct Cell {
    CellKind kind;
    Direction witness;                   // exactly in the cell (strictly inside edges and faces)
    std::span<const uint32_t> coverage;  // ascending indices of the sets containing it
  };
  // Every cell once, in an order that depends on the input only.
  void for_each_cell(const std::function<void(const Cell&)>& visit) const;

  struct Coverage {
    Direction witness;               // a vertex with this coverage
    std::vector<uint32_t> sets;      // ascending, not empty
  };
  // The distinct inclusion-maximal non-empty coverage sets with a witness each, in an
  // order that depends on the input only.
  std::vector<Coverage> maximal_coverage() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gvm
