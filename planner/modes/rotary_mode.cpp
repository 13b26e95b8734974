// 4-axis indexer, tool perpendicular to the rotary axis: a setup is an axis a (a and -a
// are one axis); the tool reaches along the great circle normal to a. By duality a
// feature's good axes are a closed set bounded by great circles (targets.h), so the axis
// choice is again an exact point cover.
#include <cmath>

#include "mode.h"
#include "placement.h"

namespace gvm::planner {
namespace {

constexpr double kDegree = 0.017453292519943295;

// The direction of the tool at table angle 0: the part's +z turned into the plane normal
// to the axis (its +x for an axis along z), exactly.
Direction table_zero(const Direction& axis) {
  const Direction z(0, 0, 1);
  const Direction reference = parallel(axis, z) ? Direction(1, 0, 0) : z;
  return cross(cross(axis, reference), axis);
}

// The angle (radians, doubles) of the interval points with the largest clearance in the
// GVM: both ends and a few hundred points between (a choice for the report; the
// intervals themselves are exact).
double most_open_angle(const DirectionSet& gvm, const std::vector<std::array<double, 2>>& intervals,
                       const Direction& zero, const Direction& axis) {
  const std::array<double, 3> e1 = zero.unit(), e2 = cross(axis, zero).unit();
  double best = intervals.front()[0], best_clearance = -1e300;
  for (const auto& [from, to] : intervals) {
    const int steps = std::max(1, static_cast<int>((to - from) / (0.5 * kDegree)));
    for (int k = 0; k <= steps; ++k) {
      const double phi = from + (to - from) * k / steps;
      const std::array<double, 3> u = {std::cos(phi) * e1[0] + std::sin(phi) * e2[0],
                                       std::cos(phi) * e1[1] + std::sin(phi) * e2[1],
                                       std::cos(phi) * e1[2] + std::sin(phi) * e2[2]};
      const double c = gvm.approx_signed_clearance(u);
      if (c > best_clearance) best_clearance = c, best = phi;
    }
  }
  return best;
}

// The table angle (radians in [0, 2 pi), doubles) of the corner of `directions` nearest
// the circle normal to `axis`.
double nearest_angle(const DirectionSet& directions, const Direction& zero, const Direction& axis) {
  const std::array<double, 3> a = axis.unit(), e1 = zero.unit(), e2 = cross(axis, zero).unit();
  double best = 2, angle = 0;
  for (const Direction& c : directions.corners()) {
    const std::array<double, 3> u = c.unit();
    const double off = std::fabs(u[0] * a[0] + u[1] * a[1] + u[2] * a[2]);
    if (off >= best) continue;
    best = off;
    angle = std::atan2(u[0] * e2[0] + u[1] * e2[1] + u[2] * e2[2], u[0] * e1[0] + u[1] * e1[1] + u[2] * e1[2]);
  }
  return angle < 0 ? angle + 2 * M_PI : angle;
}

class RotaryMode final : public Mode {
 public:
  DirectionSet reach_of(const DirectionSet& directions) const override {
    return rotary_axes(directions);
  }

  bool exact() const override { return true; }

  CandidateSet candidates(std::span<const Target> targets) const override {
    CandidateSet out = exact_candidates(targets);
    out.description = "every rotary axis (the exact arrangement of the good-axis boundaries, " +
                      std::to_string(out.overlay_vertices) + " vertices)";
    return out;
  }

  PlacedSetup place(const Candidate& chosen, std::span<const Target> targets,
                    std::span<const uint32_t> assigned) const override {
    PlacedSetup p = placed_at(chosen.direction, targets, assigned);
    table_angles(p, targets);
    return p;
  }

  PlacedSetup place_fixed(const Candidate& chosen, std::span<const Target> targets,
                          std::span<const uint32_t> assigned, std::span<const uint32_t> loose) const override {
    PlacedSetup p = Mode::place_fixed(chosen, targets, assigned, loose);
    table_angles(p, targets);
    return p;
  }

  Unserved unserved(const Target&) const override { return {}; }  // every axis set is exact

 private:
  // The table angles at which the tool reaches each target: its exact intervals and the
  // most open angle among them; for a target reached only within the tolerance (no
  // interval), the angle where its directions come nearest the circle -- at one of their
  // corners, since along an arc that misses a circle the distance to it is least at an end.
  static void table_angles(PlacedSetup& p, std::span<const Target> targets) {
    p.rotary_zero = table_zero(p.direction);
    for (TargetReach& r : p.reach) {
      const Target& t = targets[r.target];
      for (auto [from, to] : t.directions.circle_intervals(p.direction, *p.rotary_zero)) {
        r.rotary_angles.push_back({from / kDegree, to / kDegree});
      }
      if (!r.rotary_angles.empty()) {
        std::vector<std::array<double, 2>> radians;
        for (auto [from, to] : r.rotary_angles) radians.push_back({from * kDegree, to * kDegree});
        const double chosen = most_open_angle(t.directions, radians, *p.rotary_zero, p.direction) / kDegree;
        r.rotary_angle_degrees = std::fmod(chosen, 360.0);  // the intervals may run past 360
      } else {
        r.rotary_angle_degrees = nearest_angle(t.directions, *p.rotary_zero, p.direction) / kDegree;
      }
    }
  }
};

}  // namespace

std::unique_ptr<Mode> make_rotary_mode(const v1::PlanOptions&) { return std::make_unique<RotaryMode>(); }

}  // namespace gvm::planner
