// Conditions (i) and (ii) of the paper's Def. 5 (potentially facing faces), for many
// candidate triangles F' against one set S of triangles.
//
// F' potentially faces S if some triangle F_S of S has a vertex strictly in front of F'
// (i) while F' has a vertex not strictly behind F_S (ii). Condition (ii) only depends on
// F_S's oriented plane, and CAD surfaces are mostly large planar faces: S's triangles on
// one plane are tested as one (ii) and (i) on the convex hull of their vertices, instead
// of a box-tree search with both tests per triangle (Bottom F159, 547 coplanar triangles against 189k
// candidates, spent most of the whole part's time there).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "gvm/mesh.h"

namespace gvm::part_internal {

class PotentiallyFacing {
 public:
  // coordinate_bound: the largest absolute coordinate of the mesh's vertices.
  PotentiallyFacing(const SolidMesh& mesh, const std::vector<uint32_t>& s, double coordinate_bound);
  ~PotentiallyFacing();

  // Conditions (i) and (ii) for triangle f of the mesh (exact; safe to call concurrently).
  bool faces(uint32_t f) const;

 private:
  struct Impl;
  std::unique_ptr<const Impl> impl_;
};

}  // namespace gvm::part_internal
