// Candidate setups for the set cover: directions (rotary mode: axes), each with the
// targets it serves. Either the exact witnesses of the N-way overlay -- one per
// inclusion-maximal coverage set, which loses nothing: every direction serves a subset
// of what some witness serves -- or a stated finite set evaluated target by target.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gvm/direction.h"
#include "gvm/direction_set.h"
#include "targets.h"

namespace gvm::planner {

struct Candidate {
  Direction direction;
  std::vector<uint32_t> targets;  // ascending: the targets this direction serves
  uint32_t source = 0;            // evaluate(): index into its directions
};

struct CandidateSet {
  std::vector<Candidate> candidates;
  std::string description;        // what a proven optimum is optimal over
  uint32_t evaluated = 0;         // directions looked at
  uint64_t overlay_vertices = 0;  // of the N-way overlay, when built
  // When the candidates are a finite set smaller than the continuum (a clearance or cone
  // requirement): the exact candidates without that requirement, whose optimum is a lower
  // bound over every direction.
  std::vector<Candidate> relaxed;
};

// One witness per inclusion-maximal coverage set of the targets' reach sets.
CandidateSet exact_candidates(std::span<const Target> targets);

// `directions`, each serving the targets t with serves(t, direction) (in parallel;
// deterministic). Directions serving nothing are dropped.
std::vector<Candidate> evaluate(std::span<const Direction> directions, size_t targets,
                                const std::function<bool(uint32_t, const Direction&)>& serves);

// n directions spread evenly over the sphere (a Fibonacci lattice), as doubles.
std::vector<Direction> fibonacci_directions(size_t n);

}  // namespace gvm::planner
