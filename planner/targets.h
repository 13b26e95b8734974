// What the plan must reach: the planned surfaces of an analysis, and for each the set of
// directions (rotary mode: axes) from which a setup reaches it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "gvm/analysis.h"
#include "gvm/direction_set.h"
#include "gvm/v1/plan.pb.h"

namespace gvm::planner {

// The surfaces the options select: every feature (or only the concave ones), or every
// concave region; in analysis order.
std::vector<const Surface*> planned_surfaces(const Analysis& analysis, const v1::PlanOptions& options);

// A surface, or a piece of one (--split), that a setup must reach.
struct Target {
  uint32_t surface = 0;           // index into the planned surfaces
  std::vector<uint32_t> faces;    // a piece's input faces; empty for the whole surface
  uint32_t piece = 0;             // a piece's number among its surface's pieces, from 1
  DirectionSet gvm;               // GVM of the surface or piece
  // The tool directions that reach it: the GVM, or with --planar-normal its own normal
  // when the GVM holds it.
  DirectionSet directions;
  // Where a setup may be for it: `directions`, or in rotary mode the axes whose great
  // circle meets them.
  DirectionSet reach;
};

// The tool directions that reach a surface of GVM `gvm` (see Target::directions).
DirectionSet tool_directions(const DirectionSet& gvm, const std::optional<Direction>& planar_normal,
                             bool planar_normal_only);

// The rotary axes a whose great circle {u . a = 0} meets `directions`: for each cell C
// (connected), every axis but those of +-Int(polar(C)), whose circles miss C on one side.
DirectionSet rotary_axes(const DirectionSet& directions);

}  // namespace gvm::planner
