#include "mode.h"

#include "placement.h"

namespace gvm::planner {

std::vector<const DirectionSet*> reach_sets(std::span<const Target> targets,
                                            std::span<const uint32_t> assigned) {
  std::vector<const DirectionSet*> out;
  out.reserve(assigned.size());
  for (uint32_t t : assigned) out.push_back(&targets[t].reach);
  return out;
}

PlacedSetup placed_at(const Direction& start, std::span<const Target> targets,
                      std::span<const uint32_t> assigned) {
  const Placement p = place_in(reach_sets(targets, assigned), start);
  PlacedSetup out;
  out.direction = p.direction;
  for (size_t i = 0; i < assigned.size(); ++i) {
    out.reach.push_back({assigned[i], p.clearance_degrees[i], p.exact_alignment[i], {}, 0});
  }
  return out;
}

PlacedSetup Mode::place_fixed(const Candidate& chosen, std::span<const Target> targets,
                              std::span<const uint32_t> assigned, std::span<const uint32_t> loose) const {
  const Placement at = placement_at(reach_sets(targets, assigned), chosen.direction);
  PlacedSetup out;
  out.direction = chosen.direction;
  for (size_t i = 0; i < assigned.size(); ++i) {
    out.reach.push_back({assigned[i], at.clearance_degrees[i], at.exact_alignment[i], {}, 0});
  }
  for (uint32_t t : loose) out.reach.push_back({t, 0, true, {}, 0});
  return out;
}

}  // namespace gvm::planner
