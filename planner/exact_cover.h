// The minimum cover over every direction, exactly, without overlaying every reach set.
//
// The exact arrangement of all reach-set boundaries is what proves optimality, but it is
// the planner's largest cost (hundreds of hemispheres and lunes cross everywhere). A
// cover only needs it for the targets that decide the count: for a subset K, the overlay
// of K's reach sets gives the exact optimum of K -- a lower bound for every target -- and
// its witnesses, at which every other target is tested exactly. When a cover of every
// target by those witnesses meets K's bound it is optimal; otherwise the targets the best
// cover of K leaves unserved join K and the round repeats (at worst K is every target:
// the full overlay). K starts with a few targets whose reach sets are arcs or points, or
// else the smallest 2-dimensional ones.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include "candidates.h"
#include "gvm/status.h"
#include "set_cover.h"
#include "targets.h"

namespace gvm::planner {

struct ExactCover {
  CandidateSet candidates;   // witnesses, each with every target it serves
  CoverSolution solution;    // over `candidates`; its lower bound holds for every direction
  uint32_t rounds = 0;
  uint32_t overlay_targets = 0;  // |K| in the last round
};

// `serves(t, d)`: whether a setup at d serves target t (exact).
StatusOr<ExactCover> exact_cover(std::span<const Target> targets,
                                 const std::function<bool(uint32_t, const Direction&)>& serves,
                                 const CoverOptions& options);

}  // namespace gvm::planner
