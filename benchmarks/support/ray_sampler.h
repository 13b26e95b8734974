// The simplest ray-casting sampler of visibility, the alternative to exact maps that our
// users have: one Embree 3 ray from the centroid of every triangle that faces a
// direction, along each direction of a lattice. A feature is seen along a direction when
// every one of its triangles faces it and none of their rays is blocked.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gvm/mesh.h"

namespace gvm::bench {

struct SampledVisibility {
  uint64_t rays = 0;
  double seconds = 0;  // the BVH, every ray and the per-feature verdicts
  // seen[d]: the features seen along directions[d], ascending.
  std::vector<std::vector<uint32_t>> seen;
};

// features[f]: the triangles of feature f (indices into mesh.triangles). Runs on
// `threads` threads (Embree's BVH build and the rays).
SampledVisibility sample_visibility(const SolidMesh& mesh, const std::vector<std::vector<uint32_t>>& features,
                                    const std::vector<std::array<double, 3>>& directions, unsigned threads);

}  // namespace gvm::bench
