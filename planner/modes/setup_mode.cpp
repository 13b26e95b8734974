// 3-axis machining (and mould pull directions): a setup is one tool direction.
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>

#include "mode.h"
#include "placement.h"

namespace gvm::planner {
namespace {

std::string degrees(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

class SetupMode final : public Mode {
 public:
  explicit SetupMode(double min_clearance_degrees)
      : theta_(min_clearance_degrees), sin2_(sin2_at_least(min_clearance_degrees)) {}

  bool exact() const override { return theta_ == 0; }

  CandidateSet candidates(std::span<const Target> targets) const override {
    CandidateSet exact = exact_candidates(targets);
    if (theta_ == 0) return exact;
    // With a clearance requirement the served sets are no longer bounded by great
    // circles: the candidates become the largest-clearance placement of every exact
    // maximal coverage set, the exact witnesses themselves (for arcs and points) and an
    // even grid over the sphere.
    std::vector<Direction> directions(exact.candidates.size());
    tbb::parallel_for(size_t{0}, exact.candidates.size(), [&](size_t i) {
      const Candidate& c = exact.candidates[i];
      directions[i] = placed_at(c.direction, targets, c.targets).direction;
    });
    for (const Candidate& c : exact.candidates) directions.push_back(c.direction);
    const std::vector<Direction> grid = fibonacci_directions(kGrid);
    directions.insert(directions.end(), grid.begin(), grid.end());
    CandidateSet out;
    out.candidates = evaluate(directions, targets.size(),
                              [&](uint32_t t, const Direction& d) { return serves(targets[t], d); });
    out.evaluated = static_cast<uint32_t>(directions.size());
    out.overlay_vertices = exact.overlay_vertices;
    out.description = std::to_string(exact.candidates.size()) +
                      " largest-clearance placements of the exact maximal coverage sets, their " +
                      "exact witnesses and " + std::to_string(kGrid) + " Fibonacci directions";
    out.relaxed = std::move(exact.candidates);
    return out;
  }

  PlacedSetup place(const Candidate& chosen, std::span<const Target> targets,
                    std::span<const uint32_t> assigned) const override {
    PlacedSetup p = placed_at(chosen.direction, targets, assigned);
    if (theta_ > 0 && !keeps_clearance(p, targets)) {
      // The search moved where a certified clearance fell short of the requirement:
      // stay at the candidate, where every cap was verified.
      const Placement at = placement_at(reach_sets(targets, assigned), chosen.direction);
      p.direction = at.direction;
      for (size_t i = 0; i < p.reach.size(); ++i) {
        p.reach[i].clearance_degrees = at.clearance_degrees[i];
        p.reach[i].exact_alignment = at.exact_alignment[i];
      }
    }
    return p;
  }

  Unserved unserved(const Target& target) const override {
    const DirectionSet* reach[] = {&target.reach};
    const Placement best = place_in(reach, target.reach.witness());
    Unserved u;
    u.reason = v1::UNREACHABLE_REASON_NO_CLEARANCE;
    u.nearest_clearance_degrees = best.clearance_degrees[0];
    u.detail = "no direction of its GVM has " + degrees(theta_) + " degrees of clearance (the best found has " +
               degrees(best.clearance_degrees[0]) + ")";
    return u;
  }

  bool serves(const Target& t, const Direction& d) const override {
    return t.reach.dimension() == 2 ? t.reach.contains_cap(d, sin2_) : t.reach.contains(d);
  }

  // A clearance requirement stays as stated: the tolerance relaxes only the membership of
  // the arcs and points it does not apply to.
  bool serves_within(const Target& t, const Direction& d, const Tolerance& tolerance) const override {
    if (theta_ > 0 && t.reach.dimension() == 2) return t.reach.contains_cap(d, sin2_);
    return t.reach.within(d, tolerance.near_sin2);
  }

 private:
  static constexpr size_t kGrid = 2000;


  bool keeps_clearance(const PlacedSetup& p, std::span<const Target> targets) const {
    for (const TargetReach& r : p.reach) {
      if (targets[r.target].reach.dimension() == 2 && r.clearance_degrees < theta_) return false;
    }
    return true;
  }

  double theta_, sin2_;
};

}  // namespace

std::unique_ptr<Mode> make_setup_mode(const v1::PlanOptions& options) {
  return std::make_unique<SetupMode>(options.min_clearance_degrees());
}

}  // namespace gvm::planner
