// Convex cells of the occluded directions whose open inside is occluded outright, to spare
// the occlusion probe the seam candidates that lie deep inside the occluded directions.
//
// Inside a 2-cell of the LVM, the open inside of a pairwise occlusion map Phi(T + (-F_S))
// is occluded (a direction there has a segment from relint(F_S) to T), and so is the open
// inside of a projected envelope face: for V_O + (-F_S) the open prism of F_S contains the
// corner of O; for F_O + (-V_S) and E_O + (-E_S) the rays from the inside of a triangle of
// S next to the corner or edge of S still meet the face or one of the triangles at the
// edge of O, whose projections along u overlap near there (the planes through the origin
// are left out of the envelope).
#pragma once

#include <optional>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/box_tree.h"
#include "sphere/spherical_image.h"

namespace gvm {

class OpenCells {
 public:
  // Each cell as its vertices and the normals of its sides: the cell is the directions x
  // with x . n >= 0 for each normal (its open inside: > 0); the vertices only bound it.
  struct Cell {
    std::vector<exact::ExactVec> vertices, normals;
    bool minor_sides = true;  // every side shorter than 180 degrees (else: unbounded box)
  };
  explicit OpenCells(std::vector<Cell> cells) : cells_(std::move(cells)) {}

  // Adds the cells of `other` (of the same S and the same solid).
  void absorb(OpenCells&& other);

  // Whether one cell holds direction u in its open inside.
  bool hold(const exact::ExactVec& u);
  // The closed pieces of an open arc (shorter than 180 degrees) outside the open insides
  // of all cells (sphere::complement), in order along it.
  std::vector<sphere::Arc> uncovered(const sphere::Arc& open_arc);

 private:
  void index();
  std::span<const exact::UnitEstimate> normals_of(uint32_t i) const;  // cell i's estimates
  std::vector<uint32_t> near(const sphere::Box& query);

  std::vector<Cell> cells_;
  std::optional<sphere::BoxTree> tree_;
  // The normals' unit estimates, cell i's from first_normal_[i], built with the tree.
  std::vector<exact::UnitEstimate> normal_estimates_;
  std::vector<size_t> first_normal_;
};

}  // namespace gvm
