// The planning tolerance epsilon: a surface is reached along u when u is within epsilon of
// its reach set. Decided exactly with sin^2 bounds taken as doubles (nearness.h): one
// rounded down, so that "within" never accepts more than epsilon, one rounded up, so that
// "farther than 2 epsilon" never claims a pair that is not.
//
// The cover within epsilon: the exact cover's witnesses and every corner of every reach
// set, each tested within epsilon against every target. A direction within epsilon of
// several disjoint sets lies near where they are nearest, which is a corner of one of them
// (nearness.h); where two sets are more than epsilon but at most 2 epsilon apart, only a
// direction between them serves both, so pairs that keep the packing from proving the
// count get their midpoint as a candidate, round by round. The lower bound is first a
// packing of targets whose reach sets are pairwise more than 2 epsilon apart, decided
// exactly: no direction is within epsilon of two of them, so it holds for every direction.
// Where that packing falls short (sets that pairwise meet, as a box's six faces), the exact
// optimum over sets bounded by great circles that hold the epsilon-neighbourhoods
// (DirectionSet::dilation_cover) is a lower bound too, found like the exact plan's
// (exact_cover.h), and its witnesses join the candidates.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include "candidates.h"
#include "gvm/status.h"
#include "set_cover.h"
#include "targets.h"

namespace gvm::planner {

struct Tolerance {
  double radians = 0;
  double near_sin2 = 0;   // <= sin^2(epsilon)
  double cover_sin2 = 0;  // >= sin^2(epsilon)
  double far_sin2 = 0;    // >= sin^2(2 epsilon)
  static Tolerance of(double radians);
  bool active() const { return radians > 0; }
};

struct ToleranceCover {
  CandidateSet candidates;   // each with every target it serves within epsilon
  CoverSolution solution;    // lower_bound and packing: the verified 2-epsilon packing
  uint32_t candidate_lower_bound = 0;  // the solver's bound over the candidates
  uint32_t corners = 0, midpoints = 0;
  bool bound_by_covers = false;         // the lower bound is the optimum over the dilation covers
};

// `seeds`: candidates already known (the exact witnesses, a mode's finite set), each
// with the targets it serves exactly; `serves(t, d)`: within epsilon, exactly.
StatusOr<ToleranceCover> tolerance_cover(std::span<const Target> targets, const CandidateSet& seeds,
                                         const std::function<bool(uint32_t, const Direction&)>& serves,
                                         const Tolerance& tolerance, const CoverOptions& options);

// The targets of `packing` whose reach sets are pairwise more than 2 epsilon apart (kept
// in order, each against those kept before it), and the pairs that were not.
struct VerifiedPacking {
  std::vector<uint32_t> items;
  std::vector<std::pair<uint32_t, uint32_t>> near_pairs;
};
VerifiedPacking verify_packing(std::span<const Target> targets, const std::vector<uint32_t>& packing,
                               const Tolerance& tolerance);

}  // namespace gvm::planner
