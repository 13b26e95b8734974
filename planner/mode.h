// What differs between the machines a plan is for: what a setup is, which candidates
// stand for all of them, and where a chosen setup is placed. The set cover, assignment,
// reasons and output are shared (plan.cpp).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "candidates.h"
#include "gvm/v1/plan.pb.h"
#include "targets.h"
#include "tolerance.h"

namespace gvm::planner {

// How one target is reached in a placed setup.
struct TargetReach {
  uint32_t target = 0;
  double clearance_degrees = 0;     // certified
  bool exact_alignment = false;
  // Rotary mode: table angles (degrees) reaching it, and the one chosen.
  std::vector<std::array<double, 2>> rotary_angles;
  double rotary_angle_degrees = 0;
  // Reached only within the plan's tolerance, this far (radians, doubles) from its reach set.
  bool within_tolerance = false;
  double distance_radians = 0;
};

struct PlacedSetup {
  Direction direction;              // tool or probe direction; rotary axis
  std::vector<TargetReach> reach;   // in the order of the assigned targets
  double head_a_degrees = 0, head_b_degrees = 0;  // probe mode
  std::optional<Direction> rotary_zero;           // rotary mode
};

// Why no candidate serves a target that has a non-empty reach set (probe cone, minimum
// clearance), with the best candidate found.
struct Unserved {
  v1::UnreachableReason reason = v1::UNREACHABLE_REASON_UNSPECIFIED;
  std::string detail;
  double nearest_head_a_degrees = 0, nearest_head_b_degrees = 0, nearest_clearance_degrees = 0;
};

class Mode {
 public:
  virtual ~Mode() = default;
  // Where a setup may be for a target whose tool directions are `directions`.
  virtual DirectionSet reach_of(const DirectionSet& directions) const { return directions; }
  // Whether the candidates are the exact witnesses of the reach sets' overlay, so that the
  // planner may find them round by round (exact_cover.h) instead of all at once.
  virtual bool exact() const { return false; }
  virtual CandidateSet candidates(std::span<const Target> targets) const = 0;
  // When the candidates are every setup there is (a head's grid): them again, each with
  // the targets it serves within the tolerance, so that the solver's bound over them holds.
  // Otherwise nothing: the planner adds the reach sets' corners (tolerance.h).
  virtual std::optional<CandidateSet> candidates_within(std::span<const Target>, const Tolerance&) const {
    return std::nullopt;
  }
  // Whether a setup at `direction` serves the target (what the candidates were built on).
  virtual bool serves(const Target& target, const Direction& direction) const {
    return target.reach.contains(direction);
  }
  // Whether a setup at `direction` serves the target within the tolerance, exactly; it
  // must imply that `direction` is within epsilon of the target's reach set.
  virtual bool serves_within(const Target& target, const Direction& direction, const Tolerance& tolerance) const {
    return target.reach.within(direction, tolerance.near_sin2);
  }
  // Places a chosen candidate that serves every assigned target.
  virtual PlacedSetup place(const Candidate& chosen, std::span<const Target> targets,
                            std::span<const uint32_t> assigned) const = 0;
  // The same without moving it: the candidate serves the assigned targets; `loose` ones
  // only within the tolerance (clearance 0; the rotary mode says at which table angle the
  // tool comes nearest).
  virtual PlacedSetup place_fixed(const Candidate& chosen, std::span<const Target> targets,
                                  std::span<const uint32_t> assigned, std::span<const uint32_t> loose) const;
  virtual Unserved unserved(const Target& target) const = 0;
};

std::unique_ptr<Mode> make_setup_mode(const v1::PlanOptions& options);
std::unique_ptr<Mode> make_rotary_mode(const v1::PlanOptions& options);
std::unique_ptr<Mode> make_probe_mode(const v1::PlanOptions& options);

// Shared by the modes: the reach sets of the assigned targets, and their placement.
std::vector<const DirectionSet*> reach_sets(std::span<const Target> targets,
                                            std::span<const uint32_t> assigned);
PlacedSetup placed_at(const Direction& start, std::span<const Target> targets,
                      std::span<const uint32_t> assigned);

}  // namespace gvm::planner
