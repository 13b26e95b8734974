// One planning run's working state, shared by its steps (plan.cpp), the explanations of
// unreachable surfaces (unreachable.cpp) and the writing of the message (plan_message.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "candidates.h"
#include "gvm/analysis.h"
#include "gvm/v1/plan.pb.h"
#include "mode.h"
#include "set_cover.h"
#include "targets.h"

namespace gvm::planner {

struct UnreachableSurface {
  UnreachableSurface(uint32_t s, v1::UnreachableReason r) : surface(s), reason(r) {}
  uint32_t surface = 0;                   // index into PlanState::surfaces
  v1::UnreachableReason reason = v1::UNREACHABLE_REASON_UNSPECIFIED;
  std::string detail;
  std::vector<uint32_t> blocking_features;
  std::optional<Direction> probed_direction;
  Unserved nearest;                       // probe cone or clearance: the best candidate
  // Planned piece by piece (split): how many pieces, which reached and which not.
  uint32_t pieces = 0;
  bool split_by_direction = false;        // an automatic feature split where its normals part
  uint32_t split_limit = 0;               // not split: more faces than this
  uint32_t pieces_reached = 0;
  std::vector<std::pair<std::vector<uint32_t>, v1::UnreachableReason>> pieces_unreachable;
};

struct PlanTimes {
  double candidates = 0, cover = 0, placement = 0, unreachable = 0, total = 0;
  uint32_t threads = 0;
};

// The exact plan's count (tolerance 0), when the plan has a tolerance.
struct ExactCount {
  uint32_t setups = 0, lower_bound = 0;
};

// A surface every piece of which some setup reaches.
struct SplitSurface {
  uint32_t surface = 0;
  uint32_t pieces = 0;
};

struct PlanState {
  const Analysis* analysis = nullptr;
  v1::PlanOptions options;                // defaults filled in
  std::vector<const Surface*> surfaces;   // planned surfaces
  std::vector<Target> targets;
  std::vector<UnreachableSurface> unreachable;
  std::vector<SplitSurface> split;        // reached piece by piece
  Tolerance tolerance;
  std::optional<ExactCount> exact;        // with a tolerance
  // With a tolerance, over candidates that are not every setup there is: the solver's
  // bound over them (the plan's lower bound is then the separated packing, tolerance.h).
  std::optional<uint32_t> candidate_lower_bound;
  bool bound_by_covers = false;           // ... and then the optimum over the dilations' covers
  CandidateSet candidates;
  CoverSolution cover;
  std::optional<uint32_t> continuous_lower_bound;
  std::vector<PlacedSetup> setups;
  PlanTimes times;
};

// Why a surface with no reachable direction is unreachable, from its own maps.
v1::UnreachableReason reason_of_empty_reach(const Surface& surface, bool planar_normal_only);
// Fills the detail: for an occluded surface, the features whose faces block its LVM's
// most open direction.
void explain(const Analysis& analysis, const Surface& surface, UnreachableSurface& out);

// The plan message of a finished run.
v1::Plan plan_message(const PlanState& state);

}  // namespace gvm::planner
